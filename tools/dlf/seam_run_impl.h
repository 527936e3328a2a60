// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Seam_mesh of a seamed run, shared by seam_run_fixed_border.cpp and
// seam_run_free_border.cpp.

#ifndef DLF_CLI_SEAM_RUN_IMPL_H
#define DLF_CLI_SEAM_RUN_IMPL_H

#include "cli_error.h"
#include "disk_run_inits.h"
#include "seam_run.h"

#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/boost/graph/Seam_mesh.h>

namespace dlf_cli {

typedef Surface_mesh::Property_map<boost::graph_traits<Surface_mesh>::edge_descriptor, bool> Seam_edge_map;
typedef Surface_mesh::Property_map<vertex_descriptor, bool> Seam_vertex_map;
typedef CGAL::Seam_mesh<Surface_mesh, Seam_edge_map, Seam_vertex_map> Seam_mesh;
typedef boost::graph_traits<Seam_mesh>::halfedge_descriptor Seam_halfedge;
typedef boost::property_map<Seam_mesh, CGAL::dynamic_vertex_property_t<int> >::type Seam_vertex_index_map;

/// Builds the Seam_mesh of `input` cut along `cut.seams` (with add_seam(),
/// as CGAL's seam_Polyhedron_3 example), numbers its vertices as `cut.mesh`
/// does, takes the longest border as the border to map, and returns
/// `run(seam_mesh, border_halfedge, vertex_index_map)`.
template <class Run>
Disk_run with_seam_mesh(const Indexed_mesh& input, const Seam_cut& cut, Run run)
{
  Surface_mesh sm;
  build_surface_mesh(input, sm);
  Seam_edge_map sem = sm.add_property_map<boost::graph_traits<Surface_mesh>::edge_descriptor, bool>("e:dlf_on_seam", false).first;
  Seam_vertex_map svm = sm.add_property_map<vertex_descriptor, bool>("v:dlf_on_seam", false).first;
  Seam_mesh mesh(sm, sem, svm);
  for(const Vertex_pair& e : cut.seams.edges)
    if(!mesh.add_seam(Surface_mesh::Vertex_index(e[0]), Surface_mesh::Vertex_index(e[1])))
      throw Cli_error("Seam_mesh refused the seam edge (" + std::to_string(e[0]) + " " + std::to_string(e[1]) + ")");

  // A Seam_mesh vertex is a side of an input vertex; the corner of a face at
  // it names the cut vertex.
  Seam_vertex_index_map vimap = get(CGAL::dynamic_vertex_property_t<int>(), mesh);
  for(boost::graph_traits<Seam_mesh>::vertex_descriptor v : vertices(mesh)) put(vimap, v, -1);
  std::size_t numbered = 0;
  for(boost::graph_traits<Seam_mesh>::face_descriptor f : faces(mesh)) {
    const Triangle& in = input.faces[std::size_t(f.idx())];
    for(Seam_halfedge h : halfedges_around_face(halfedge(f, mesh), mesh)) {
      const int tm_vertex = int(target(h.tmhd, sm).idx());
      const int k = in[0] == tm_vertex ? 0 : in[1] == tm_vertex ? 1 : 2;
      const int side = cut.mesh.faces[std::size_t(f.idx())][std::size_t(k)];
      const int known = get(vimap, target(h, mesh));
      if(known < 0) { put(vimap, target(h, mesh), side); ++numbered; }
      else if(known != side)
        throw Cli_error("the Seam_mesh joins sides " + std::to_string(known) + " and " + std::to_string(side) +
                        " of input vertex " + std::to_string(tm_vertex) + " that the cut separates");
    }
  }
  if(numbered != num_vertices(mesh) || numbered != cut.mesh.xyz.size())
    throw Cli_error("the Seam_mesh has " + std::to_string(num_vertices(mesh)) + " vertices, the cut " +
                    std::to_string(cut.mesh.xyz.size()));
  const Seam_halfedge bhd = CGAL::Polygon_mesh_processing::longest_border(mesh).first;
  return run(mesh, bhd, vimap);
}

} // namespace dlf_cli

#endif
