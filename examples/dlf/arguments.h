// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Command lines of `dlf disk` and `dlf score` (Boost.Program_options), and
// the help texts.

#ifndef DLF_CLI_ARGUMENTS_H
#define DLF_CLI_ARGUMENTS_H

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_options.h>

#include <ostream>
#include <string>
#include <vector>

namespace dlf_cli {

enum class Verbosity { QUIET, NORMAL, VERBOSE };

struct Disk_settings
{
  std::string input;
  std::string output, report, domain_mesh, svg; ///< empty: not written
  std::string mode = "certified";               ///< certified | paper
  std::string init = "tutte";                   ///< tutte | mvc | dcp | lscm | arap
  std::string border;                           ///< circle | square | free (resolved from init if not given)
  CGAL::Surface_mesh_parameterization::Discrete_lie_flow_options options;
  Verbosity verbosity = Verbosity::NORMAL;
};

struct Score_settings
{
  std::string mesh, parameterization, report;
  Verbosity verbosity = Verbosity::NORMAL;
};

/// Parse the arguments that follow `dlf disk` / `dlf score`. Return false
/// when `--help` was asked (and printed); throw `Cli_error` on a usage error.
bool parse_disk_arguments(const std::vector<std::string>& args, Disk_settings& settings);
bool parse_score_arguments(const std::vector<std::string>& args, Score_settings& settings);

void print_main_help(std::ostream& out);

/// True for the fixed-border initial maps (convex border: circle or square).
inline bool has_fixed_border(const std::string& init) { return init == "tutte" || init == "mvc" || init == "dcp"; }

} // namespace dlf_cli

#endif
