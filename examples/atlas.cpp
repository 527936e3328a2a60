// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// An area-preserving atlas of a closed mesh of any genus: cut into charts,
// each flattened by the certified flow, packed into the unit square. The
// uv map is per corner (per halfedge), as CGAL's Seam_mesh users expect.
//
// Usage: atlas [mesh.off]
// Without a mesh: meshes/elephant.off of CGAL's data set, found as CGAL's own
// examples find it: CGAL::data_file_path() reads $CGAL_DATA_DIR, else the
// macro of that name (this project's build defines it).

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_atlas_3.h>

#include <iostream>
#include <string>

typedef CGAL::Simple_cartesian<double> Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Surface_mesh;
typedef boost::graph_traits<Surface_mesh>::halfedge_descriptor halfedge_descriptor;

namespace SMP = CGAL::Surface_mesh_parameterization;

int main(int argc, char** argv)
{
  const std::string filename = (argc > 1) ? argv[1] : CGAL::data_file_path("meshes/elephant.off");

  Surface_mesh sm;
  if(!CGAL::Polygon_mesh_processing::IO::read_polygon_mesh(filename, sm)) {
    std::cerr << "Invalid input file: " << filename << std::endl;
    return EXIT_FAILURE;
  }

  // One uv per corner: halfedge h holds the uv of target(h) in face(h).
  Surface_mesh::Property_map<halfedge_descriptor, Kernel::Point_2> uvmap =
    sm.add_property_map<halfedge_descriptor, Kernel::Point_2>("h:uv").first;

  // Defaults: square charts, seams through 2 tips and the handles, a
  // gutter of 1/1024; Discrete_lie_flow_atlas_options changes them.
  const SMP::Discrete_lie_flow_atlas_report report = SMP::discrete_lie_flow_atlas(sm, uvmap);
  if(report.code != SMP::OK) {
    std::cerr << "Error: " << SMP::discrete_lie_flow_error_message(report.code) << ": " << report.message << std::endl;
    return EXIT_FAILURE;
  }

  std::cout << filename << ": " << num_faces(sm) << " faces, genus " << report.max_genus << ", " << report.charts
            << " charts, seam " << report.seam_length << ", packing " << report.packing_efficiency << ", D_area "
            << report.metrics.d_area << " (optimum 2), " << report.inverted_faces + report.degenerate_faces
            << " inverted, " << report.overlapping_chart_pairs << " overlapping, "
            << (report.converged() ? "converged" : "not converged") << std::endl;
  return report.valid() ? EXIT_SUCCESS : EXIT_FAILURE;
}
