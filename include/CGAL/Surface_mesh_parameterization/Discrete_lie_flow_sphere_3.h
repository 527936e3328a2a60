// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_DISCRETE_LIE_FLOW_SPHERE_3_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_DISCRETE_LIE_FLOW_SPHERE_3_H

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_options.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_parameterizer_3.h> // Default_spd_solver
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/sphere_flow.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/sphere_initial_map.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/sphere_problem.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/sphere_paper_flow.h>

#include <CGAL/Surface_mesh_parameterization/Error_code.h>
#include <CGAL/Surface_mesh_parameterization/internal/kernel_traits.h>

#include <CGAL/Default.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Eigen_solver_traits.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <array>
#include <chrono>
#include <memory>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgDiscreteLieFlowOptions
/// What a run of the spherical Discrete Lie Flow did.
struct Discrete_lie_flow_sphere_report
{
  /// `OK`, or the error code that `parameterize()` returned.
  Error_code status = OK;
  std::string message;          ///< one line naming the offending element on error
  /// Why the flow stopped.
  Discrete_lie_flow_stop_reason stop_reason = Discrete_lie_flow_stop_reason::NOT_RUN;
  ///@{
  /// The size of the input mesh.
  std::size_t vertices = 0, faces = 0;
  ///@}
  /// The number of accepted iterations.
  std::size_t iterations = 0;
  double initial_d_area = 0;    ///< of the certified initial map (flat triangles between sphere points)
  /// The area distortion of the result (optimum 2).
  double final_d_area = 0;
  double final_residual = 0;    ///< Σ (A_Ω − A_M)² / (Σ A_Ω)²
  /// The largest error of a region's share of the sphere (density_levels.h,
  /// flat triangles; the measure of `options.share_tolerance`); 0 without a density.
  double final_share_error = 0;
  ///@{
  /// Faces of the result not positively oriented (exact `orientation(O, p, q, r)`); 0 on success.
  std::size_t inverted_faces = 0, degenerate_faces = 0;
  ///@}
  std::size_t rejected_by_exact_check = 0; ///< trial steps the doubles accepted and the exact predicate refused
  int puncture_face = -1;       ///< the face of the initial map's north cap (index in face order)
  double initial_scale = 0;     ///< the plane scale of the stereographic lift
  std::size_t initial_attempts = 0; ///< punctures tried before one was certified
  ///@{
  /// Numeric factorisations and symbolic analyses of the flow's sparse matrices.
  std::size_t factorizations = 0, symbolic_analyses = 0;
  ///@}
  ///@{
  /// Seconds spent on the initial map and on the flow.
  double seconds_initial = 0, seconds_flow = 0;
  ///@}
  /// Split of seconds_flow: matrix assembly, factorisation and solve, step search, certification and
  /// the polish's vertex relaxation.
  ///@{
  double seconds_assembly = 0, seconds_solve = 0, seconds_step = 0;
  ///@}
  ///@{
  /// The distortion metrics (d_area, ARAP, symmetric Dirichlet, log area ratios, inverted faces,
  /// smallest angle) of the initial and the final map (valid when status is OK).
  internal::dlf::Distortion_metrics initial_metrics, final_metrics;
  ///@}
  std::vector<Discrete_lie_flow_iteration> history; ///< when options.record_history
  /// Paper mode: there `inverted_faces` and `degenerate_faces` count the
  /// caller's triangles folded under the result (the mode's documented
  /// contract), `final_d_area` and `final_residual` are those of the flowing
  /// triangulation, whose faces (vertex indices in the order of
  /// `vertices(mesh)`) are `flowing_faces` (empty in certified mode, whose
  /// triangulation is the input's). `flowing_inverted_faces` counts its
  /// faces not positively oriented (exact; always 0), and
  /// `flowing_non_delaunay_edges` its edges left non-Delaunay on the sphere
  /// (0 except with flips off, or when the last flips were undone because
  /// they raised D_area: starts compressed to the rounding level).
  std::size_t flips = 0;
  ///@{
  /// Paper mode: see `flips`.
  std::size_t flowing_inverted_faces = 0, flowing_non_delaunay_edges = 0;
  std::vector<std::array<int, 3> > flowing_faces;
  ///@}
};

/// \ingroup PkgDiscreteLieFlowParameterizers
///
/// Area-preserving (or density-prescribed) map of a closed genus-0 triangle
/// mesh onto the unit sphere by the Discrete Lie Flow on the sphere.
///
/// The initial map punctures one face, embeds the remaining disk by Tutte's
/// barycentric map with the punctured triangle as a convex border, and lifts
/// it by inverse stereographic projection at the scale that minimises the
/// area distortion; it is accepted only when every face is positively
/// oriented by CGAL's exact predicate `orientation(O, p, q, r)` (O the
/// centre), else other punctures are tried. The flow (certified mode, the
/// default) descends the barrier energy D_area of the
/// triangles between the sphere points: first on their cone areas along the
/// tangential Sobolev gradient, then on their flat areas along a regularised
/// Gauss–Newton direction followed by vertex-by-vertex relaxation sweeps.
/// Every global step is bounded by μ times the smallest positive root of the
/// per-face cubics det[p₁ + λt₁, p₂ + λt₂, p₃ + λt₃], every point is
/// re-normalised and every accepted step certified exactly. The result is
/// never folded: every face of the caller's mesh keeps det[p, q, r] > 0.
///
/// Paper mode (`Discrete_lie_flow_mode::PAPER`, the reference) runs the
/// paper's flow from the same initial map: Delaunay edge flips of the flowing
/// spherical triangulation before each Poisson solve, the tangential part of
/// the potential's gradient, the same cubic step, every step certified on the
/// flowing triangulation. Its result may fold the caller's triangles; the
/// report counts them and holds the flowing triangulation.
///
/// \tparam TriangleMesh_ a model of `FaceGraph` (closed, connected, genus 0, triangles)
/// \tparam SolverTraits_ `CGAL::Eigen_solver_traits<S>` with `S` an Eigen
///   sparse SPD solver offering `analyzePattern()`/`factorize()`. Default:
///   CHOLMOD's supernodal LLT when available, else `Eigen::SimplicialLDLT`.
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
    Eigen_solver_traits<internal::dlf::Default_spd_solver> >::type Solver_traits;
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
    : m_options(options), m_solver_traits(solver_traits),
      m_report(std::make_shared<Discrete_lie_flow_sphere_report>())
  {}

  /// The flow settings, to read or change before `parameterize()`.
  Discrete_lie_flow_options& options() { return m_options; }
  /// The flow settings.
  const Discrete_lie_flow_options& options() const { return m_options; }

  /// The report of the last run (shared by all copies of this object).
  const Discrete_lie_flow_sphere_report& report() const { return *m_report; }

  /// Maps `mesh` onto the unit sphere: `sphere_map` (a writable property
  /// map `vertex_descriptor` → a 3D point type constructible from three
  /// doubles, e.g. the mesh kernel's `Point_3`) receives unit vectors, and
  /// only on success (never NaN; never a folded map in certified mode). Per-face densities, if
  /// any, are read from `options().face_density` in the order of `faces(mesh)`.
  template <class VertexSphereMap>
  Error_code parameterize(const Triangle_mesh& mesh, VertexSphereMap sphere_map)
  {
    namespace D = internal::dlf;
    Discrete_lie_flow_sphere_report& R = *m_report;
    R = Discrete_lie_flow_sphere_report();
    if(faces(mesh).empty()) return fail(ERROR_EMPTY_MESH, "the mesh has no faces");
    // Index the vertices in iteration order, and gather the faces.
    typedef typename boost::property_map<Triangle_mesh, CGAL::dynamic_vertex_property_t<int> >::const_type Index_map;
    Index_map index = get(CGAL::dynamic_vertex_property_t<int>(), mesh);
    std::vector<vertex_descriptor> vertex_of;
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
        return fail(ERROR_NON_TRIANGULAR_MESH, "face " + std::to_string(f_index) + " has " +
                    std::to_string(degree(f, mesh)) + " vertices; a spherical map needs triangles");
      D::Face t;
      int k = 0;
      for(vertex_descriptor v : vertices_around_face(halfedge(f, mesh), mesh)) t[k++] = get(index, v);
      P.faces.push_back(t);
      ++f_index;
    }
    std::vector<D::Vec3> points;
    const Error_code code = run(P, points);
    if(code != OK) return code;
    typedef typename boost::property_traits<VertexSphereMap>::value_type Point;
    for(std::size_t i = 0; i < vertex_of.size(); ++i) put(sphere_map, vertex_of[i], Point(points[i][0], points[i][1], points[i][2]));
    return OK;
  }

  /// The same on index data (`P.xyz`, `P.faces`; `P.target` is filled from
  /// the areas and `options().face_density`). `points` receives the unit
  /// vectors, in vertex order, only on success.
  Error_code run(internal::dlf::Sphere_problem& P, std::vector<internal::dlf::Vec3>& points)
  {
    namespace D = internal::dlf;
    typedef std::chrono::steady_clock Clock;
    Discrete_lie_flow_sphere_report& R = *m_report;
    R = Discrete_lie_flow_sphere_report();
    R.vertices = P.xyz.size();
    R.faces = P.faces.size();
    std::vector<D::Vec3> p;
    const Error_code started = start(P, p);
    if(started != OK) return started;
    if(m_options.mode == Discrete_lie_flow_mode::PAPER) return run_paper(P, p, points);

    const Clock::time_point t1 = Clock::now();
    D::Flow_outcome out = D::certified_sphere_flow(P, p, m_options, m_solver_traits.solver());
    R.seconds_flow = std::chrono::duration<double>(Clock::now() - t1).count();
    record(out);
    R.final_metrics = D::spherical_distortion(P.xyz, p, P.faces, density());
    R.final_share_error = share_error(P, p);
    const D::Orientation_count oc = D::count_orientations_sphere(p, P.faces);
    R.inverted_faces = oc.inverted;
    R.degenerate_faces = oc.degenerate;
    if(!oc.all_positive()) // cannot happen: the start and every accepted step are certified
      return fail(ERROR_NO_1_TO_1_MAPPING, "the flow produced " + std::to_string(oc.inverted + oc.degenerate) + " non-positive faces");
    points.swap(p);
    R.status = OK;
    R.message = "Success";
    return OK;
  }

private:
  Error_code fail(int code, const std::string& msg)
  {
    m_report->status = Error_code(code);
    m_report->message = msg.empty() ? std::string(discrete_lie_flow_error_message(code)) : msg;
    return Error_code(code);
  }

  const std::vector<double>& density() const { return m_options.face_density; }

  // Both modes: validation, then the certified initial map `p`.
  Error_code start(internal::dlf::Sphere_problem& P, std::vector<internal::dlf::Vec3>& p)
  {
    namespace D = internal::dlf;
    typedef std::chrono::steady_clock Clock;
    Discrete_lie_flow_sphere_report& R = *m_report;
    D::Validation check = D::validate_sphere_topology(P.xyz.size(), P.faces);
    if(!check.ok()) return fail(check.code, check.message);
    check = D::validate_sphere_geometry(P, m_options.face_density);
    if(!check.ok()) return fail(check.code, check.message);
    const Clock::time_point t0 = Clock::now();
    const D::Sphere_initial_outcome init = D::certified_sphere_initial_map<typename Solver_traits::Solver>(P, p);
    R.seconds_initial = std::chrono::duration<double>(Clock::now() - t0).count();
    R.initial_attempts = init.attempts;
    if(!init.certified) return fail(Error_code(ERROR_INITIAL_MAP_FOLDED), init.message);
    R.puncture_face = init.puncture;
    R.initial_scale = init.scale;
    R.initial_metrics = D::spherical_distortion(P.xyz, p, P.faces, density());
    return OK;
  }

  static double share_error(const internal::dlf::Sphere_problem& P, const std::vector<internal::dlf::Vec3>& p)
  {
    std::vector<double> flat;
    internal::dlf::signed_areas_sphere(p, P.faces, flat);
    return internal::dlf::Density_levels(P.xyz, P.faces, P.target).error(flat);
  }

  // Both modes: what the flow reports, into the report.
  void record(internal::dlf::Flow_outcome& out)
  {
    Discrete_lie_flow_sphere_report& R = *m_report;
    R.stop_reason = out.stop_reason;
    R.iterations = out.iterations;
    R.initial_d_area = out.initial_d_area;
    R.final_d_area = out.final_d_area;
    R.final_residual = out.final_residual;
    R.rejected_by_exact_check = out.rejected_by_exact_check;
    R.factorizations = out.factorizations;
    R.symbolic_analyses = out.symbolic_analyses;
    R.seconds_assembly = out.seconds_assembly;
    R.seconds_solve = out.seconds_solve;
    R.seconds_step = out.seconds_step;
    R.history = std::move(out.history);
  }

  Discrete_lie_flow_options m_options;
  Solver_traits m_solver_traits;
  std::shared_ptr<Discrete_lie_flow_sphere_report> m_report;

  // Paper mode (the reference): the paper's flow with Delaunay edge flips of
  // the flowing spherical triangulation, from the same certified initial map.
  // The flowing triangulation is certified at every step; the caller's
  // triangles may fold under the result, which is reported, not refused.
  Error_code run_paper(internal::dlf::Sphere_problem& P, std::vector<internal::dlf::Vec3>& p,
                       std::vector<internal::dlf::Vec3>& points)
  {
    namespace D = internal::dlf;
    typedef std::chrono::steady_clock Clock;
    Discrete_lie_flow_sphere_report& R = *m_report;
    const Clock::time_point t1 = Clock::now();
    D::Sphere_paper_outcome out = D::paper_sphere_flow(P, p, m_options, m_solver_traits.solver());
    R.seconds_flow = std::chrono::duration<double>(Clock::now() - t1).count();
    record(out);
    R.flips = out.flips;
    R.flowing_non_delaunay_edges = out.non_delaunay_edges;
    R.flowing_faces.assign(out.flowing.begin(), out.flowing.end());
    R.final_metrics = D::spherical_distortion(P.xyz, p, P.faces, density());
    R.final_share_error = share_error(P, p);
    const D::Orientation_count caller = D::count_orientations_sphere(p, P.faces);
    R.inverted_faces = caller.inverted;
    R.degenerate_faces = caller.degenerate;
    const D::Orientation_count flowing = D::count_orientations_sphere(p, out.flowing);
    R.flowing_inverted_faces = flowing.inverted + flowing.degenerate;
    if(!flowing.all_positive()) // cannot happen: the start, every accepted step and every flip are certified
      return fail(ERROR_NO_1_TO_1_MAPPING, "the flow produced " + std::to_string(R.flowing_inverted_faces) +
                                           " non-positive faces of its flowing triangulation");
    if(out.iterations == 0 && out.stop_reason == Discrete_lie_flow_stop_reason::STALLED)
      return fail(Error_code(ERROR_FLOW_STALLED), out.solver_failed ? "the linear solver failed on the initial map"
                                                                     : "no step improves the initial map");
    points.swap(p);
    R.status = OK;
    R.message = "Success";
    return OK;
  }
};

/// \ingroup PkgDiscreteLieFlowParameterizers
/// Maps the closed genus-0 triangle mesh `mesh` onto the unit sphere with
/// the spherical Discrete Lie Flow (see `Discrete_lie_flow_sphere_parameterizer_3`);
/// `sphere_map` receives unit vectors on success. Returns the report, whose
/// `status` is `OK` or the error code, and whose `message` says what was found.
template <class TriangleMesh, class VertexSphereMap>
Discrete_lie_flow_sphere_report discrete_lie_flow_sphere(const TriangleMesh& mesh, VertexSphereMap sphere_map,
                                                         const Discrete_lie_flow_options& options = Discrete_lie_flow_options())
{
  Discrete_lie_flow_sphere_parameterizer_3<TriangleMesh> dlf(options);
  dlf.parameterize(mesh, sphere_map);
  return dlf.report();
}

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
