// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Makes long thin disks for the flow (cut_to_disk.h):
//
//   cut_to_disk cut CLOSED.off K OUT.off [SEAM.selection.txt]
//       cut a closed mesh open along a tree of shortest paths through K
//       tips (and a cut graph of its handles): OUT.off has the seam's
//       vertices duplicated; SEAM.selection.txt lists the seam edges of
//       CLOSED.off (for CGAL's Seam_mesh)
//   cut_to_disk cut-root CLOSED.off K OUT.off [SEAM.selection.txt]
//       the same, each tip by its own shortest path to the first tip: the
//       branches run side by side before they merge
//   cut_to_disk maze N S OUT.off      N × N cells, S × S squares per block
//   cut_to_disk comb TEETH LENGTH S OUT.off
//   cut_to_disk spiral TURNS S OUT.off
//   cut_to_disk slits N SLITS LENGTH OUT.off
//
// One line on standard output: vertices, faces, border vertices, the tips.

#include "cut_to_disk.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/subdivision_method_3.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <string>

namespace {

int usage()
{
  std::cerr << "usage: cut_to_disk cut|cut-root CLOSED.off K OUT.off [SEAM.selection.txt]\n"
               "       cut_to_disk maze N S OUT.off | comb TEETH LENGTH S OUT.off | spiral TURNS S OUT.off\n"
               "       cut_to_disk slits N SLITS LENGTH OUT.off\n"
               "       cut_to_disk subdivide CLOSED.off K OUT.off   (K steps of Loop subdivision)\n";
  return 2;
}

std::size_t border_vertices(const dlf_cut::Mesh& m)
{
  std::map<std::pair<int, int>, int> directed;
  for(const dlf_cut::Triangle& t : m.faces)
    for(int k = 0; k < 3; ++k) directed[{ t[k], t[(k + 1) % 3] }] = 1;
  std::set<int> border;
  for(const auto& e : directed)
    if(!directed.count({ e.first.second, e.first.first })) { border.insert(e.first.first); border.insert(e.first.second); }
  return border.size();
}

bool write(const std::string& path, const dlf_cut::Mesh& m)
{
  std::ofstream out(path);
  dlf_cut::write_off(out, m);
  std::cout << "vertices " << m.points.size() << " faces " << m.faces.size() << " border " << border_vertices(m)
            << " euler " << dlf_cut::euler_characteristic(m);
  return bool(out);
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 2) return usage();
  const std::string what = argv[1];
  bool ok = false;
  if((what == "cut" || what == "cut-root") && (argc == 5 || argc == 6)) {
    dlf_cut::Mesh closed;
    std::ifstream in(argv[2]);
    if(!dlf_cut::read_off(in, closed)) { std::cerr << "cut_to_disk: cannot read " << argv[2] << "\n"; return 1; }
    const long chi = dlf_cut::euler_characteristic(closed);
    const std::vector<int> tips = dlf_cut::extremities(closed, std::size_t(std::atoi(argv[3])));
    const std::set<dlf_cut::Edge> seam = dlf_cut::cut_graph(closed, tips, what == "cut");
    const dlf_cut::Mesh disk = dlf_cut::cut_open(closed, seam);
    ok = write(argv[4], disk);
    std::cout << " genus " << (2 - chi) / 2 << " seam_edges " << seam.size() << " tips";
    for(int t : tips) std::cout << " " << t;
    if(argc == 6) {
      std::ofstream sel(argv[5]);
      dlf_cut::write_selection(sel, seam);
      ok = ok && bool(sel);
    }
  } else if(what == "subdivide" && argc == 5) {
    // Larger cut surfaces: subdivide first, then cut the result.
    CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3> mesh;
    if(!CGAL::IO::read_polygon_mesh(argv[2], mesh)) { std::cerr << "cut_to_disk: cannot read " << argv[2] << "\n"; return 1; }
    CGAL::Subdivision_method_3::Loop_subdivision(mesh, CGAL::parameters::number_of_iterations(std::atoi(argv[3])));
    ok = CGAL::IO::write_OFF(argv[4], mesh, CGAL::parameters::stream_precision(17));
    std::cout << "faces " << num_faces(mesh);
  } else if(what == "maze" && argc == 5) {
    ok = write(argv[4], dlf_cut::block_shape(dlf_cut::maze_blocks(std::atoi(argv[2])), std::atoi(argv[3])));
  } else if(what == "comb" && argc == 6) {
    ok = write(argv[5], dlf_cut::block_shape(dlf_cut::comb_blocks(std::atoi(argv[2]), std::atoi(argv[3])), std::atoi(argv[4])));
  } else if(what == "spiral" && argc == 5) {
    ok = write(argv[4], dlf_cut::block_shape(dlf_cut::spiral_blocks(std::atoi(argv[2])), std::atoi(argv[3])));
  } else if(what == "slits" && argc == 6) {
    ok = write(argv[5], dlf_cut::slit_square(std::atoi(argv[2]), std::atoi(argv[3]), std::atoi(argv[4])));
  } else {
    return usage();
  }
  std::cout << "\n";
  return ok ? 0 : 1;
}
