// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Area-preserving map of a closed genus-0 triangle mesh onto the unit sphere
// with the spherical Discrete Lie Flow. Prints what happened, and the area
// elements the run stored as properties of the mesh; writes no file.
//
// Usage: sphere_map [mesh.off] [max_iterations]
// Without a mesh: meshes/blobby.off of CGAL's data set, found as CGAL's own
// examples find it: CGAL::data_file_path() reads $CGAL_DATA_DIR, else the
// macro of that name (this project's build defines it).

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_sphere_3.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>

typedef CGAL::Simple_cartesian<double> Kernel;
typedef Kernel::Point_3 Point_3;
typedef CGAL::Surface_mesh<Point_3> Surface_mesh;
typedef boost::graph_traits<Surface_mesh>::vertex_descriptor vertex_descriptor;

namespace SMP = CGAL::Surface_mesh_parameterization;

int main(int argc, char** argv)
{
  const std::string filename = (argc > 1) ? argv[1] : CGAL::data_file_path("meshes/blobby.off");

  Surface_mesh sm;
  if(!CGAL::Polygon_mesh_processing::IO::read_polygon_mesh(filename, sm)) {
    std::cerr << "Invalid input file: " << filename << std::endl;
    return EXIT_FAILURE;
  }

  // The points on the unit sphere are stored in a property map of the mesh.
  Surface_mesh::Property_map<vertex_descriptor, Point_3> sphere =
    sm.add_property_map<vertex_descriptor, Point_3>("v:sphere").first;

  // Defaults: certified initial map, certified flow to D_area ≤ 2.01.
  SMP::Discrete_lie_flow_sphere_parameterizer_3<Surface_mesh> dlf;
  if(argc > 2) dlf.options().max_iterations = std::size_t(std::atol(argv[2]));
  dlf.parameterize(sm, sphere);
  const SMP::Discrete_lie_flow_report& report = dlf.report();

  std::cout << filename << ": " << report.vertices << " vertices, " << report.faces << " faces\n"
            << "status: " << SMP::discrete_lie_flow_error_name(report.status) << " (" << report.message << ")\n";
  if(report.status != SMP::OK) return EXIT_FAILURE;
  std::cout << "initial map: puncture face " << report.puncture_face << ", scale " << report.initial_scale
            << ", d_area " << report.initial_d_area << ", max |log area ratio| "
            << report.initial_metrics.log_area_max_abs << " (" << report.seconds_initial << " s)\n"
            << "flow: " << report.iterations << " iterations, stop: " << SMP::discrete_lie_flow_stop_reason_name(report.stop_reason)
            << ", d_area " << report.final_d_area << ", mean/max |log area ratio| "
            << report.final_metrics.log_area_mean_abs << " / " << report.final_metrics.log_area_max_abs
            << " (" << report.seconds_flow << " s)\n"
            << "inverted or degenerate faces: " << report.caller_inverted_faces << std::endl;

  // The area elements of the run, stored on the mesh: per vertex the target
  // area A_M and the sphere area A_Ω (both sum to the area of the flat
  // triangles between the sphere points), per face the density used.
  const auto target = sm.property_map<vertex_descriptor, double>("v:dlf_target_area");
  const auto domain = sm.property_map<vertex_descriptor, double>("v:dlf_domain_area");
  if(!target.second || !domain.second) {
    std::cerr << "Error: the area elements are not stored on the mesh" << std::endl;
    return EXIT_FAILURE;
  }
  double sum_target = 0, sum_domain = 0, worst = 0;
  for(vertex_descriptor v : vertices(sm)) {
    sum_target += target.first[v];
    sum_domain += domain.first[v];
    worst = (std::max)(worst, std::abs(std::log(domain.first[v] / target.first[v])));
  }
  std::cout << "area elements: target " << sum_target << ", domain " << sum_domain
            << " (4π = 12.566), largest |log(A_Ω / A_M)| at a vertex " << worst << std::endl;
  return EXIT_SUCCESS;
}
