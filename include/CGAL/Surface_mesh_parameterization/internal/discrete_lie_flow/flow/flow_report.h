// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// From a flow's outcome to the public report, alike for every surface wing:
// per-face densities, area elements, counts, the verdict and its message.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_FLOW_REPORT_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_FLOW_REPORT_H

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_options.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_report.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/area_elements.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/flow/flow_driver.h>

#include <iomanip>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// Per face: the density ρ_f = target_f / area_M(f) of a problem.
template <class Problem>
std::vector<double> face_densities(const Problem& P)
{
  std::vector<double> rho(P.faces.size());
  for(std::size_t f = 0; f < P.faces.size(); ++f) {
    const Face& t = P.faces[f];
    rho[f] = P.target[f] / triangle_area_3(P.xyz[std::size_t(t[0])], P.xyz[std::size_t(t[1])], P.xyz[std::size_t(t[2])]);
  }
  return rho;
}

/// The area elements of the final triangulation (the outcome's, with the
/// targets the flow used on it) into the report, the targets scaled to the
/// domain's total area.
template <class Point, class Areas>
void report_area_elements(const std::vector<Point>& p, const Flow_outcome& out, const Areas& signed_areas,
                          Discrete_lie_flow_report& R)
{
  std::vector<double> u;
  signed_areas(p, out.domain_faces, u);
  lump_on_vertices(p.size(), out.domain_faces, u, R.domain_area);
  lump_on_vertices(p.size(), out.domain_faces, out.domain_target, R.target_area);
  double so = 0, st = 0;
  for(std::size_t i = 0; i < p.size(); ++i) { so += R.domain_area[i]; st += R.target_area[i]; }
  for(double& a : R.target_area) a *= so / st;
  R.domain_faces.assign(out.domain_faces.begin(), out.domain_faces.end());
}

/// What every flow reports the same way.
inline void report_outcome(Flow_outcome& out, Discrete_lie_flow_report& R)
{
  R.stop_reason = out.stop_reason;
  R.iterations = out.iterations;
  R.initial_d_area = out.initial_d_area;
  R.final_d_area = out.final_d_area;
  R.final_residual = out.final_residual;
  R.flips = out.flips;
  R.rejected_by_exact_check = out.rejected_by_exact_check;
  R.collapse_faces = out.collapse_faces;
  R.factorizations = out.factorizations;
  R.symbolic_analyses = out.symbolic_analyses;
  R.seconds_assembly = out.seconds_assembly;
  R.seconds_solve = out.seconds_solve;
  R.seconds_step = out.seconds_step;
  R.history = std::move(out.history);
}

/// Sets the report's status and message; returns the code.
inline Error_code report_failure(Discrete_lie_flow_report& R, int code, const std::string& message)
{
  R.status = Error_code(code);
  R.message = message.empty() ? std::string(discrete_lie_flow_error_message(code)) : message;
  return Error_code(code);
}

/// The goals a run is judged by and the values it reached: a run that did
/// not converge names each goal it missed with its value.
struct Flow_goals
{
  double d_area = 0, d_area_goal = 0;       ///< D_area ≤ 2 + tolerance
  double share_error = 0, share_goal = -1;  ///< with a density (goal ≥ 0) only
  double mean_log = 0, mean_log_goal = -1;  ///< the sphere's mean |log area ratio| (goal > 0) only
};

/// The goals every surface flow is judged by, from the options and the
/// filled report: D_area, and the share error of a density in the certified
/// mode (the paper modes stop on D_area alone).
inline Flow_goals surface_goals(const Discrete_lie_flow_options& opt, const Discrete_lie_flow_report& R)
{
  Flow_goals goals;
  goals.d_area = R.final_d_area;
  goals.d_area_goal = 2 + opt.tolerance;
  goals.share_error = R.final_share_error;
  if(opt.mode == Discrete_lie_flow_mode::CERTIFIED && opt.certified.share_tolerance > 0 && R.final_share_error > 0)
    goals.share_goal = opt.certified.share_tolerance;
  return goals;
}

/// "d_area 2.03 > 2.01; ..." for each goal of `g` not met, empty if none.
inline std::string missed_goals(const Flow_goals& g)
{
  std::ostringstream s;
  s << std::setprecision(6);
  const char* sep = "";
  if(!(g.d_area <= g.d_area_goal)) { s << "d_area " << g.d_area << " > " << g.d_area_goal; sep = "; "; }
  if(g.share_goal >= 0 && !(g.share_error <= g.share_goal)) {
    s << sep << "share error " << g.share_error << " > " << g.share_goal; sep = "; ";
  }
  if(g.mean_log_goal > 0 && !(g.mean_log <= g.mean_log_goal))
    s << sep << "mean |log area ratio| " << g.mean_log << " > " << g.mean_log_goal;
  return s.str();
}

/// The status and message of a run that produced a map: OK, converged or
/// not. A run that stopped short says where, which goals it missed (with
/// their values), and whether the caller's triangles are fold-free (in the
/// paper and literal modes only the flowing triangulation is certified).
inline Error_code report_verdict(const Flow_outcome& out, Discrete_lie_flow_report& R, const Flow_goals& goals)
{
  if(R.flowing_inverted_faces != 0)
    return report_failure(R, ERROR_NO_1_TO_1_MAPPING, "the flow produced " + std::to_string(R.flowing_inverted_faces) +
                                                      " non-positive faces of its triangulation");
  if(out.iterations == 0 && out.stop_reason == Discrete_lie_flow_stop_reason::STALLED)
    return report_failure(R, ERROR_FLOW_STALLED, out.solver_failed ? "the linear solver failed on the initial map"
                                                                   : "no step improves the initial map");
  R.status = OK;
  const std::string folds = R.caller_inverted_faces == 0
    ? std::string("fold-free on the input's triangles")
    : std::to_string(R.caller_inverted_faces) + " of the input's triangles inverted or degenerate (only the flowing "
      "triangulation is certified in this mode)";
  if(out.stop_reason == Discrete_lie_flow_stop_reason::CONVERGED) {
    R.message = R.caller_inverted_faces == 0 ? std::string("Success") : "converged; " + folds;
  } else if(out.stop_reason == Discrete_lie_flow_stop_reason::COLLAPSED) {
    // The literal mode's documented failure (the paper's "c").
    std::ostringstream s;
    s << std::setprecision(6) << "collapsed: the step of iteration " << out.iterations + 1 << " "
      << (out.collapse_faces > 0 ? "folds or degenerates " + std::to_string(out.collapse_faces) + " faces of the flowing mesh"
                                 : std::string("no longer moves the mesh (or runs a border vertex off its side)"))
      << "; the last fold-free iterate is returned, d_area " << R.final_d_area << ", " << folds;
    R.message = s.str();
  } else {
    const std::string missed = missed_goals(goals);
    std::ostringstream s;
    s << std::setprecision(6) << "not converged: stopped (" << discrete_lie_flow_stop_reason_name(out.stop_reason)
      << ") after " << out.iterations << " iterations short of "
      << (missed.empty() ? std::string("the flow's own stop rule") : missed) << "; the map is " << folds
      << ", d_area " << R.final_d_area;
    R.message = s.str();
  }
  return OK;
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
