// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Surface_mesh the tool hands to the library, built in input order.

#ifndef DLF_CLI_SURFACE_MESH_H
#define DLF_CLI_SURFACE_MESH_H

#include "mesh_input.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

namespace dlf_cli {

typedef CGAL::Simple_cartesian<double> Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Surface_mesh;
typedef boost::graph_traits<Surface_mesh>::halfedge_descriptor halfedge_descriptor;
typedef boost::graph_traits<Surface_mesh>::vertex_descriptor vertex_descriptor;
typedef boost::graph_traits<Surface_mesh>::face_descriptor face_descriptor;

/// Builds the Surface_mesh in input order: vertex i of the file is
/// `Surface_mesh::Vertex_index(i)` and face f is `Surface_mesh::Face_index(f)`.
inline void build_surface_mesh(const Indexed_mesh& in, Surface_mesh& sm)
{
  sm.reserve(Surface_mesh::size_type(in.xyz.size()), Surface_mesh::size_type(3 * in.faces.size()),
             Surface_mesh::size_type(in.faces.size()));
  for(const Vec3& p : in.xyz) sm.add_vertex(Kernel::Point_3(p[0], p[1], p[2]));
  for(const Triangle& t : in.faces)
    sm.add_face(Surface_mesh::Vertex_index(t[0]), Surface_mesh::Vertex_index(t[1]), Surface_mesh::Vertex_index(t[2]));
}

} // namespace dlf_cli

#endif
