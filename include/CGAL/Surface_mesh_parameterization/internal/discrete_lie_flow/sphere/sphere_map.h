// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The spherical map on index data, from a closed genus-0 mesh to a filled
// report: validation, the certified initial map, the mode's policy run by
// the flow driver, and the report (metrics, area elements, counts).

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_SPHERE_MAP_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_SPHERE_MAP_H

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_options.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_report.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/certification.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/density_levels.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/flow/flow_report.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/distortion.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/flow/flow_driver.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/sphere/sphere_literal_flow.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/sphere/sphere_certified_flow.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/sphere/sphere_coarse_to_fine.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/sphere/sphere_initial_map.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/sphere/sphere_paper_flow.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/sphere/sphere_problem.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/sphere/sphere_split_vertices.h>

#include <chrono>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// The certified flow's start on a mesh with many edge-split vertices
/// (`sphere_split_vertices.h`): the coarse mesh without them is mapped (the
/// library's start and the certified flow, the caller's options without the
/// callback), and the map is prolongated. The fans of needles around split
/// points are what slows the flow on such meshes (hundreds of iterations
/// capped by their critical roots); the coarse mesh has none and the
/// prolongation keeps the coarse map's shares to second order. False (and
/// `p` untouched) when there is little to remove, the coarse map fails, or
/// the prolongated map is not certified by the exact predicate.
template <class EigenSolver>
bool coarse_sphere_start(const Sphere_problem& P, std::vector<Vec3>& p, const Discrete_lie_flow_options& opt,
                         Discrete_lie_flow_report& R, const Split_vertex_settings& settings = Split_vertex_settings())
{
  const Split_vertex_coarsening c = coarsen_split_vertices(P, settings.sin_tolerance);
  if(double(c.removed.size()) < settings.least_fraction * double(P.xyz.size())) return false;
  std::vector<Vec3> q;
  const Sphere_initial_outcome init = certified_sphere_initial_map<EigenSolver>(
    c.coarse, q, false, 3, true, false, true, opt.sphere.start == Discrete_lie_flow_sphere_start::MEAN_VALUE);
  if(!init.certified) return false;
  Discrete_lie_flow_options coarse_options = opt;
  coarse_options.callback = nullptr;
  EigenSolver solver;
  Sphere_certified_flow<EigenSolver> flow(c.coarse, q, coarse_options, solver, Sphere_flow_settings());
  const Flow_outcome out = run_flow(flow, coarse_options);
  if(out.stop_reason == Discrete_lie_flow_stop_reason::STALLED || out.solver_failed) return false;
  std::vector<Vec3> fine = prolongate_split_vertices(c, q);
  if(!count_orientations_sphere(fine, P.faces).all_positive()) return false;
  p.swap(fine);
  R.split_vertices_removed = c.removed.size();
  R.coarse_iterations = out.iterations;
  R.puncture_face = init.puncture;
  R.initial_scale = init.scale;
  R.initial_attempts = init.attempts;
  return true;
}

/// Validation, then the certified initial map `p`: the caller's `given`
/// one when not null, else the library's start `opt.sphere.start`.
template <class EigenSolver>
Error_code start_sphere(Sphere_problem& P, std::vector<Vec3>& p, const Discrete_lie_flow_options& opt,
                        Discrete_lie_flow_report& R, const std::vector<Vec3>* given = nullptr)
{
  typedef std::chrono::steady_clock Clock;
  Validation check = validate_sphere_topology(P.xyz.size(), P.faces);
  if(!check.ok()) return report_failure(R, check.code, check.message);
  check = validate_sphere_geometry(P, opt.face_density);
  if(!check.ok()) return report_failure(R, check.code, check.message);
  const Clock::time_point t0 = Clock::now();
  if(given) {
    R.sphere_start = Discrete_lie_flow_sphere_start::GIVEN;
    const std::string why = certified_given_sphere_map(P, *given, p);
    if(!why.empty())
      return report_failure(R, given->size() == P.xyz.size() ? int(ERROR_INITIAL_MAP_FOLDED) : int(ERROR_WRONG_PARAMETER), why);
  } else {
    if(opt.sphere.start == Discrete_lie_flow_sphere_start::GIVEN)
      return report_failure(R, ERROR_WRONG_PARAMETER, "the start GIVEN needs a map (set_initial_map())");
    R.sphere_start = opt.sphere.start;
    // The certified flow opens a less compressed start in fewer steps; the
    // paper's modes keep the plain Tutte start they are measured from.
    const bool conformal = opt.sphere.start == Discrete_lie_flow_sphere_start::CONFORMAL;
    // Edge-split vertices first (their coarse mesh is the one they were
    // made from), then the levels of a large mesh; the plain start when
    // neither applies or a level's map is refused.
    const bool certified = opt.mode == Discrete_lie_flow_mode::CERTIFIED && !conformal;
    if(!(certified && coarse_sphere_start<EigenSolver>(P, p, opt, R)) &&
       !(sphere_flows_coarse_to_fine(opt, P.faces.size()) && sphere_coarse_to_fine_start<EigenSolver>(P, p, opt, R))) {
      const Sphere_initial_outcome init = certified_sphere_initial_map<EigenSolver>(
        P, p, conformal, 3, true, false, opt.mode == Discrete_lie_flow_mode::CERTIFIED,
        opt.sphere.start == Discrete_lie_flow_sphere_start::MEAN_VALUE);
      R.initial_attempts = init.attempts;
      if(!init.certified) return report_failure(R, ERROR_INITIAL_MAP_FOLDED, init.message);
      R.puncture_face = init.puncture;
      R.initial_scale = init.scale;
    }
  }
  R.seconds_initial = std::chrono::duration<double>(Clock::now() - t0).count();
  R.face_density = face_densities(P);
  R.initial_metrics = spherical_distortion(P.xyz, p, P.faces, R.face_density);
  return OK;
}

/// Maps the closed genus-0 mesh `P` (`P.target` is filled from the areas and
/// `opt.face_density`) onto the unit sphere: `points` receives the unit
/// vectors, in vertex order, only on success. Fills `R`. In paper mode the
/// flowing triangulation is certified at every step and the caller's
/// triangles may fold under the result, which is reported, not refused.
/// `given`, when not null, is the caller's start (a point per vertex).
template <class EigenSolver>
Error_code map_to_sphere(Sphere_problem& P, std::vector<Vec3>& points, const Discrete_lie_flow_options& opt,
                         EigenSolver& solver, Discrete_lie_flow_report& R, const std::vector<Vec3>* given = nullptr)
{
  typedef std::chrono::steady_clock Clock;
  const Scoped_blas_threads threads(opt.solver_threads, P.xyz.size());
  R.vertices = P.xyz.size();
  R.faces = P.faces.size();
  std::vector<Vec3> p;
  const Error_code started = start_sphere<EigenSolver>(P, p, opt, R, given);
  if(started != OK) return started;

  const Clock::time_point t1 = Clock::now();
  Flow_outcome out;
  if(opt.mode == Discrete_lie_flow_mode::PAPER) {
    Sphere_paper_flow<EigenSolver> flow(P, p, opt, solver);
    out = run_flow(flow, opt);
    R.flowing_non_delaunay_edges = flow.non_delaunay_edges();
  } else if(opt.mode == Discrete_lie_flow_mode::LITERAL) {
    Sphere_literal_flow<EigenSolver> flow(P, p, opt, solver);
    out = run_flow(flow, opt);
    R.flowing_non_delaunay_edges = flow.non_delaunay_edges();
  } else {
    Sphere_certified_flow<EigenSolver> flow(P, p, opt, solver, Sphere_flow_settings());
    out = run_flow(flow, opt);
  }
  R.seconds_flow = std::chrono::duration<double>(Clock::now() - t1).count();
  report_area_elements(p, out, [](const std::vector<Vec3>& x, const std::vector<Face>& F, std::vector<double>& u) {
    signed_areas_sphere(x, F, u);
  }, R);
  report_outcome(out, R);
  R.final_metrics = spherical_distortion(P.xyz, p, P.faces, R.face_density);
  std::vector<double> flat;
  signed_areas_sphere(p, P.faces, flat);
  R.final_share_error = Density_levels(P.xyz, P.faces, P.target).error(flat);
  const Orientation_count caller = count_orientations_sphere(p, P.faces);
  R.caller_inverted_faces = caller.inverted + caller.degenerate;
  const Orientation_count flowing = count_orientations_sphere(p, out.domain_faces);
  R.flowing_inverted_faces = flowing.inverted + flowing.degenerate;
  Flow_goals goals = surface_goals(opt, R);
  if(opt.mode != Discrete_lie_flow_mode::LITERAL) {
    goals.mean_log = flat_mean_abs_log_ratio(p, P.faces, P.target);
    goals.mean_log_goal = opt.sphere.log_area_tolerance;
  }
  const Error_code verdict = report_verdict(out, R, goals);
  if(verdict == OK) points.swap(p);
  return verdict;
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
