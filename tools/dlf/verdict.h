// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The tool's verdict on a run whose parameterizer returned OK: converged, or
// a valid, fold-free map short of its targets, which is not "Success" — the
// report's status, the summary, a warning and the exit code (3) say so; and
// the report's first fields, which `dlf disk` and `dlf sphere` share.

#ifndef DLF_CLI_VERDICT_H
#define DLF_CLI_VERDICT_H

#include "cli_error.h"
#include "mesh_input.h"
#include "output_files.h"

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_options.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_report.h>

#include <nlohmann/json.hpp>

#include <iostream>
#include <string>

namespace dlf_cli {

/// The report's "status": the library's status name, except "not_converged"
/// for an OK run that stopped short of its targets.
inline std::string run_status(CGAL::Surface_mesh_parameterization::Error_code code,
                              const CGAL::Surface_mesh_parameterization::Discrete_lie_flow_report& R)
{
  namespace SMP = CGAL::Surface_mesh_parameterization;
  if(code == SMP::OK && !R.converged()) return "not_converged";
  return SMP::discrete_lie_flow_error_name(code);
}

/// The first fields of the reports of `dlf disk` and `dlf sphere`, in their
/// order: status, message, input, vertices, faces, iterations, stop_reason,
/// seconds (`total`: the parameterizer's whole call).
inline nlohmann::ordered_json run_report_head(CGAL::Surface_mesh_parameterization::Error_code code,
                                              const CGAL::Surface_mesh_parameterization::Discrete_lie_flow_report& R,
                                              const std::string& input_name, const Indexed_mesh& input,
                                              const Command_seconds& io, double total)
{
  nlohmann::ordered_json j;
  j["status"] = run_status(code, R);
  j["message"] = R.message;
  j["input"] = input_name;
  j["vertices"] = input.xyz.size();
  j["faces"] = input.faces.size();
  j["iterations"] = R.iterations;
  j["stop_reason"] = CGAL::Surface_mesh_parameterization::discrete_lie_flow_stop_reason_name(R.stop_reason);
  j["seconds"] = seconds_json(io, R.seconds_initial, R.seconds_flow, total);
  return j;
}

/// What may get a run that did not converge to its targets, by why it stopped.
inline std::string not_converged_hint(CGAL::Surface_mesh_parameterization::Discrete_lie_flow_stop_reason r, bool disk)
{
  typedef CGAL::Surface_mesh_parameterization::Discrete_lie_flow_stop_reason Stop;
  if(r == Stop::INTERRUPTED) return "the run was interrupted";
  if(r == Stop::COLLAPSED)
    return "the literal Algorithm 1 collapsed, its documented failure (doc/paper_errata.md); a smaller --mu "
           "or --fixed-step may go further, --mode paper or certified avoid it";
  std::string hint = r == Stop::ITERATION_CAP ? "it was still improving: a larger --max-iterations may reach the targets"
                                              : "more iterations will not help";
  if(disk)
    hint += "; long thin parts (slits, corridors, protrusions) ask a circle for the most deformation: "
            "--border free --init arap keeps the input's own boundary shape, --border square may also do better";
  else
    hint += "; splitting the largest or thinnest triangles of the input may help";
  return hint;
}

/// The exit code of an OK run: 0, or EXIT_NOT_CONVERGED after a warning on
/// stderr that says where the flow stopped and what to try.
inline int exit_code_of_ok_run(const CGAL::Surface_mesh_parameterization::Discrete_lie_flow_report& R, bool disk)
{
  if(R.converged()) return EXIT_OK;
  // The message names the goals that were missed and their values.
  std::cerr << "dlf: warning: " << R.message << "; " << not_converged_hint(R.stop_reason, disk) << "\n";
  return EXIT_NOT_CONVERGED;
}

} // namespace dlf_cli

#endif
