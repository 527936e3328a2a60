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

/// The verdict of a run whose report is filled: a triangulation the flow
/// left non-positive (cannot happen: every accepted step and every flip is
/// certified), a flow that could not improve its start, or success.
inline Error_code report_verdict(const Flow_outcome& out, Discrete_lie_flow_report& R)
{
  if(R.flowing_inverted_faces != 0)
    return report_failure(R, ERROR_NO_1_TO_1_MAPPING, "the flow produced " + std::to_string(R.flowing_inverted_faces) +
                                                      " non-positive faces of its triangulation");
  if(out.iterations == 0 && out.stop_reason == Discrete_lie_flow_stop_reason::STALLED)
    return report_failure(R, ERROR_FLOW_STALLED, out.solver_failed ? "the linear solver failed on the initial map"
                                                                   : "no step improves the initial map");
  R.status = OK;
  if(out.stop_reason == Discrete_lie_flow_stop_reason::CONVERGED) {
    R.message = "Success";
  } else if(out.stop_reason == Discrete_lie_flow_stop_reason::COLLAPSED) {
    // The literal mode's documented failure (the paper's "c").
    std::ostringstream s;
    s << std::setprecision(6) << "collapsed: the step of iteration " << out.iterations + 1 << " "
      << (out.collapse_faces > 0 ? "folds or degenerates " + std::to_string(out.collapse_faces) + " faces of the flowing mesh"
                                 : std::string("no longer moves the mesh (or runs a border vertex off its side)"))
      << "; the last fold-free iterate is returned, d_area " << out.final_d_area;
    R.message = s.str();
  } else {
    std::ostringstream s;
    s << std::setprecision(6) << "not converged: a valid, fold-free map, stopped (" << discrete_lie_flow_stop_reason_name(out.stop_reason)
      << ") after " << out.iterations << " iterations at d_area " << out.final_d_area;
    R.message = s.str();
  }
  return OK;
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
