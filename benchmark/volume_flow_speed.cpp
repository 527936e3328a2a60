// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The volumetric flow alone, from a saved certified start: the start of a
// million tetrahedra costs over a minute (border map, Tutte, untangling),
// which measurements of the flow need not repeat. Make the start once with
//
//   dlf volume IN.mesh --max-iterations 0 -o START.mesh
//
// then time the flow with the parameterizer's defaults (or the options
// below: --coarse 0 the 3x3 blocks alone, --no-forcing a fixed conjugate-
// gradient tolerance) as often as needed:
//
//   volume_flow_speed IN.mesh START.mesh [--threads N] [--cg-iterations N]
//                     [--max-iterations N] [--no-forcing] [--coarse K] [-v]
//
// Prints one line per iteration with -v, then the outcome: iterations,
// conjugate-gradient steps, D_vol, inverted tets (exact), seconds of the
// flow (wall) and of the process (user CPU).

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_volume_3.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/volume/volume_medit.h>

#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace D = SMP::internal::dlf;

namespace {

bool read(const char* path, D::Medit_tet_mesh& m)
{
  std::ifstream in(path);
  std::string error;
  if(!in || !D::read_medit(in, m, error)) {
    std::cerr << path << ": " << (in ? error : "cannot open") << "\n";
    return false;
  }
  std::vector<int> kept;
  D::drop_unused_vertices(m, kept);
  return true;
}

double user_seconds()
{
  rusage r;
  getrusage(RUSAGE_SELF, &r);
  return double(r.ru_utime.tv_sec) + 1e-6 * double(r.ru_utime.tv_usec);
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 3) {
    std::cerr << "usage: volume_flow_speed IN.mesh START.mesh [--threads N] [--cg-iterations N] "
                 "[--max-iterations N] [--no-forcing] [--coarse K] [-v]\n";
    return 2;
  }
  SMP::Discrete_lie_flow_volume_options O;
  bool verbose = false;
  for(int i = 3; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "-v") verbose = true;
    else if(a == "--no-forcing") O.cg_forcing = false;
    else if(i + 1 < argc && a == "--coarse") O.coarse_aggregate = std::size_t(std::atol(argv[++i]));
    else if(i + 1 < argc && a == "--threads") O.threads = std::atoi(argv[++i]);
    else if(i + 1 < argc && a == "--cg-iterations") O.cg_max_iterations = std::size_t(std::atol(argv[++i]));
    else if(i + 1 < argc && a == "--max-iterations") O.max_iterations = std::size_t(std::atol(argv[++i]));
    else { std::cerr << "unknown argument " << a << "\n"; return 2; }
  }
  D::Medit_tet_mesh in, start;
  if(!read(argv[1], in) || !read(argv[2], start)) return 1;
  if(in.points.size() != start.points.size() || in.tets != start.tets) {
    std::cerr << "the start is not a map of the input (other vertices or tets)\n";
    return 1;
  }
  D::Ball_topology topo;
  std::string message;
  if(D::check_ball(in.points, in.tets, topo, message) != SMP::OK) { std::cerr << message << "\n"; return 1; }
  std::vector<double> target(in.tets.size());
  for(std::size_t t = 0; t < in.tets.size(); ++t) {
    const D::Tet& k = in.tets[t];
    target[t] = D::tet_det(in.points[std::size_t(k[0])], in.points[std::size_t(k[1])], in.points[std::size_t(k[2])],
                           in.points[std::size_t(k[3])]);
  }
  std::vector<D::Vec3> x = start.points;
  if(D::count_bad_tets(x, in.tets).not_positive() != 0) { std::cerr << "the start is not certified\n"; return 1; }
  if(verbose)
    O.callback = [](const SMP::Discrete_lie_flow_volume_iteration& I) {
      std::printf("it %4zu  D_vol %.6f  step %.3g  cg %3zu  %.2f s\n", I.iteration, I.d_vol, I.step,
                  I.cg_iterations, I.seconds);
      std::fflush(stdout);
      return true;
    };
  const double user0 = user_seconds();
  const auto t0 = std::chrono::steady_clock::now();
  const D::Volume_flow_outcome o = D::run_volume_flow(x, in.tets, topo.on_border, topo.border_faces, target, O);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double user = user_seconds() - user0;
  std::vector<double> u;
  D::tet_dets(x, in.tets, u);
  const D::Volume_energy energy(target);
  const D::Tet_orientation_counts bad = D::count_bad_tets(x, in.tets);
  std::printf("tets %zu  threads %d  stop %d  iterations %zu  cg %zu  D_vol %.6f  inverted %zu  flat %zu  "
              "flow %.2f s  user %.2f s\n",
              in.tets.size(), O.threads, int(o.stop_reason), o.iterations, o.cg_iterations, energy.value(u, 0),
              bad.negative, bad.flat, wall, user);
  return 0;
}
