// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// `dlf`: the command-line tool of the Discrete Lie Flow package. Dispatches
// to a subcommand and turns every error into one line on stderr and an exit
// code (see cli_error.h).

#include "arguments.h"
#include "cli_error.h"
#include "commands.h"

#include <exception>
#include <iostream>
#include <new>
#include <string>
#include <vector>

int main(int argc, char** argv)
{
  using namespace dlf_cli;
  const std::vector<std::string> args(argv + (argc > 1 ? 2 : 1), argv + argc);
  const std::string command = argc > 1 ? argv[1] : "";
  try {
    if(command == "disk") return disk_command(args);
    if(command == "atlas") return atlas_command(args);
    if(command == "score") return score_command(args);
    if(command == "sphere") return sphere_command(args);
    if(command == "info") return info_command(args);
    if(command == "volume") return volume_command(args);
    if(command == "tetrahedralize") return tetrahedralize_command(args);
    if(command == "--help" || command == "-h" || command == "help") {
      print_main_help(std::cout);
      return EXIT_OK;
    }
    if(command.empty()) throw Cli_error("missing command: disk, atlas, sphere, volume, tetrahedralize, score or info (see 'dlf --help')");
    throw Cli_error("unknown command '" + command + "': expected disk, atlas, sphere, volume, tetrahedralize, score or info (see 'dlf --help')");
  } catch(const Cli_error& e) {
    std::cerr << "dlf: error: " << e.what() << std::endl;
    return e.code();
  } catch(const std::bad_alloc&) {
    std::cerr << "dlf: error: out of memory" << std::endl;
  } catch(const std::exception& e) {
    // CGAL preconditions and the like: a bug, but still one line.
    std::cerr << "dlf: error: " << e.what() << std::endl;
  }
  return EXIT_BAD_INPUT;
}
