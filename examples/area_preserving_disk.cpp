// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Area-preserving parameterization of a disk-topology triangle mesh with the
// Discrete Lie Flow, called exactly like the parameterizers CGAL ships.
//
// Usage: area_preserving_disk [mesh.off]
// Without a mesh: meshes/nefertiti.off of CGAL's data set, found as CGAL's own
// examples find it: CGAL::data_file_path() reads $CGAL_DATA_DIR, else the
// macro of that name (this project's build defines it).

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/measure.h>

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <iostream>
#include <string>

typedef CGAL::Simple_cartesian<double> Kernel;
typedef Kernel::Point_2 Point_2;
typedef Kernel::Point_3 Point_3;
typedef CGAL::Surface_mesh<Point_3> Surface_mesh;

typedef boost::graph_traits<Surface_mesh>::halfedge_descriptor halfedge_descriptor;
typedef boost::graph_traits<Surface_mesh>::vertex_descriptor vertex_descriptor;

namespace SMP = CGAL::Surface_mesh_parameterization;

int main(int argc, char** argv)
{
  const std::string filename = (argc > 1) ? argv[1] : CGAL::data_file_path("meshes/nefertiti.off");

  Surface_mesh sm;
  if(!CGAL::Polygon_mesh_processing::IO::read_polygon_mesh(filename, sm)) {
    std::cerr << "Invalid input file: " << filename << std::endl;
    return EXIT_FAILURE;
  }

  // A halfedge on the longest border: the flow maps this border's loop onto
  // the boundary of the domain.
  const halfedge_descriptor bhd = CGAL::Polygon_mesh_processing::longest_border(sm).first;
  if(bhd == boost::graph_traits<Surface_mesh>::null_halfedge()) { // SMP's parameterize() requires a border
    std::cerr << "Error: " << SMP::discrete_lie_flow_error_message(SMP::ERROR_NO_TOPOLOGICAL_DISC)
              << ": the mesh has no border" << std::endl;
    return EXIT_FAILURE;
  }

  // The uv coordinates are stored in a property map of the mesh.
  Surface_mesh::Property_map<vertex_descriptor, Point_2> uvmap =
    sm.add_property_map<vertex_descriptor, Point_2>("v:uv").first;

  // Default: Tutte's initial map on a circle, then the certified flow, which
  // never folds a triangle. Discrete_lie_flow_options selects the paper's
  // flow, a square or free border, a density, tolerances and a callback.
  typedef SMP::Discrete_lie_flow_parameterizer_3<Surface_mesh> Parameterizer;
  Parameterizer parameterizer;

  const SMP::Error_code err = SMP::parameterize(sm, parameterizer, bhd, uvmap);
  if(err != SMP::OK) {
    // CGAL's code is returned; the report holds the precise one, and its
    // message names the offending element (face, vertex).
    std::cerr << "Error: " << SMP::discrete_lie_flow_error_message(parameterizer.report().status) << ": "
              << parameterizer.report().message
              << std::endl;
    return EXIT_FAILURE;
  }

  const SMP::Discrete_lie_flow_report& report = parameterizer.report();
  std::cout << filename << ": " << num_vertices(sm) << " vertices, area distortion " << report.initial_d_area
            << " -> " << report.final_d_area << " (optimum 2) in " << report.iterations << " iterations ("
            << SMP::discrete_lie_flow_stop_reason_name(report.stop_reason) << ")" << std::endl;
  return EXIT_SUCCESS;
}
