// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Volume-preserving map of a tetrahedral mesh of a ball into the unit ball
// with the volumetric Discrete Lie Flow: the mesh read from a Medit `.mesh`
// file (as CGAL's Mesh_3 writes it), its border mapped onto the sphere by
// the spherical flow, the interior by Tutte's embedding untangled and then
// flowed. Prints what happened; writes no file.
//
// Usage: volume_map tets.mesh

#include <CGAL/Simple_cartesian.h>

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_medit.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_volume_3.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Simple_cartesian<double>::Point_3 Point_3;

namespace SMP = CGAL::Surface_mesh_parameterization;

int main(int argc, char** argv)
{
  if(argc != 2) {
    std::cerr << "usage: " << argv[0] << " tets.mesh" << std::endl;
    return EXIT_FAILURE;
  }
  std::ifstream in(argv[1]);
  SMP::Discrete_lie_flow_tet_mesh tm;
  std::string error;
  if(!in || !SMP::read_medit_tet_mesh(in, tm, error)) {
    std::cerr << "Invalid input file: " << argv[1] << (error.empty() ? "" : ": " + error) << std::endl;
    return EXIT_FAILURE;
  }
  std::vector<Point_3> points;
  for(const auto& p : tm.points) points.emplace_back(p[0], p[1], p[2]);

  // Defaults: certified start, certified flow to D_vol ≤ 2.01.
  SMP::Discrete_lie_flow_volume_parameterizer_3<> dlf;
  std::vector<Point_3> ball;
  const SMP::Error_code err = dlf.parameterize(points, tm.tets, ball);
  const SMP::Discrete_lie_flow_volume_report& report = dlf.report();
  std::cout << argv[1] << ": " << report.vertices << " vertices (" << report.border_vertices << " on the border), "
            << report.tets << " tets\n"
            << "status: " << SMP::discrete_lie_flow_error_name(report.status) << " (" << report.message << ")\n";
  if(err != SMP::OK) return EXIT_FAILURE;
  std::cout << "flow: " << report.iterations << " iterations, stop: "
            << SMP::discrete_lie_flow_stop_reason_name(report.stop_reason) << ", d_vol " << report.initial_d_vol
            << " -> " << report.final_d_vol << ", mean |log volume ratio| " << report.log_volume_mean_abs << "\n"
            << "inverted or flat tets: " << report.inverted_tets + report.flat_tets
            << ", border faces not facing out: " << report.inverted_border_faces << "\n";

  // Every image point lies in the closed unit ball.
  double farthest = 0;
  for(const Point_3& p : ball) farthest = (std::max)(farthest, p.x() * p.x() + p.y() * p.y() + p.z() * p.z());
  std::cout << "largest |x| " << std::sqrt(farthest) << std::endl;
  return EXIT_SUCCESS;
}
