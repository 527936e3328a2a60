// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// `dlf score`: the metrics of an existing map, e.g. to compare with other tools.
// A map with per-corner uv (an atlas: `f v/vt`) is also scored as an atlas:
// charts, seam, packing efficiency, folds and overlapping uv triangles, all
// exact (atlas/atlas_score.h), whoever made it.

#include "arguments.h"
#include "cli_error.h"
#include "commands.h"
#include "metrics.h"
#include "obj_io.h"
#include "output_files.h"

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_distortion.h>

#include <iomanip>
#include <cmath>
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
  namespace SMP = CGAL::Surface_mesh_parameterization;
  SMP::Discrete_lie_flow_atlas_score atlas;
  if(map.per_corner) atlas = SMP::discrete_lie_flow_atlas_score(mesh.xyz, mesh.faces, map.uv, map.surface.faces);

  if(!s.report.empty() || !s.csv.empty()) {
    nlohmann::ordered_json report = { { "status", "ok" }, { "mesh", s.mesh }, { "parameterization", s.parameterization },
                                       { "vertices", mesh.xyz.size() }, { "faces", mesh.faces.size() },
                                       { "uv", map.per_corner ? "per_corner" : "per_vertex" },
                                       { "uv_vertices", map.uv.size() }, { "metrics", metrics_to_json(m) } };
    if(map.per_corner)
      report["atlas"] = { { "charts", atlas.charts }, { "seam_length", atlas.seam_length },
                          { "seam_length_over_sqrt_area", atlas.seam_length / std::sqrt(atlas.surface_area) },
                          { "packing_efficiency", atlas.packing_efficiency },
                          { "uv_box", { atlas.bounding_width, atlas.bounding_height } }, { "d_area", atlas.metrics.d_area },
                          { "inverted_faces", atlas.inverted_faces }, { "degenerate_faces", atlas.degenerate_faces },
                          { "mirrored_charts", atlas.mirrored_charts },
                          { "overlapping_face_pairs", atlas.overlapping_face_pairs },
                          { "overlapping_pairs_in_a_chart", atlas.overlapping_pairs_in_a_chart } };
    write_report_files(outputs, s.report, s.csv, report);
  }
  outputs.commit();
  if(s.verbosity != Verbosity::QUIET) {
    std::cout << std::setprecision(10) << "dlf score " << s.mesh << " " << s.parameterization << ": "
              << mesh.xyz.size() << " vertices, " << mesh.faces.size() << " faces";
    if(map.per_corner) std::cout << ", per-corner uv (" << map.uv.size() << " vt: measured on the mesh cut open)";
    std::cout << "\n";
    print_metrics(std::cout, m, "  ");
    if(map.per_corner)
      std::cout << "  atlas: " << atlas.charts << " charts, seam length " << atlas.seam_length / std::sqrt(atlas.surface_area)
                << " x sqrt(area), packing efficiency " << atlas.packing_efficiency << " (uv area / its bounding box "
                << atlas.bounding_width << " x " << atlas.bounding_height << "), D_area " << atlas.metrics.d_area << ", "
                << atlas.inverted_faces << " inverted (against their chart) and " << atlas.degenerate_faces
                << " degenerate uv triangles, " << atlas.mirrored_charts << " mirrored charts, "
                << atlas.overlapping_face_pairs << " overlapping uv triangle pairs (" << atlas.overlapping_pairs_in_a_chart
                << " within a chart)\n";
    for(const std::string& w : outputs.committed()) std::cout << "  wrote " << w << "\n";
  }
  return EXIT_OK;
}

} // namespace dlf_cli
