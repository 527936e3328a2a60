// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Area-preserving map of a surface cut open along seams: CGAL's Seam_mesh
// over a Surface_mesh, its seam edges read from a CGAL selection file, mapped
// by Discrete_lie_flow_parameterizer_3 through CGAL's parameterize(), as
// CGAL's own seam examples do with LSCM. A vertex on a seam gets one uv per
// side, so the uv map is stored per halfedge of the underlying mesh. Prints
// the report and the distortion measured independently; writes no file.
//
// Usage: seams mesh.off seams.selection.txt
//        (e.g. CGAL's lion.off and its lion.selection.txt)

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Seam_mesh.h>

#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/measure.h>

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_distortion.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_parameterizer_3.h>

#include <cstdlib>
#include <iostream>
#include <string>

typedef CGAL::Simple_cartesian<double> Kernel;
typedef Kernel::Point_2 Point_2;
typedef Kernel::Point_3 Point_3;
typedef CGAL::Surface_mesh<Point_3> Surface_mesh;
typedef boost::graph_traits<Surface_mesh>::edge_descriptor SM_edge;
typedef boost::graph_traits<Surface_mesh>::vertex_descriptor SM_vertex;
typedef boost::graph_traits<Surface_mesh>::halfedge_descriptor SM_halfedge;

typedef Surface_mesh::Property_map<SM_edge, bool> Seam_edges;
typedef Surface_mesh::Property_map<SM_vertex, bool> Seam_vertices;
typedef CGAL::Seam_mesh<Surface_mesh, Seam_edges, Seam_vertices> Mesh;
typedef boost::graph_traits<Mesh>::halfedge_descriptor halfedge_descriptor;

namespace SMP = CGAL::Surface_mesh_parameterization;

int main(int argc, char** argv)
{
  if(argc != 3) {
    std::cerr << "usage: " << argv[0] << " mesh.off seams.selection.txt" << std::endl;
    return EXIT_FAILURE;
  }
  Surface_mesh sm;
  if(!CGAL::Polygon_mesh_processing::IO::read_polygon_mesh(argv[1], sm)) {
    std::cerr << "Invalid input file: " << argv[1] << std::endl;
    return EXIT_FAILURE;
  }

  // The seams: marks on the edges and vertices of the underlying mesh.
  Seam_edges seam_edges = sm.add_property_map<SM_edge, bool>("e:on_seam", false).first;
  Seam_vertices seam_vertices = sm.add_property_map<SM_vertex, bool>("v:on_seam", false).first;
  Mesh mesh(sm, seam_edges, seam_vertices);
  if(mesh.add_seams(argv[2]) == SM_halfedge()) {
    std::cerr << "No seam read from " << argv[2] << std::endl;
    return EXIT_FAILURE;
  }

  // One uv per halfedge of the underlying mesh (a vertex of the seam mesh).
  Surface_mesh::Property_map<SM_halfedge, Point_2> uv = sm.add_property_map<SM_halfedge, Point_2>("h:uv").first;

  // The cut surface's longest border is the outer one: it goes to the circle.
  const halfedge_descriptor bhd = CGAL::Polygon_mesh_processing::longest_border(mesh).first;
  SMP::Discrete_lie_flow_parameterizer_3<Mesh> dlf;
  const SMP::Error_code err = SMP::parameterize(mesh, dlf, bhd, uv);
  const SMP::Discrete_lie_flow_report& report = dlf.report();
  std::cout << argv[1] << " cut along " << argv[2] << ": " << report.vertices << " vertices, " << report.faces
            << " faces, " << report.holes << " holes\n"
            << "status: " << SMP::discrete_lie_flow_error_name(report.status) << " (" << report.message << ")\n";
  if(err != SMP::OK) return EXIT_FAILURE;
  std::cout << "flow: " << report.iterations << " iterations, stop: "
            << SMP::discrete_lie_flow_stop_reason_name(report.stop_reason) << ", d_area " << report.initial_d_area
            << " -> " << report.final_d_area << "\n";

  // The same map measured on its own: D_area and the folds by exact orientation.
  const SMP::Discrete_lie_flow_distortion d = SMP::discrete_lie_flow_distortion(mesh, uv);
  std::cout << "measured: d_area " << d.d_area << ", inverted or degenerate faces "
            << d.inverted_faces + d.degenerate_faces << std::endl;
  return EXIT_SUCCESS;
}
