// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// `dlf score`: the metrics of an existing map, e.g. to compare with other tools.

#include "arguments.h"
#include "cli_error.h"
#include "commands.h"
#include "metrics.h"
#include "obj_io.h"
#include "output_files.h"

#include <iomanip>
#include <iostream>

namespace dlf_cli {

int score_command(const std::vector<std::string>& args)
{
  Score_settings s;
  if(!parse_score_arguments(args, s)) return EXIT_OK;
  Output_files outputs;
  if(!s.report.empty()) outputs.declare(s.report, "--report");
  if(!s.csv.empty()) outputs.declare(s.csv, "--csv");

  const Indexed_mesh mesh = read_triangle_mesh(s.mesh);
  // Per-corner uv (a map with seams) is measured on the mesh cut open.
  const Obj_map map = read_map_obj(s.parameterization, mesh);
  const Metrics m = compute_metrics(map.surface, map.uv);

  if(!s.report.empty() || !s.csv.empty()) {
    nlohmann::ordered_json report = { { "status", "ok" }, { "mesh", s.mesh }, { "parameterization", s.parameterization },
                                       { "vertices", mesh.xyz.size() }, { "faces", mesh.faces.size() },
                                       { "uv", map.per_corner ? "per_corner" : "per_vertex" },
                                       { "uv_vertices", map.uv.size() }, { "metrics", metrics_to_json(m) } };
    if(!s.report.empty()) outputs.write(s.report, [&](std::ostream& o) { o << report.dump(2) << '\n'; });
    if(!s.csv.empty()) outputs.write(s.csv, [&](std::ostream& o) { write_csv_report(o, report); });
  }
  outputs.commit();
  if(s.verbosity != Verbosity::QUIET) {
    std::cout << std::setprecision(10) << "dlf score " << s.mesh << " " << s.parameterization << ": "
              << mesh.xyz.size() << " vertices, " << mesh.faces.size() << " faces";
    if(map.per_corner) std::cout << ", per-corner uv (" << map.uv.size() << " vt: measured on the mesh cut open)";
    std::cout << "\n";
    print_metrics(std::cout, m, "  ");
    for(const std::string& w : outputs.committed()) std::cout << "  wrote " << w << "\n";
  }
  return EXIT_OK;
}

} // namespace dlf_cli
