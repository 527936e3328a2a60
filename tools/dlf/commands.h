// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The subcommands of `dlf`. Each takes the arguments after its name, returns
// the exit code of a success and throws `Cli_error` otherwise.

#ifndef DLF_CLI_COMMANDS_H
#define DLF_CLI_COMMANDS_H

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_atlas_options.h>

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace dlf_cli {

int disk_command(const std::vector<std::string>& args);
int atlas_command(const std::vector<std::string>& args);
/// The atlas report's keys of `dlf atlas --report` (status, charts, seams,
/// packing, checks, seconds, chart_list); the Python module's too.
nlohmann::ordered_json atlas_report_json(const CGAL::Surface_mesh_parameterization::Discrete_lie_flow_atlas_report& r);
int score_command(const std::vector<std::string>& args);
int sphere_command(const std::vector<std::string>& args);
int info_command(const std::vector<std::string>& args);
int volume_command(const std::vector<std::string>& args);
int tetrahedralize_command(const std::vector<std::string>& args);

} // namespace dlf_cli

#endif
