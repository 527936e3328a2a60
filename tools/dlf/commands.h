// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The subcommands of `dlf`. Each takes the arguments after its name, returns
// the exit code of a success and throws `Cli_error` otherwise.

#ifndef DLF_CLI_COMMANDS_H
#define DLF_CLI_COMMANDS_H

#include <string>
#include <vector>

namespace dlf_cli {

int disk_command(const std::vector<std::string>& args);
int atlas_command(const std::vector<std::string>& args);
int score_command(const std::vector<std::string>& args);
int sphere_command(const std::vector<std::string>& args);
int info_command(const std::vector<std::string>& args);
int volume_command(const std::vector<std::string>& args);
int tetrahedralize_command(const std::vector<std::string>& args);

} // namespace dlf_cli

#endif
