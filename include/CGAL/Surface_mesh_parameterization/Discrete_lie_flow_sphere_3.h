// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_DISCRETE_LIE_FLOW_SPHERE_3_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_DISCRETE_LIE_FLOW_SPHERE_3_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_options.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_report.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_solver.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/default_solver.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/disk/disk_flow.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/mesh_properties.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/sphere/sphere_map.h>

#include <CGAL/Surface_mesh_parameterization/Error_code.h>
#include <CGAL/Surface_mesh_parameterization/internal/kernel_traits.h>

#include <CGAL/Default.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Eigen_solver_traits.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <array>
#include <chrono>
#include <functional>
#include <memory>
#include <utility>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgDiscreteLieFlowParameterizers
///
/// Area-preserving (or density-prescribed) map of a closed genus-0 triangle
/// mesh onto the unit sphere by the Discrete Lie Flow on the sphere (Kehua
/// Su, Chenchen Li, Shifan Zhao, Na Lei and Xianfeng Gu, "Discrete Lie flow:
/// A measure controllable parameterization method", Computer Aided Geometric
/// Design 72 (2019) 49–68; \ref DLFBibSu2019 "Su et al. 2019").
///
/// The initial map punctures one face, embeds the remaining disk by Tutte's
/// barycentric map with the punctured triangle as a convex border (or, with
/// `options().sphere.start = CONFORMAL`, by the cotangent-harmonic map, the
/// paper's kind of start), and lifts it by inverse stereographic projection
/// at the scale that minimises the area distortion; it is accepted only when
/// every face is positively oriented by CGAL's exact predicate
/// `orientation(O, p, q, r)` (O the centre), else other punctures are tried.
/// A caller's own start is given with `set_initial_map()`. The flow (certified mode, the
/// default) descends the barrier energy D_area of the
/// triangles between the sphere points: first on their cone areas along the
/// tangential Sobolev gradient, then on their flat areas along a regularised
/// Gauss–Newton direction followed by vertex-by-vertex relaxation sweeps.
/// Every global step is bounded by μ times the smallest positive root of the
/// per-face cubics det[p₁ + λt₁, p₂ + λt₂, p₃ + λt₃], every point is
/// re-normalised and every accepted step certified exactly. The result is
/// never folded: every face of the caller's mesh keeps det[p, q, r] > 0.
///
/// Paper mode (`Discrete_lie_flow_mode::PAPER`) runs the paper's flow,
/// stabilised (a plateau test, a stall detector, the best iterate), from the
/// same initial map: Delaunay edge flips of the flowing
/// spherical triangulation before each Poisson solve, the tangential part of
/// the potential's gradient, the same cubic step, every step certified on the
/// flowing triangulation. Its result may fold the caller's triangles; the
/// report counts them and holds the flowing triangulation. Literal mode
/// (`Discrete_lie_flow_mode::LITERAL`) runs Algorithm 1 as printed from the
/// same start: the step μ·min λ̃ or a fixed step, no safeguards, the stop
/// rule ‖h_M − h_Ω‖² < ε, a collapse reported as the stop reason
/// `COLLAPSED` (doc/paper_literal.md, doc/paper_errata.md).
///
/// \tparam TriangleMesh_ a model of `FaceGraph` (closed, connected, genus 0, triangles)
/// \tparam SolverTraits_ `CGAL::Eigen_solver_traits<S>` with `S` an Eigen
///   sparse SPD solver offering `analyzePattern()`/`factorize()`. Default:
///   `Discrete_lie_flow_default_spd_solver` (CHOLMOD's supernodal LLT when
///   available, else `Eigen::SimplicialLDLT`).
template <class TriangleMesh_, class SolverTraits_ = Default>
class Discrete_lie_flow_sphere_parameterizer_3
{
public:
  /// \name Types
  /// @{

  /// The mesh type, `TriangleMesh_`.
  typedef TriangleMesh_ Triangle_mesh;
  /// The solver traits of the flow's sparse SPD systems.
  typedef typename Default::Get<SolverTraits_,
    Eigen_solver_traits<Discrete_lie_flow_default_spd_solver> >::type Solver_traits;
  /// Vertex descriptor of the mesh.
  typedef typename boost::graph_traits<Triangle_mesh>::vertex_descriptor vertex_descriptor;
  /// Face descriptor of the mesh.
  typedef typename boost::graph_traits<Triangle_mesh>::face_descriptor face_descriptor;
  /// Halfedge descriptor of the mesh.
  typedef typename boost::graph_traits<Triangle_mesh>::halfedge_descriptor halfedge_descriptor;

  /// @}

  /// \param options flow settings (mode, tolerances, caps, density, callback)
  /// \param solver_traits the sparse SPD solver
  explicit Discrete_lie_flow_sphere_parameterizer_3(const Discrete_lie_flow_options& options = Discrete_lie_flow_options(),
                                                    Solver_traits solver_traits = Solver_traits())
    : m_options(options), m_solver_traits(solver_traits)
  {}

  /// The flow settings, to read or change before `parameterize()`.
  Discrete_lie_flow_options& options() { return m_options; }
  /// The flow settings.
  const Discrete_lie_flow_options& options() const { return m_options; }

  /// The report of this object's last run (each copy owns its own).
  const Discrete_lie_flow_report& report() const { return m_report; }

  /// Sets a per-face density ρ > 0 (a readable property map, `face_descriptor`
  /// → number): the sphere area of a face becomes proportional to ρ·area.
  /// Replaces `options().face_density`.
  template <class FaceDensityMap>
  void set_face_density(FaceDensityMap density)
  {
    m_face_density = [density](face_descriptor f) { return double(get(density, f)); };
    m_vertex_density = nullptr;
  }
  /// Sets a per-vertex density ρ > 0; a face takes the mean of its corners.
  template <class VertexDensityMap>
  void set_vertex_density(VertexDensityMap density)
  {
    m_vertex_density = [density](vertex_descriptor v) { return double(get(density, v)); };
    m_face_density = nullptr;
  }

  /// Starts the flow from the caller's map instead of the library's
  /// (`options().sphere.start`): `initial_map` is a readable property map
  /// `vertex_descriptor` → a 3D point with `x()`, `y()`, `z()` (e.g. an
  /// earlier result, or a conformal map made elsewhere). Each point is
  /// scaled onto the unit sphere; the map must keep every face positively
  /// oriented by the exact predicate, else `parameterize()` returns
  /// `ERROR_INITIAL_MAP_FOLDED` and names the first folded face.
  template <class VertexPointMap>
  void set_initial_map(VertexPointMap initial_map)
  {
    m_initial_map = [initial_map](vertex_descriptor v) {
      const auto& q = get(initial_map, v);
      return internal::dlf::Vec3{{ CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z()) }};
    };
  }
  /// Goes back to the library's start (`options().sphere.start`).
  void clear_initial_map() { m_initial_map = nullptr; }

  /// Maps `mesh` onto the unit sphere: `sphere_map` (a writable property
  /// map `vertex_descriptor` → a 3D point type constructible from three
  /// doubles, e.g. the mesh kernel's `Point_3`) receives unit vectors, and
  /// only on success (never NaN; never a folded map in certified mode). The
  /// density, if any, comes from `set_face_density()`,
  /// `set_vertex_density()` or `options().face_density` (in the order of
  /// `faces(mesh)`).
  template <class VertexSphereMap>
  Error_code parameterize(const Triangle_mesh& mesh, VertexSphereMap sphere_map)
  {
    std::vector<vertex_descriptor> vertex_of;
    std::vector<face_descriptor> face_of;
    return parameterize(mesh, sphere_map, vertex_of, face_of);
  }

  /// The same; on a `Surface_mesh`, the per-vertex target and domain area
  /// elements (`report().target_area`, `report().domain_area`) and the
  /// per-face density are then stored as the properties "v:dlf_target_area",
  /// "v:dlf_domain_area" and "f:dlf_density" of `mesh`.
  template <class VertexSphereMap>
  Error_code parameterize(Triangle_mesh& mesh, VertexSphereMap sphere_map)
  {
    std::vector<vertex_descriptor> vertex_of;
    std::vector<face_descriptor> face_of;
    const Error_code code = parameterize(std::as_const(mesh), sphere_map, vertex_of, face_of);
    if(code == OK)
      internal::dlf::store_area_elements(mesh, vertex_of, m_report.target_area, m_report.domain_area, face_of,
                                         m_report.face_density);
    return code;
  }

  /// Writes the area elements of the last run into vertex property maps
  /// (`vertex_descriptor` → number), in the order of `vertices(mesh)`.
  template <class TargetAreaMap, class DomainAreaMap>
  void area_elements(const Triangle_mesh& mesh, TargetAreaMap target, DomainAreaMap domain) const
  {
    std::size_t i = 0;
    for(vertex_descriptor v : vertices(mesh)) {
      if(i >= m_report.target_area.size()) break;
      put(target, v, m_report.target_area[i]);
      put(domain, v, m_report.domain_area[i]);
      ++i;
    }
  }

private:
  template <class VertexSphereMap>
  Error_code parameterize(const Triangle_mesh& mesh, VertexSphereMap sphere_map, std::vector<vertex_descriptor>& vertex_of,
                          std::vector<face_descriptor>& face_of)
  {
    namespace D = internal::dlf;
    Discrete_lie_flow_report& R = m_report;
    R = Discrete_lie_flow_report();
    if(faces(mesh).empty()) return D::report_failure(R, ERROR_EMPTY_MESH, "the mesh has no faces");
    // Index the vertices in iteration order, and gather the faces.
    typedef typename boost::property_map<Triangle_mesh, CGAL::dynamic_vertex_property_t<int> >::const_type Index_map;
    Index_map index = get(CGAL::dynamic_vertex_property_t<int>(), mesh);
    for(vertex_descriptor v : vertices(mesh)) { put(index, v, int(vertex_of.size())); vertex_of.push_back(v); }
    D::Sphere_problem P;
    const typename internal::Kernel_traits<Triangle_mesh>::PPM ppmap = get(vertex_point, mesh);
    P.xyz.resize(vertex_of.size());
    for(std::size_t i = 0; i < vertex_of.size(); ++i) {
      const auto& q = get(ppmap, vertex_of[i]);
      P.xyz[i] = {{ CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z()) }};
    }
    std::size_t f_index = 0;
    for(face_descriptor f : faces(mesh)) {
      if(degree(f, mesh) != 3)
        return D::report_failure(R, ERROR_NON_TRIANGULAR_MESH, "face " + std::to_string(f_index) + " has " +
                                 std::to_string(degree(f, mesh)) + " vertices; a spherical map needs triangles");
      D::Face t;
      int k = 0;
      for(vertex_descriptor v : vertices_around_face(halfedge(f, mesh), mesh)) t[k++] = get(index, v);
      P.faces.push_back(t);
      face_of.push_back(f);
      ++f_index;
    }
    Discrete_lie_flow_options options = m_options;
    if(m_face_density || m_vertex_density) {
      options.face_density.assign(face_of.size(), 0.);
      for(std::size_t f = 0; f < face_of.size(); ++f) {
        if(m_face_density) { options.face_density[f] = m_face_density(face_of[f]); continue; }
        for(int k = 0; k < 3; ++k) options.face_density[f] += m_vertex_density(vertex_of[std::size_t(P.faces[f][k])]) / 3;
      }
    }
    std::vector<D::Vec3> given;
    if(m_initial_map)
      for(vertex_descriptor v : vertex_of) given.push_back(m_initial_map(v));
    std::vector<D::Vec3> points;
    const Error_code code = D::map_to_sphere(P, points, options, m_solver_traits.solver(), R, m_initial_map ? &given : nullptr);
    if(code != OK) return code;
    typedef typename boost::property_traits<VertexSphereMap>::value_type Point;
    for(std::size_t i = 0; i < vertex_of.size(); ++i) put(sphere_map, vertex_of[i], Point(points[i][0], points[i][1], points[i][2]));
    return OK;
  }

  Discrete_lie_flow_options m_options;
  Solver_traits m_solver_traits;
  std::function<double(face_descriptor)> m_face_density;
  std::function<double(vertex_descriptor)> m_vertex_density;
  std::function<internal::dlf::Vec3(vertex_descriptor)> m_initial_map;
  Discrete_lie_flow_report m_report;
};

/// \ingroup PkgDiscreteLieFlowParameterizers
/// Maps the closed genus-0 triangle mesh `mesh` onto the unit sphere with
/// the spherical Discrete Lie Flow (see `Discrete_lie_flow_sphere_parameterizer_3`);
/// `sphere_map` receives unit vectors on success. Returns the report, whose
/// `status` is `OK` or the error code, and whose `message` says what was found.
template <class TriangleMesh, class VertexSphereMap>
Discrete_lie_flow_report discrete_lie_flow_sphere(const TriangleMesh& mesh, VertexSphereMap sphere_map,
                                                         const Discrete_lie_flow_options& options = Discrete_lie_flow_options())
{
  Discrete_lie_flow_sphere_parameterizer_3<TriangleMesh> dlf(options);
  dlf.parameterize(mesh, sphere_map);
  return dlf.report();
}

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
