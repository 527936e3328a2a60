// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The atlas on a list of meshes, one row each: components, closed ones, genus, charts,
// splits, seam length (relative to √area), packing efficiency, global
// D_area, inverted and degenerate uv triangles, overlapping chart pairs,
// unconverged charts, seconds, triangles made charts of their own. Polygons
// are triangulated first.
//
//   atlas_benchmark [--border circle|square] [--tips K] [--gutter G] [--split-depth D] [--cap N] [--tolerance T] [--no-stretch] [--charts] MESH...
//
// --charts: after each row, one line per chart that did not converge (faces,
// holes, split depth, iterations, D_area, triangles with three border corners).

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_atlas_3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>

typedef CGAL::Simple_cartesian<double> K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace SMP = CGAL::Surface_mesh_parameterization;

int main(int argc, char** argv)
{
  SMP::Discrete_lie_flow_atlas_options opt;
  bool chart_lines = false;
  std::printf("%-28s %7s %4s %4s %4s %6s %6s %7s %6s %8s %4s %4s %4s %4s %8s %4s %7s %5s %6s\n", "mesh", "faces", "cc", "cl", "g", "charts",
              "splits", "seam/√A", "pack", "D_area", "inv", "deg", "ovl", "unc", "seconds", "tbc", "stretch", "maxit", "peeled");
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--border" && i + 1 < argc) {
      opt.border = std::string(argv[++i]) == "circle" ? SMP::Discrete_lie_flow_border::CIRCLE : SMP::Discrete_lie_flow_border::SQUARE;
      continue;
    }
    if(a == "--tips" && i + 1 < argc) { opt.tips = std::size_t(std::atoi(argv[++i])); continue; }
    if(a == "--gutter" && i + 1 < argc) { opt.gutter = std::atof(argv[++i]); continue; }
    if(a == "--split-depth" && i + 1 < argc) { opt.max_split_depth = std::size_t(std::atoi(argv[++i])); continue; }
    if(a == "--tolerance" && i + 1 < argc) { opt.flow.tolerance = std::atof(argv[++i]); continue; }
    if(a == "--cap" && i + 1 < argc) { opt.flow.max_iterations = std::size_t(std::atoi(argv[++i])); continue; }
    if(a == "--no-stretch") { opt.stretch_to_fill = false; continue; }
    if(a == "--charts") { chart_lines = true; continue; }
    Mesh mesh;
    if(!CGAL::Polygon_mesh_processing::IO::read_polygon_mesh(a, mesh)) { std::printf("%s: cannot read\n", a.c_str()); continue; }
    if(!CGAL::is_triangle_mesh(mesh)) CGAL::Polygon_mesh_processing::triangulate_faces(mesh);
    auto uv = mesh.add_property_map<Mesh::Halfedge_index, K::Point_2>("h:uv").first;
    const SMP::Discrete_lie_flow_atlas_report r = SMP::discrete_lie_flow_atlas(mesh, uv, opt);
    std::string name = a.substr(a.find_last_of('/') + 1);
    std::size_t max_iterations = 0; // of the converged charts: what the splitting rule's cap leaves room for
    for(const auto& c : r.chart_reports)
      if(c.stop_reason == SMP::Discrete_lie_flow_stop_reason::CONVERGED) max_iterations = std::max(max_iterations, c.iterations);
    if(r.code != SMP::OK) { std::printf("%-28s error: %s\n", name.c_str(), r.message.c_str()); continue; }
    std::printf("%-28s %7zu %4zu %4zu %4zu %6zu %6zu %7.3f %6.3f %8.4f %4zu %4zu %4zu %4zu %8.2f %4zu %7.2f %5zu %6zu\n", name.c_str(),
                std::size_t(num_faces(mesh)), r.components, r.closed_components, r.max_genus, r.charts, r.splits,
                r.seam_length / std::sqrt(r.surface_area), r.packing_efficiency, r.metrics.d_area, r.inverted_faces,
                r.degenerate_faces, r.overlapping_chart_pairs, r.unconverged_charts, r.seconds, r.three_border_corner_faces, r.max_chart_stretch, max_iterations, r.peeled_faces);
    if(chart_lines)
      for(const auto& c : r.chart_reports)
        if(c.stop_reason != SMP::Discrete_lie_flow_stop_reason::CONVERGED)
          std::printf("    unconverged chart: %zu faces, %zu holes, depth %zu, %zu iterations, D_area %.4f, %s, %zu three-border-corner\n",
                      c.faces, c.holes, c.split_depth, c.iterations, c.d_area, SMP::discrete_lie_flow_stop_reason_name(c.stop_reason),
                      c.three_border_corner_faces);
    std::fflush(stdout);
  }
  return 0;
}
