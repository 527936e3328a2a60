// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Scores a uv map written by CGAL's `IO::output_uvmap_to_off(mesh, bhd,
// uvmap, os)` (the file CGAL's parameterization examples write), for the
// test cgal_examples_swap:
//
//   dlf_cgal_map_score KIND MESH.off [SEAMS.selection.txt] UV.off
//
// KIND is how the program held its mesh: surface_mesh, polyhedron,
// seam_surface_mesh or seam_polyhedron. The file carries no 3D positions;
// its faces are those of the connected component of the longest border in
// the order CGAL's writer visits them, so the mesh is read as the program
// read it and visited the same way: face k of the file is face k of the
// walk, corner by corner. Prints faces, inverted, degenerate and D_area;
// exits 1 when the file and the walk disagree.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Seam_mesh.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_parameterization/internal/Containers_filler.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_distortion.h>
#include <CGAL/Unique_hash_map.h>

#include <boost/function_output_iterator.hpp>
#include <boost/property_map/property_map.hpp>

#include <array>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <unordered_set>
#include <vector>

namespace {

typedef CGAL::Simple_cartesian<double> Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Surface_mesh;
typedef CGAL::Polyhedron_3<Kernel> Polyhedron;

struct Uv_off
{
  std::vector<std::array<double, 2> > uv;
  std::vector<std::array<int, 3> > faces;
};

bool read_uv_off(const std::string& name, Uv_off& m)
{
  std::ifstream in(name);
  std::string header;
  std::size_t nv = 0, nf = 0, ne = 0;
  if(!(in >> header >> nv >> nf >> ne) || header != "OFF") return false;
  m.uv.resize(nv);
  for(std::array<double, 2>& p : m.uv) {
    double z = 0;
    if(!(in >> p[0] >> p[1] >> z)) return false;
  }
  m.faces.resize(nf);
  for(std::array<int, 3>& f : m.faces) {
    int k = 0;
    if(!(in >> k >> f[0] >> f[1] >> f[2]) || k != 3) return false;
  }
  return true;
}

template <class Mesh>
int score(const Mesh& mesh, const Uv_off& map)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<Mesh>::face_descriptor face_descriptor;
  const typename boost::graph_traits<Mesh>::halfedge_descriptor bhd =
    CGAL::Polygon_mesh_processing::longest_border(mesh).first;
  // The walk of CGAL's writer.
  std::unordered_set<vertex_descriptor> vertices;
  std::vector<face_descriptor> faces;
  CGAL::Surface_mesh_parameterization::internal::Containers_filler<Mesh> fc(mesh, vertices, &faces);
  CGAL::Polygon_mesh_processing::connected_component(face(opposite(bhd, mesh), mesh), mesh,
                                                     boost::make_function_output_iterator(fc));
  if(faces.size() != map.faces.size() || vertices.size() != map.uv.size()) {
    std::cerr << "the map has " << map.faces.size() << " faces and " << map.uv.size() << " vertices, the component "
              << faces.size() << " and " << vertices.size() << "\n";
    return 1;
  }
  const auto points = get(CGAL::vertex_point, mesh);
  std::vector<std::array<double, 3> > xyz(map.uv.size());
  std::vector<vertex_descriptor> of(map.uv.size());
  std::vector<char> seen(map.uv.size(), 0);
  for(std::size_t k = 0; k < faces.size(); ++k) {
    int c = 0;
    for(vertex_descriptor v : vertices_around_face(halfedge(faces[k], mesh), mesh)) {
      const std::size_t i = std::size_t(map.faces[k][std::size_t(c++)]);
      if(i >= of.size() || (seen[i] && of[i] != v)) { std::cerr << "face " << k << " does not match the walk\n"; return 1; }
      seen[i] = 1;
      of[i] = v;
      const Kernel::Point_3 p = get(points, v);
      xyz[i] = {{ p.x(), p.y(), p.z() }};
    }
  }
  const CGAL::Surface_mesh_parameterization::Discrete_lie_flow_distortion d =
    CGAL::Surface_mesh_parameterization::discrete_lie_flow_distortion(xyz, map.uv, map.faces);
  std::cout << "faces " << map.faces.size() << " inverted " << d.inverted_faces << " degenerate " << d.degenerate_faces
            << " d_area " << d.d_area << "\n";
  return 0;
}

template <class Mesh>
int score_seamed(Mesh& sm, const std::string& seams, const Uv_off& map)
{
  typedef typename boost::graph_traits<Mesh>::edge_descriptor edge_descriptor;
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  typedef CGAL::Unique_hash_map<edge_descriptor, bool> Seam_edges;
  typedef CGAL::Unique_hash_map<vertex_descriptor, bool> Seam_vertices;
  typedef boost::associative_property_map<Seam_edges> Seam_edge_map;
  typedef boost::associative_property_map<Seam_vertices> Seam_vertex_map;
  Seam_edges seam_edges(false);
  Seam_vertices seam_vertices(false);
  CGAL::Seam_mesh<Mesh, Seam_edge_map, Seam_vertex_map> mesh(sm, Seam_edge_map(seam_edges), Seam_vertex_map(seam_vertices));
  mesh.add_seams(seams.c_str());
  return score(mesh, map);
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 4) {
    std::cerr << "usage: dlf_cgal_map_score surface_mesh|polyhedron|seam_surface_mesh|seam_polyhedron MESH.off [SEAMS] UV.off\n";
    return 2;
  }
  const std::string kind = argv[1];
  const bool seamed = kind.compare(0, 5, "seam_") == 0;
  if(seamed && argc < 5) { std::cerr << "a seamed mesh needs its selection file\n"; return 2; }
  Uv_off map;
  if(!read_uv_off(argv[seamed ? 4 : 3], map)) { std::cerr << "cannot read the uv OFF\n"; return 1; }
  // Each read as CGAL's examples read it.
  std::ifstream in(argv[2]);
  if(kind == "surface_mesh" || kind == "seam_surface_mesh") {
    Surface_mesh sm;
    if(!(in >> sm)) { std::cerr << "cannot read the mesh\n"; return 1; }
    return seamed ? score_seamed(sm, argv[3], map) : score(sm, map);
  }
  if(kind == "polyhedron" || kind == "seam_polyhedron") {
    Polyhedron sm;
    if(!(in >> sm)) { std::cerr << "cannot read the mesh\n"; return 1; }
    return seamed ? score_seamed(sm, argv[3], map) : score(sm, map);
  }
  std::cerr << "unknown kind " << kind << "\n";
  return 2;
}
