// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The C++ peer of a Python call discrete_lie_flow.disk(V, F): the same
// work on index arrays already in memory (the input checks, the flow, the
// report), through the code the Python module calls, timed in-process.
// python_overhead.py runs it beside the Python call.
//   dlf_call_timing MESH.off [RUNS]   prints one line per run: seconds

#include "disk_outcome.h"
#include "mesh_input.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

int main(int argc, char** argv)
{
  if(argc < 2) {
    std::fprintf(stderr, "usage: dlf_call_timing MESH [RUNS]\n");
    return 1;
  }
  const int runs = argc > 2 ? std::atoi(argv[2]) : 7;
  const dlf_cli::Indexed_mesh mesh = dlf_cli::read_triangle_mesh(argv[1]);
  // The arrays a caller holds: positions and index triples.
  std::vector<dlf_cli::Vec3> xyz = mesh.xyz;
  std::vector<std::vector<std::size_t> > polygons;
  for(const dlf_cli::Triangle& t : mesh.faces) polygons.push_back({ std::size_t(t[0]), std::size_t(t[1]), std::size_t(t[2]) });
  for(int k = 0; k < runs; ++k) {
    const auto t0 = std::chrono::steady_clock::now();
    const dlf_cli::Indexed_mesh input = dlf_cli::checked_triangle_mesh(xyz, polygons, "mesh");
    dlf_cli::Disk_settings s;
    dlf_cli::parse_disk_arguments({ "mesh", "--quiet" }, s);
    const dlf_cli::Disk_outcome o = dlf_cli::compute_disk(input, s);
    const std::string report = dlf_cli::disk_report(s, input, o).dump();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if(!o.ok) return 2;
    std::printf("%.6f %.6f %zu\n", seconds, o.run.seconds, report.size());
  }
  return 0;
}
