// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// `dlf sphere` without its files: its settings, and the run and JSON report
// of a mesh given as arrays, shared by the command line and the Python
// module.

#ifndef DLF_CLI_SPHERE_OUTCOME_H
#define DLF_CLI_SPHERE_OUTCOME_H

#include "arguments.h"
#include "cli_error.h"
#include "density_input.h"
#include "mesh_input.h"
#include "output_files.h"

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_options.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_report.h>
#include <CGAL/Surface_mesh_parameterization/Error_code.h>

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace dlf_cli {

struct Sphere_settings
{
  std::string input, output, report, svg, convergence_svg, histogram_svg, domain_mesh;
  std::string csv; ///< `--csv`: the report as one CSV row
  Svg_options svg_options;
  std::string mode = "certified";
  std::string start = "tutte";  ///< tutte | conformal | given (`--init-map`)
  std::string init_map_file;    ///< `--init-map`: the caller's start
  std::vector<Vec3> init_map;   ///< its point per input vertex, once read
  CGAL::Surface_mesh_parameterization::Discrete_lie_flow_options options;
  Verbosity verbosity = Verbosity::NORMAL;
  bool history_in_report = false;
  Disk_settings density; ///< only its density_file, regions and band are used
};

/// Parses the arguments after `dlf sphere`; false when `--help` was asked
/// (and printed); throws `Cli_error` on a usage error.
bool parse_sphere_arguments(const std::vector<std::string>& args, Sphere_settings& settings);

struct Sphere_outcome
{
  CGAL::Surface_mesh_parameterization::Error_code status = CGAL::Surface_mesh_parameterization::OK;
  CGAL::Surface_mesh_parameterization::Discrete_lie_flow_report report;
  std::vector<Vec3> points; ///< on the unit sphere, per input vertex; empty unless status is OK
  Density_setup density;
  double seconds = 0;       ///< the whole parameterize() call
  bool ok() const { return status == CGAL::Surface_mesh_parameterization::OK; }
  /// The library refused the input (not genus 0, degenerate, ...), as opposed to a flow error.
  bool input_error() const;
};

/// Builds the density (of `density_values`, one per face or per vertex, if
/// not empty; else of the settings' file or regions) and runs the flow.
/// Throws `Cli_error` on non-manifold input or a bad density.
Sphere_outcome compute_sphere(const Indexed_mesh& input, Sphere_settings& settings,
                              const std::vector<double>& density_values = std::vector<double>());

/// The JSON report of doc/design.md ("dlf sphere --report").
nlohmann::ordered_json sphere_report(const Sphere_settings& settings, const Indexed_mesh& input,
                                     const Sphere_outcome& outcome, const Command_seconds& io = Command_seconds());

/// The error of a failed run: its message and exit code.
Cli_error sphere_failure(const Sphere_settings& settings, const Sphere_outcome& outcome);

} // namespace dlf_cli

#endif
