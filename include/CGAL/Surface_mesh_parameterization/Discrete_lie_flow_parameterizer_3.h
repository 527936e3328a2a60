// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_DISCRETE_LIE_FLOW_PARAMETERIZER_3_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_DISCRETE_LIE_FLOW_PARAMETERIZER_3_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_options.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_report.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/default_solver.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/disk/disk_flow.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/mesh_properties.h>

#include <CGAL/Surface_mesh_parameterization/Symmetric_barycentric_mapping_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Circular_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Error_code.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <CGAL/Surface_mesh_parameterization/internal/Containers_filler.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/Surface_mesh_parameterization/internal/kernel_traits.h>

#include <CGAL/Default.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Eigen_solver_traits.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <chrono>
#include <functional>
#include <memory>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// Whether an initial parameterizer gives Tutte's map (uniform weights) with
/// the border on the circle by arc length, which the flow then computes
/// itself (the same map to rounding), whatever the parameterizer's solver.
template <class Initial, class TriangleMesh>
struct Is_tutte_on_arc_length_circle : std::false_type {};
template <class TriangleMesh, class Solver>
struct Is_tutte_on_arc_length_circle<Symmetric_barycentric_mapping_parameterizer_3<TriangleMesh, Default, Solver>,
                                     TriangleMesh> : std::true_type {};
template <class TriangleMesh, class Solver>
struct Is_tutte_on_arc_length_circle<
  Symmetric_barycentric_mapping_parameterizer_3<TriangleMesh, Circular_border_arc_length_parameterizer_3<TriangleMesh>, Solver>,
  TriangleMesh> : std::true_type {};

} // namespace dlf
} // namespace internal

/// \ingroup PkgDiscreteLieFlowParameterizers
///
/// The class `Discrete_lie_flow_parameterizer_3` computes an area-preserving
/// (or density-prescribed) parameterization of a disk-topology triangle mesh
/// by the Discrete Lie Flow of Kehua Su, Chencheng Li, Shifan Zhao, Na Lei and
/// Xianfeng Gu, "Discrete Lie flow: A measure controllable parameterization
/// method", Computer Aided Geometric Design 72 (2019) 49–68
/// (\ref DLFBibSu2019 "Su et al. 2019"): starting from any flip-free
/// initial map, the domain vertices flow until every triangle's domain area
/// is proportional to its (density-weighted) surface area, with the step
/// bounded by the closed-form critical roots and certified by CGAL's exact
/// orientation predicate.
///
/// Three modes (`Discrete_lie_flow_options::mode`): `CERTIFIED` (default)
/// keeps the caller's connectivity and never folds it; `LITERAL` runs the
/// paper's Algorithm 1 as printed (doc/paper_literal.md; its failure, a
/// collapse, is reported as the stop reason `COLLAPSED`); `PAPER` is that
/// flow stabilised (doc/paper_mode.md). Both flip edges of the flowing
/// domain mesh. Where the printed paper is corrected: doc/paper_errata.md.
///
/// Meshes with holes (a connected genus-0 component with several border
/// loops, certified mode): the loop of `bhd` goes to the domain's border
/// (circle, square or free, as the initial parameterizer places it); every
/// other loop floats. The flow runs on the disk made by filling each hole
/// with a fan of virtual triangles around a virtual vertex (their targets:
/// the fan's 3D area), starting from Tutte's embedding of that filled disk
/// inside the initial parameterizer's outer loop (the library's own start:
/// the initial parameterizer cannot see the fill). The fill stays positively
/// oriented like the caller's triangles, so the result is globally
/// injective: no hole overlaps the rest of the map. The map, the report and
/// the area elements are about the caller's vertices and faces only.
///
/// \cgalModels `Parameterizer_3`
///
/// \tparam TriangleMesh_ a model of `FaceGraph`
/// \tparam InitialParameterizer_ a model of `Parameterizer_3` giving a flip-free
///   initial map; its border decides the domain (circle, square, or free).
///   Default: Tutte on the circle by arc length (`Symmetric_barycentric_mapping_parameterizer_3`).
///   With that parameterizer (on the circle by arc length, any solver), a
///   disk and the certified mode, the flow computes the same map itself,
///   with its own solver: one factorization of Tutte's system then gives the
///   start and the start's border spacing by area (the same map to rounding).
/// \tparam SolverTraits_ `CGAL::Eigen_solver_traits<S>` with `S` an Eigen
///   sparse SPD solver offering `analyzePattern()`/`factorize()`. Default:
///   CHOLMOD's supernodal LLT when available, else `Eigen::SimplicialLDLT`.
template <class TriangleMesh_, class InitialParameterizer_ = Default, class SolverTraits_ = Default>
class Discrete_lie_flow_parameterizer_3
{
public:
  /// \name Types
  /// @{

  /// The mesh type, `TriangleMesh_`.
  typedef TriangleMesh_ Triangle_mesh;
  /// The parameterizer of the initial map.
  typedef typename Default::Get<InitialParameterizer_,
    Symmetric_barycentric_mapping_parameterizer_3<TriangleMesh_> >::type Initial_parameterizer;
  /// The solver traits of the flow's sparse SPD systems.
  typedef typename Default::Get<SolverTraits_,
    Eigen_solver_traits<internal::dlf::Default_spd_solver> >::type Solver_traits;

  /// Vertex descriptor of the mesh.
  typedef typename boost::graph_traits<Triangle_mesh>::vertex_descriptor vertex_descriptor;
  /// Halfedge descriptor of the mesh.
  typedef typename boost::graph_traits<Triangle_mesh>::halfedge_descriptor halfedge_descriptor;
  /// Face descriptor of the mesh.
  typedef typename boost::graph_traits<Triangle_mesh>::face_descriptor face_descriptor;
  /// The kernel of the mesh's points.
  typedef typename internal::Kernel_traits<Triangle_mesh>::Kernel Kernel;
  /// The point type of the uv map.
  typedef typename Kernel::Point_2 Point_2;

  /// @}

  /// \param initial the parameterizer that gives the initial map
  /// \param options flow settings (mode, tolerance, caps, density, callback)
  /// \param solver_traits the sparse SPD solver
  explicit Discrete_lie_flow_parameterizer_3(Initial_parameterizer initial = Initial_parameterizer(),
                                             Discrete_lie_flow_options options = Discrete_lie_flow_options(),
                                             Solver_traits solver_traits = Solver_traits())
    : m_initial(initial), m_options(options), m_solver_traits(solver_traits)
  {}

  /// The flow settings, to read or change before `parameterize()`.
  Discrete_lie_flow_options& options() { return m_options; }
  /// The flow settings.
  const Discrete_lie_flow_options& options() const { return m_options; }
  /// The parameterizer of the initial map.
  Initial_parameterizer& initial_parameterizer() { return m_initial; }

  /// Sets a per-face density ρ > 0 (a readable property map, `face_descriptor`
  /// → number). The domain area of a face becomes proportional to ρ·area.
  template <class FaceDensityMap>
  void set_face_density(FaceDensityMap density)
  {
    m_face_density = [density](face_descriptor f) { return double(get(density, f)); };
  }
  /// Sets a per-vertex density ρ > 0; a face takes the mean of its corners.
  template <class VertexDensityMap>
  void set_vertex_density(VertexDensityMap density)
  {
    m_vertex_density = [density](vertex_descriptor v) { return double(get(density, v)); };
  }

  /// The report of this object's last run. Each copy owns its report: CGAL's
  /// `parameterize(mesh, parameterizer, bhd, uvmap)` runs a named
  /// `Discrete_lie_flow_parameterizer_3` itself (the overload below), so its
  /// `report()` describes that call.
  const Discrete_lie_flow_report& report() const { return m_report; }

  /// Writes the area elements of the last run into vertex property maps
  /// (`vertex_descriptor` → number): `target` receives A_M(v), the lumped
  /// (density-weighted) surface area scaled to the domain's total, `domain`
  /// receives A_Ω(v) of the final map. On a `Surface_mesh`, `parameterize()`
  /// already stores them as the properties "v:dlf_target_area" and
  /// "v:dlf_domain_area" (and the density as "f:dlf_density").
  template <class TargetAreaMap, class DomainAreaMap>
  void area_elements(TargetAreaMap target, DomainAreaMap domain) const
  {
    for(std::size_t i = 0; i < m_vertex_of.size() && i < m_report.target_area.size(); ++i) {
      put(target, m_vertex_of[i], m_report.target_area[i]);
      put(domain, m_vertex_of[i], m_report.domain_area[i]);
    }
  }

  /// The final domain triangulation of the last run, as vertex triples: the
  /// input triangles in certified mode, the flowing (flipped) ones in paper mode.
  std::vector<std::array<vertex_descriptor, 3> > domain_triangles() const
  {
    std::vector<std::array<vertex_descriptor, 3> > out;
    for(const std::array<int, 3>& t : m_report.domain_faces)
      out.push_back({{ m_vertex_of[std::size_t(t[0])], m_vertex_of[std::size_t(t[1])], m_vertex_of[std::size_t(t[2])] }});
    return out;
  }

  /// Computes the initial map, then flows it. Fills `uvmap` only with a map
  /// whose triangles all have the orientation of the initial map's (never NaN); on error, `uvmap` keeps whatever the
  /// initial parameterizer wrote, and the report's message names the element.
  ///
  /// \pre `bhd` is a border halfedge of `mesh`, whose connected component is
  /// a disk or, in certified mode, a disk with holes (genus 0); `vimap`
  /// indexes the vertices of that component from 0.
  template <typename VertexUVmap, typename VertexIndexMap, typename VertexParameterizedMap>
  Error_code parameterize(Triangle_mesh& mesh, halfedge_descriptor bhd, VertexUVmap uvmap,
                          VertexIndexMap vimap, VertexParameterizedMap vpmap)
  {
    typedef std::chrono::steady_clock Clock;
    namespace D = internal::dlf;
    Discrete_lie_flow_report& R = m_report;
    R = Discrete_lie_flow_report();
    auto fail = [&R](int code, const std::string& msg) { return D::report_failure(R, code, msg); };
    if(faces(mesh).empty()) return fail(ERROR_EMPTY_MESH, "");
    if(bhd == boost::graph_traits<Triangle_mesh>::null_halfedge() || !is_border(bhd, mesh))
      return fail(ERROR_NO_TOPOLOGICAL_DISC, "the given halfedge is not on a border");

    // Gather the connected component of bhd, its faces and its border loop.
    D::Disk_problem P;
    std::vector<vertex_descriptor> vertex_of;
    std::vector<face_descriptor> face_of;
    Error_code code = gather(mesh, bhd, vimap, P, vertex_of, face_of);
    if(code != OK) return code;
    m_vertex_of = vertex_of;

    // The solver's threads for the initial map too (Tutte's factorization
    // is as large as a flow step's); flow_disk() keeps them.
    const D::Scoped_blas_threads threads(m_options.solver_threads, vertex_of.size());
    typedef typename std::remove_reference<decltype(m_solver_traits.solver())>::type Eigen_solver;
    std::unique_ptr<D::Tutte_interior_system<Eigen_solver> > tutte;
    std::vector<D::Vec2> uv(vertex_of.size());
    const Clock::time_point t0 = Clock::now();
    // The library's own Tutte start in certified mode, whose start spacing
    // reuses the factorization; the paper's modes keep the caller's.
    if(D::Is_tutte_on_arc_length_circle<Initial_parameterizer, Triangle_mesh>::value && P.fill_faces == 0 &&
       m_options.mode == Discrete_lie_flow_mode::CERTIFIED) {
      code = tutte_start(P, uv, tutte);
      R.seconds_initial = std::chrono::duration<double>(Clock::now() - t0).count();
      if(code != OK) return fail(code, std::string("initial map: ") + discrete_lie_flow_error_message(code));
      for(std::size_t i = 0; i < vertex_of.size(); ++i) {
        put(uvmap, vertex_of[i], Point_2(uv[i][0], uv[i][1]));
        put(vpmap, vertex_of[i], true);
      }
    } else {
      code = m_initial.parameterize(mesh, bhd, uvmap, vimap, vpmap);
      R.seconds_initial = std::chrono::duration<double>(Clock::now() - t0).count();
      if(code != OK) return fail(code, std::string("initial map: ") + discrete_lie_flow_error_message(code));
    }

    // With holes, only the outer loop is taken from the initial map.
    std::vector<char> taken(vertex_of.size(), P.fill_faces == 0);
    for(int b : P.boundary) taken[std::size_t(b)] = 1;
    for(std::size_t i = 0; i < vertex_of.size(); ++i) {
      const Point_2 p = get(uvmap, vertex_of[i]);
      uv[i] = {{ CGAL::to_double(p.x()), CGAL::to_double(p.y()) }};
      if(taken[i] && (!std::isfinite(uv[i][0]) || !std::isfinite(uv[i][1])))
        return fail(ERROR_INITIAL_MAP_FOLDED, "initial map: vertex " + std::to_string(i) + " has a non-finite uv");
    }
    if(P.fill_faces > 0) {
      // The initial parameterizer does not see the fill: it gives the outer
      // loop (the domain's border), and the start is Tutte's embedding of
      // the filled disk inside it, bijective in exact arithmetic when the
      // loop is convex; flow_disk() certifies it by the exact predicate.
      const Clock::time_point t1 = Clock::now();
      uv.resize(P.xyz.size(), D::Vec2{{ 0, 0 }});
      if(!D::filled_disk_tutte<Eigen_solver>(P, uv))
        return fail(ERROR_CANNOT_SOLVE_LINEAR_SYSTEM, "initial map: the Tutte solve of the disk with filled holes failed");
      R.seconds_initial += std::chrono::duration<double>(Clock::now() - t1).count();
    }
    R.initial_uv.assign(uv.begin(), uv.begin() + std::ptrdiff_t(vertex_of.size()));
    code = D::flow_disk(P, uv, m_options, m_solver_traits.solver(), R, tutte.get());
    if(code != OK) {
      if(int(code) == int(ERROR_INITIAL_MAP_FOLDED) && P.fill_faces > 0)
        R.message += " (the start on the disk with filled holes: Tutte's embedding inside the initial map's outer loop, "
                     "bijective only when that loop is convex)";
      return code;
    }
    if(P.fill_faces > 0)
      R.message = (R.converged() ? std::string("Success") : R.message) + "; " + std::to_string(P.holes) + (P.holes == 1 ? " hole" : " holes") +
                  " filled for the flow and left free; initial map: Tutte's embedding of the filled disk "
                  "inside the initial parameterizer's outer loop";
    for(std::size_t i = 0; i < vertex_of.size(); ++i) put(uvmap, vertex_of[i], Point_2(uv[i][0], uv[i][1]));
    // On a Surface_mesh, the area elements and the densities become properties of the mesh.
    D::store_area_elements(mesh, vertex_of, R.target_area, R.domain_area, face_of, R.face_density);
    return OK;
  }

private:
  // The default initial map, Tutte's with the border on the circle by arc
  // length, from the problem: its factorization stays in `tutte`.
  template <class EigenSolver>
  Error_code tutte_start(const internal::dlf::Disk_problem& P, std::vector<internal::dlf::Vec2>& uv,
                         std::unique_ptr<internal::dlf::Tutte_interior_system<EigenSolver> >& tutte)
  {
    namespace D = internal::dlf;
    if(!D::circle_border_by_arc_length(P, uv)) return ERROR_BORDER_TOO_SHORT;
    tutte.reset(new D::Tutte_interior_system<EigenSolver>(P, uv.size(), m_solver_traits.solver()));
    if(tutte->unknowns() > 0 && !tutte->factorized()) return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
    return tutte->solve(uv) ? OK : ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
  }

  // A face named by the indices of its vertices, the only names every mesh type shares.
  template <typename VertexIndexMap>
  static std::string face_name(const Triangle_mesh& mesh, VertexIndexMap vimap, face_descriptor f)
  {
    std::string s = "(vertices";
    for(vertex_descriptor v : vertices_around_face(halfedge(f, mesh), mesh)) s += " " + std::to_string(long(get(vimap, v)));
    return s + ")";
  }

  // The component of `bhd` in index form: positions, faces, targets, and
  // the holes filled (see `disk_holes.h`).
  template <typename VertexIndexMap>
  Error_code gather(Triangle_mesh& mesh, halfedge_descriptor bhd, VertexIndexMap vimap,
                    internal::dlf::Disk_problem& P, std::vector<vertex_descriptor>& vertex_of,
                    std::vector<face_descriptor>& face_of)
  {
    Error_code code = gather_component(mesh, bhd, vimap, P, vertex_of, face_of);
    if(code == OK) code = gather_targets(mesh, vimap, P, vertex_of, face_of);
    if(code == OK) code = gather_loops(mesh, bhd, vimap, P, face_of);
    return code;
  }

  template <typename VertexIndexMap>
  Error_code gather_component(Triangle_mesh& mesh, halfedge_descriptor bhd, VertexIndexMap vimap,
                              internal::dlf::Disk_problem& P, std::vector<vertex_descriptor>& vertex_of,
                              std::vector<face_descriptor>& face_of)
  {
    namespace D = internal::dlf;
    Discrete_lie_flow_report& R = m_report;
    auto fail = [&R](int code, const std::string& msg) { return D::report_failure(R, code, msg); };
    // Faces of the component, by a walk across non-border edges. Dynamic
    // property maps, not trees of descriptors: millions of faces.
    auto seen = get(CGAL::dynamic_face_property_t<bool>(), mesh);
    for(face_descriptor f : faces(mesh)) put(seen, f, false);
    std::vector<face_descriptor> stack(1, face(opposite(bhd, mesh), mesh));
    put(seen, stack.back(), true);
    while(!stack.empty()) {
      const face_descriptor f = stack.back();
      stack.pop_back();
      for(halfedge_descriptor h : halfedges_around_face(halfedge(f, mesh), mesh)) {
        const halfedge_descriptor o = opposite(h, mesh);
        if(is_border(o, mesh)) continue;
        const face_descriptor g = face(o, mesh);
        if(!get(seen, g)) { put(seen, g, true); stack.push_back(g); }
      }
    }
    // In the order of faces(mesh), so that domain faces follow the input.
    for(face_descriptor f : faces(mesh))
      if(get(seen, f)) face_of.push_back(f);
    auto in_component = get(CGAL::dynamic_vertex_property_t<bool>(), mesh);
    for(vertex_descriptor v : vertices(mesh)) put(in_component, v, false);
    std::vector<vertex_descriptor> vs;
    for(std::size_t k = 0; k < face_of.size(); ++k) {
      std::size_t corners = 0;
      for(vertex_descriptor v : vertices_around_face(halfedge(face_of[k], mesh), mesh)) {
        if(!get(in_component, v)) { put(in_component, v, true); vs.push_back(v); }
        ++corners;
      }
      if(corners != 3)
        return fail(ERROR_NON_TRIANGULAR_MESH, "face " + face_name(mesh, vimap, face_of[k]) + " has " + std::to_string(corners) + " vertices");
    }
    const std::size_t n = vs.size();
    vertex_of.assign(n, vertex_descriptor());
    std::vector<bool> used(n, false);
    for(vertex_descriptor v : vs) {
      const long i = long(get(vimap, v));
      if(i < 0 || std::size_t(i) >= n || used[std::size_t(i)])
        return fail(ERROR_WRONG_PARAMETER, "the vertex index map does not number the component's vertices 0.." + std::to_string(n - 1));
      used[std::size_t(i)] = true;
      vertex_of[std::size_t(i)] = v;
    }
    const typename internal::Kernel_traits<Triangle_mesh>::PPM ppmap = get(vertex_point, mesh);
    P.xyz.resize(n);
    for(std::size_t i = 0; i < n; ++i) {
      const auto& p = get(ppmap, vertex_of[i]);
      P.xyz[i] = {{ CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()) }};
      if(!std::isfinite(P.xyz[i][0]) || !std::isfinite(P.xyz[i][1]) || !std::isfinite(P.xyz[i][2]))
        return fail(Error_code(ERROR_DEGENERATE_INPUT), "vertex " + std::to_string(i) + " has a non-finite coordinate");
    }
    for(face_descriptor f : face_of) {
      D::Face t;
      int k = 0;
      for(vertex_descriptor v : vertices_around_face(halfedge(f, mesh), mesh)) t[k++] = int(get(vimap, v));
      P.faces.push_back(t);
    }
    return OK;
  }

  // Targets: ρ_f · area_M(f); options.face_density follows faces(mesh).
  template <typename VertexIndexMap>
  Error_code gather_targets(Triangle_mesh& mesh, VertexIndexMap vimap, internal::dlf::Disk_problem& P,
                            const std::vector<vertex_descriptor>& vertex_of, const std::vector<face_descriptor>& face_of)
  {
    namespace D = internal::dlf;
    Discrete_lie_flow_report& R = m_report;
    auto fail = [&R](int code, const std::string& msg) { return D::report_failure(R, code, msg); };
    auto position = get(CGAL::dynamic_face_property_t<std::size_t>(), mesh);
    if(!m_face_density && !m_vertex_density && !m_options.face_density.empty()) {
      std::size_t count = 0;
      for(face_descriptor f : faces(mesh)) put(position, f, count++);
      if(m_options.face_density.size() != count)
        return fail(Error_code(ERROR_INVALID_DENSITY), "the density has " + std::to_string(m_options.face_density.size()) +
                    " values for " + std::to_string(count) + " faces");
    }
    P.target.resize(P.faces.size());
    for(std::size_t f = 0; f < P.faces.size(); ++f) {
      const D::Face& t = P.faces[f];
      const double a = D::triangle_area_3(P.xyz[t[0]], P.xyz[t[1]], P.xyz[t[2]]);
      if(!(a > 0) || !std::isfinite(a))
        return fail(Error_code(ERROR_DEGENERATE_INPUT), "face " + face_name(mesh, vimap, face_of[f]) + " has zero area");
      double rho = 1;
      if(m_face_density) rho = m_face_density(face_of[f]);
      else if(m_vertex_density) {
        rho = 0;
        for(int k = 0; k < 3; ++k) {
          const double r = m_vertex_density(vertex_of[std::size_t(t[k])]);
          if(!(r > 0) || !std::isfinite(r))
            return fail(Error_code(ERROR_INVALID_DENSITY), "the density of vertex " + std::to_string(t[k]) + " is " + std::to_string(r));
          rho += r / 3;
        }
      }
      else if(!m_options.face_density.empty()) rho = m_options.face_density[get(position, face_of[f])];
      if(!(rho > 0) || !std::isfinite(rho))
        return fail(Error_code(ERROR_INVALID_DENSITY), "the density of face " + face_name(mesh, vimap, face_of[f]) + " is " + std::to_string(rho));
      P.target[f] = rho * a;
    }
    return OK;
  }

  // The border loops, bhd's first: the outer loop becomes `P.boundary`,
  // the topology is checked, and every other loop is filled.
  template <typename VertexIndexMap>
  Error_code gather_loops(Triangle_mesh& mesh, halfedge_descriptor bhd, VertexIndexMap vimap,
                          internal::dlf::Disk_problem& P, const std::vector<face_descriptor>& face_of)
  {
    namespace D = internal::dlf;
    Discrete_lie_flow_report& R = m_report;
    auto fail = [&R](int code, const std::string& msg) { return D::report_failure(R, code, msg); };
    const std::size_t n = P.xyz.size();
    std::vector<std::vector<halfedge_descriptor> > loops(1);
    auto walked = get(CGAL::dynamic_halfedge_property_t<bool>(), mesh);
    for(halfedge_descriptor h : halfedges(mesh)) put(walked, h, false);
    for(halfedge_descriptor h : halfedges_around_face(bhd, mesh)) { loops[0].push_back(h); put(walked, h, true); }
    std::size_t border_edges = 0;
    for(face_descriptor f : face_of)
      for(halfedge_descriptor h : halfedges_around_face(halfedge(f, mesh), mesh)) {
        const halfedge_descriptor o = opposite(h, mesh);
        if(!is_border(o, mesh)) continue;
        ++border_edges;
        if(get(walked, o)) continue;
        put(walked, o, true);
        loops.emplace_back(1, o);
        for(halfedge_descriptor b = next(o, mesh); b != o; b = next(b, mesh)) { loops.back().push_back(b); put(walked, b, true); }
      }
    for(halfedge_descriptor h : loops[0]) P.boundary.push_back(int(get(vimap, target(h, mesh))));
    if(P.boundary.size() < 3) return fail(ERROR_BORDER_TOO_SHORT, "the border has fewer than 3 vertices");
    // χ = V − E + F = 2 − 2g − (loops): a disk has one loop and χ = 1; a
    // genus-0 mesh with holes has χ = 2 − loops.
    const std::size_t E = (3 * P.faces.size() + border_edges) / 2;
    const long chi = long(n) - long(E) + long(P.faces.size());
    if(loops.size() == 1 && chi == 1) return OK;
    const long twice_genus = 2 - chi - long(loops.size());
    if(twice_genus != 0) {
      std::string s = "the component has " + std::to_string(loops.size()) + " border loop" +
                      (loops.size() == 1 ? "" : "s") + " (" + std::to_string(border_edges) + " border edges, " +
                      std::to_string(P.boundary.size()) + " on the given loop), Euler characteristic " + std::to_string(chi);
      if(twice_genus > 0 && twice_genus % 2 == 0) s += ", genus " + std::to_string(twice_genus / 2);
      if(face_of.size() < faces(mesh).size())
        s += "; it is one of the mesh's connected components (" + std::to_string(face_of.size()) + " of " +
             std::to_string(faces(mesh).size()) + " faces)";
      return fail(ERROR_NO_TOPOLOGICAL_DISC, s + "; the parameterizer takes genus 0: a disk, or a disk with holes");
    }
    // Genus 0 with holes: fill every other loop. A vertex on two loops
    // (or twice on one) would give the fill a repeated edge.
    std::vector<char> on_loop(n, 0);
    for(const std::vector<halfedge_descriptor>& loop : loops)
      for(halfedge_descriptor h : loop) {
        const std::size_t v = std::size_t(get(vimap, target(h, mesh)));
        if(on_loop[v]++)
          return fail(ERROR_NO_TOPOLOGICAL_DISC, "vertex " + std::to_string(v) + " lies twice on the border loops "
                      "(a pinched border); a disk with holes needs them disjoint");
      }
    auto index_of = get(CGAL::dynamic_face_property_t<std::size_t>(), mesh);
    for(std::size_t k = 0; k < face_of.size(); ++k) put(index_of, face_of[k], k);
    for(std::size_t l = 1; l < loops.size(); ++l) {
      std::vector<int> loop;
      std::vector<std::size_t> across;
      // The border halfedge s → t: the fill face (s, t, c) has the caller's orientation.
      for(halfedge_descriptor h : loops[l]) {
        loop.push_back(int(get(vimap, source(h, mesh))));
        across.push_back(get(index_of, face(opposite(h, mesh), mesh)));
      }
      D::fill_hole(P, loop, across);
    }
    return OK;
  }

  Initial_parameterizer m_initial;
  Discrete_lie_flow_options m_options;
  Solver_traits m_solver_traits;
  std::function<double(face_descriptor)> m_face_density;
  std::function<double(vertex_descriptor)> m_vertex_density;
  // The last run: its report and the vertex of each index.
  Discrete_lie_flow_report m_report;
  std::vector<vertex_descriptor> m_vertex_of;
};

/// \ingroup PkgDiscreteLieFlowParameterizers
/// CGAL's `parameterize(mesh, parameterizer, bhd, uvmap)` for a named
/// `Discrete_lie_flow_parameterizer_3`: the generic function takes its
/// parameterizer by value, this one runs `parameterizer` itself, so that
/// `parameterizer.report()` describes the call. Same maps and result as the
/// generic function.
template <class TriangleMesh, class InitialParameterizer, class SolverTraits, class HD, class VertexUVmap>
Error_code parameterize(TriangleMesh& mesh,
                        Discrete_lie_flow_parameterizer_3<TriangleMesh, InitialParameterizer, SolverTraits>& parameterizer,
                        HD bhd, VertexUVmap uvmap)
{
  typedef CGAL::dynamic_vertex_property_t<int> Vertex_int_tag;
  typename boost::property_map<TriangleMesh, Vertex_int_tag>::type vimap = get(Vertex_int_tag(), mesh);
  // A halfedge that is not on a border is reported by the parameterizer.
  if(bhd != boost::graph_traits<TriangleMesh>::null_halfedge() && is_border(bhd, mesh))
    internal::fill_index_map_of_cc(bhd, mesh, vimap);
  typedef CGAL::dynamic_vertex_property_t<bool> Vertex_bool_tag;
  typename boost::property_map<TriangleMesh, Vertex_bool_tag>::type vpmap = get(Vertex_bool_tag(), mesh);
  return parameterizer.parameterize(mesh, bhd, uvmap, vimap, vpmap);
}

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
