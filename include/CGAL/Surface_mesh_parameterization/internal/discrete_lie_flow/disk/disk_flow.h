// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The planar flow on index data, from an initial map to a filled report:
// orientation and border checks, the boundary curve, the mode's policy run
// by the flow driver, and the report (metrics, area elements, counts).

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_DISK_FLOW_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_DISK_FLOW_H

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_options.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_report.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/area_elements.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/disk/border_spacing.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/disk/boundary_curve.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/disk/coarse_to_fine.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/certification.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/density_levels.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/disk/disk_holes.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/disk/disk_problem.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/distortion.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/flow/flow_driver.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/disk/planar_literal_flow.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/flow/flow_report.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/disk/planar_certified_flow.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/disk/planar_paper_flow.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/solver_threads.h>

#include <algorithm>
#include <chrono>
#include <iomanip>
#include <memory>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// Orients `P` as the initial map `uv`: faces and border loop counter-clockwise
/// in the domain. Fails, naming the first bad face, unless every face then
/// has a positive area. `loop` receives the border positions in order.
inline Error_code orient_to_initial_map(Disk_problem& P, const std::vector<Vec2>& uv, std::vector<Vec2>& loop,
                                        Discrete_lie_flow_report& R)
{
  // Some border parameterizers run clockwise: the flow then works on the
  // faces with their index order reversed.
  Orientation_count oc = count_orientations_2(uv, P.faces);
  if(oc.inverted * 2 > P.faces.size()) {
    for(Face& f : P.faces) std::swap(f[1], f[2]);
    oc = count_orientations_2(uv, P.faces);
  }
  if(!oc.all_positive()) {
    const Face& f = P.faces[std::size_t(oc.first_bad)];
    std::ostringstream s;
    s << "the initial map has " << oc.inverted << " inverted and " << oc.degenerate
      << " degenerate triangles; first: face " << oc.first_bad << " (vertices " << f[0] << ", " << f[1] << ", " << f[2] << ")";
    return report_failure(R, ERROR_INITIAL_MAP_FOLDED, s.str());
  }
  loop.resize(P.boundary.size());
  for(std::size_t k = 0; k < loop.size(); ++k) loop[k] = uv[std::size_t(P.boundary[k])];
  double twice = 0;
  for(std::size_t k = 0; k < loop.size(); ++k) {
    const Vec2 &a = loop[k], &b = loop[(k + 1) % loop.size()];
    twice += a[0] * b[1] - a[1] * b[0];
  }
  if(twice < 0) {
    std::reverse(P.boundary.begin(), P.boundary.end());
    std::reverse(loop.begin(), loop.end());
  }
  return OK;
}

/// The planar flow on index data: `uv` is an initial map of `P` with all
/// faces positive or all negative (modified in place on success; the map
/// keeps the initial orientation). Fills `R`. `start`, when the library
/// computed the start itself, is the factorised Tutte system that gave it
/// (on `solver`): the border spacing by area then solves with its factor.
template <class EigenSolver>
Error_code flow_disk(Disk_problem& P, std::vector<Vec2>& uv, const Discrete_lie_flow_options& opt,
                     EigenSolver& solver, Discrete_lie_flow_report& R,
                     Tutte_interior_system<EigenSolver>* start = nullptr)
{
  typedef std::chrono::steady_clock Clock;
  const Scoped_blas_threads threads(opt.solver_threads, uv.size());
  // With holes (P.fill_faces > 0) the flow runs on the filled disk; the
  // report speaks of the caller's vertices and faces only.
  const bool holes = P.fill_faces > 0;
  R.vertices = P.caller_vertices();
  R.faces = P.caller_faces();
  R.holes = P.holes;
  if(holes && opt.mode != Discrete_lie_flow_mode::CERTIFIED)
    return report_failure(R, ERROR_NO_TOPOLOGICAL_DISC, std::string("the ") + discrete_lie_flow_mode_name(opt.mode) +
                          " mode takes disks only (the mesh has " +
                          std::to_string(P.holes) + (P.holes == 1 ? " hole" : " holes") + "); the certified mode fills them");
  if(opt.disk.border == Discrete_lie_flow_border::FLOATING && opt.mode != Discrete_lie_flow_mode::CERTIFIED)
    return report_failure(R, ERROR_WRONG_PARAMETER, std::string("a floating border takes the certified mode, not the ") +
                          discrete_lie_flow_mode_name(opt.mode));
  std::vector<Vec2> loop;
  const Error_code oriented = orient_to_initial_map(P, uv, loop, R);
  if(oriented != OK) return oriented;
  Boundary_curve curve(loop, opt.disk.border);
  R.border = curve.kind();
  const std::vector<Face> caller_faces = caller_part(P.faces, P);
  R.face_density = caller_part(face_densities(P), P);
  R.initial_metrics = planar_distortion(P.xyz, uv, caller_faces, R.face_density);

  const Clock::time_point t0 = Clock::now();
  Flow_outcome out;
  if(opt.mode == Discrete_lie_flow_mode::PAPER) {
    Planar_paper_flow<EigenSolver> flow(P, uv, curve, opt, solver, Paper_flow_settings());
    out = run_flow(flow, opt);
  } else if(opt.mode == Discrete_lie_flow_mode::LITERAL) {
    Planar_literal_flow<EigenSolver> flow(P, uv, curve, opt, solver);
    out = run_flow(flow, opt);
  } else {
    // On the circle, when Tutte's map spaced by area (border_spacing.h) has
    // less than half the caller's E, the border spacing by length was far
    // off (a long seam, a thin disk): the flow starts from that map, and its
    // metric takes the exact border block, for the border has far to slide.
    // A fixed step asks for the flow from the caller's map as it is.
    std::vector<double> u0;
    signed_areas_2(uv, P.faces, u0);
    const double E0 = Area_barrier_energy(P.target).value(u0);
    // Tutte's system there is factorised by the flow's solver (once, by the
    // start when the library computed it): its analysis serves the flow's
    // interior stiffness (the same pattern).
    Planar_flow_settings settings;
    std::unique_ptr<Tutte_interior_system<EigenSolver> > own;
    Tutte_interior_system<EigenSolver>* tutte = start;
    // A large disk flows coarse to fine (coarse_to_fine.h), whose coarsest
    // level is spaced by area instead: its Tutte system is a small one.
    const bool coarse_to_fine = flows_coarse_to_fine(opt, P.faces.size());
    // The levels do not solve with the start's factor: its values go while
    // they run (a refused hierarchy refactorizes it, below).
    if(coarse_to_fine && tutte != nullptr) tutte->release_factor();
    const bool levels = coarse_to_fine && coarse_to_fine_start<EigenSolver>(P, uv, curve, opt, settings, R);
    if(!levels && opt.fixed_step == 0 && curve.kind() == Discrete_lie_flow_border::CIRCLE) {
      if(tutte == nullptr) {
        own.reset(new Tutte_interior_system<EigenSolver>(P, uv.size(), solver));
        tutte = own.get();
      }
      settings.coupled_metric = respace_border_by_area<EigenSolver>(P, uv, curve, 0.5, *tutte);
    }
    Planar_certified_flow<EigenSolver> flow(P, uv, curve, opt, solver, settings,
                                            tutte != nullptr && tutte->solver().analyses() > 0 ? &tutte->solver() : nullptr);
    out = run_flow(flow, opt);
    out.initial_d_area = E0; // the caller's map
  }
  R.seconds_flow = std::chrono::duration<double>(Clock::now() - t0).count();
  // The fill counts here: a non-positive fill face would let a hole overlap the caller's faces.
  const Orientation_count dc = count_orientations_2(uv, out.domain_faces);
  R.flowing_inverted_faces = dc.inverted + dc.degenerate;
  const std::vector<Vec2> caller_uv(uv.begin(), uv.begin() + std::ptrdiff_t(P.caller_vertices()));
  if(holes) {
    out.domain_faces = caller_part(out.domain_faces, P);
    out.domain_target = caller_part(out.domain_target, P);
  }
  report_area_elements(caller_uv, out, [](const std::vector<Vec2>& x, const std::vector<Face>& F, std::vector<double>& u) {
    signed_areas_2(x, F, u);
  }, R);
  report_outcome(out, R);
  std::vector<double> caller_areas;
  signed_areas_2(uv, caller_faces, caller_areas);
  R.final_share_error = Density_levels(P.xyz, caller_faces, caller_part(P.target, P)).error(caller_areas);
  R.final_metrics = planar_distortion(P.xyz, uv, caller_faces, R.face_density);
  if(holes) { // the flow's D_area is the filled disk's
    R.initial_d_area = R.initial_metrics.d_area;
    R.final_d_area = R.final_metrics.d_area;
  }
  const Orientation_count cc = count_orientations_2(uv, caller_faces);
  R.caller_inverted_faces = cc.inverted + cc.degenerate;
  return report_verdict(out, R, surface_goals(opt, R));
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
