// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "mesh_input.h"
#include "cli_error.h"

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <numeric>
#include <sstream>
#include <utility>

namespace dlf_cli {

namespace {

typedef CGAL::Simple_cartesian<double>::Point_3 Point_3;
typedef std::vector<std::size_t> Polygon;

std::string quoted(const std::string& path) { return "'" + path + "'"; }

void check_triangles(const std::vector<Polygon>& polygons, const std::string& path)
{
  std::size_t bad = 0, first = 0;
  for(std::size_t f = 0; f < polygons.size(); ++f)
    if(polygons[f].size() != 3 && bad++ == 0) first = f;
  if(bad == 0) {
    for(std::size_t f = 0; f < polygons.size(); ++f) {
      const Polygon& p = polygons[f];
      if(p[0] == p[1] || p[1] == p[2] || p[2] == p[0])
        throw Cli_error(quoted(path) + ": face " + std::to_string(f) + " uses vertex " +
                        std::to_string(p[0] == p[1] || p[0] == p[2] ? p[0] : p[1]) + " twice");
    }
    return;
  }
  std::ostringstream s;
  s << quoted(path) << ": " << bad << " of " << polygons.size() << " faces are not triangles (first: face " << first
    << " with " << polygons[first].size() << " vertices); triangulate the mesh first";
  throw Cli_error(s.str());
}

// Unreferenced vertices would have no uv; rather than invent one (and break
// "vt i is the uv of input vertex i"), refuse them.
void check_referenced(std::size_t n, const std::vector<Polygon>& polygons, const std::string& path)
{
  std::vector<bool> used(n, false);
  for(const Polygon& p : polygons)
    for(std::size_t i : p) used[i] = true;
  const std::size_t unused = std::size_t(std::count(used.begin(), used.end(), false));
  if(unused == 0) return;
  std::ostringstream s;
  s << quoted(path) << ": " << unused << (unused == 1 ? " vertex is" : " vertices are") << " not used by any face (first: vertex "
    << std::size_t(std::find(used.begin(), used.end(), false) - used.begin()) << "); remove them first";
  throw Cli_error(s.str());
}

// A tiny union-find over vertex indices, for counting connected components.
struct Union_find
{
  std::vector<std::size_t> parent;
  explicit Union_find(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), std::size_t(0)); }
  std::size_t find(std::size_t i)
  {
    while(parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }
  void unite(std::size_t a, std::size_t b) { parent[find(a)] = find(b); }
};

} // namespace

Indexed_mesh read_triangle_mesh(const std::string& path)
{
  if(!std::ifstream(path))
    throw Cli_error(quoted(path) + ": cannot open (no such file, or not readable)");

  std::vector<Point_3> points;
  std::vector<Polygon> polygons;
  // The soup reader, not PMP::IO::read_polygon_mesh(): the latter's repair
  // step merges duplicate points and drops isolated ones, which renumbers
  // vertices, and every output of the tool must keep the input's numbering.
  if(!CGAL::IO::read_polygon_soup(path, points, polygons))
    throw Cli_error(quoted(path) + ": cannot read as a mesh (CGAL reads .off, .obj, .ply, .stl, .ts, .vtp)");
  if(polygons.empty())
    throw Cli_error(quoted(path) + ": the mesh has no faces");
  for(std::size_t i = 0; i < points.size(); ++i)
    if(!std::isfinite(points[i].x()) || !std::isfinite(points[i].y()) || !std::isfinite(points[i].z()))
      throw Cli_error(quoted(path) + ": vertex " + std::to_string(i) + " has a non-finite coordinate");
  for(std::size_t f = 0; f < polygons.size(); ++f)
    for(std::size_t i : polygons[f])
      if(i >= points.size())
        throw Cli_error(quoted(path) + ": face " + std::to_string(f) + " refers to vertex " + std::to_string(i) +
                        " of " + std::to_string(points.size()));
  check_triangles(polygons, path);
  check_referenced(points.size(), polygons, path);

  if(!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(polygons)) {
    // Only an inconsistently oriented file gets here; orienting flips some
    // faces but keeps the order, unless it must duplicate non-manifold
    // vertices, which would renumber.
    const std::size_t n = points.size(), mesh_faces = polygons.size();
    CGAL::Polygon_mesh_processing::orient_polygon_soup(points, polygons);
    if(points.size() != n || polygons.size() != mesh_faces || !CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(polygons))
      throw Cli_error(quoted(path) + ": the mesh is not manifold (an edge has more than two faces, or a vertex "
                      "joins separate fans)");
  }

  Indexed_mesh mesh;
  mesh.xyz.reserve(points.size());
  for(const Point_3& p : points) mesh.xyz.push_back({{ p.x(), p.y(), p.z() }});
  mesh.faces.reserve(polygons.size());
  for(const Polygon& p : polygons) mesh.faces.push_back({{ int(p[0]), int(p[1]), int(p[2]) }});
  return mesh;
}

void check_disk_topology(const Indexed_mesh& mesh, const std::string& path)
{
  const std::size_t V = mesh.xyz.size(), F = mesh.faces.size();
  // Directed edges; a border edge is one whose reverse is absent. The mesh is
  // manifold and consistently oriented (read_triangle_mesh), so every border
  // vertex starts exactly one border edge and the loops can be walked.
  std::map<std::pair<int, int>, int> directed;
  for(const Triangle& t : mesh.faces)
    for(int k = 0; k < 3; ++k) directed[{ t[k], t[(k + 1) % 3] }] = 1;
  std::map<int, int> border_next; // b -> a for every border edge (b, a), reversed face edge a -> b
  std::size_t E = 0;
  for(const auto& e : directed) {
    const std::pair<int, int> reverse(e.first.second, e.first.first);
    if(directed.count(reverse) == 0) { border_next[e.first.second] = e.first.first; ++E; }
    else if(e.first.first < e.first.second) ++E;
  }
  std::size_t loops = 0;
  std::map<int, bool> walked;
  for(const auto& b : border_next) {
    if(walked[b.first]) continue;
    ++loops;
    for(int v = b.first; !walked[v]; ) {
      walked[v] = true;
      const auto next = border_next.find(v);
      if(next == border_next.end()) break;
      v = next->second;
    }
  }
  Union_find uf(V);
  for(const Triangle& t : mesh.faces) { uf.unite(std::size_t(t[0]), std::size_t(t[1])); uf.unite(std::size_t(t[1]), std::size_t(t[2])); }
  std::size_t components = 0;
  for(std::size_t i = 0; i < V; ++i)
    if(uf.find(i) == i) ++components;
  const long euler = long(V) - long(E) + long(F);
  if(components == 1 && loops == 1 && euler == 1) return;

  std::ostringstream s;
  s << quoted(path) << ": not a topological disk: found " << components << " connected component"
    << (components == 1 ? "" : "s") << ", " << loops << " border loop" << (loops == 1 ? "" : "s");
  if(components == 1) {
    // χ = 2 − 2g − b for a connected orientable surface with b border loops.
    const long twice_genus = 2 - long(loops) - euler;
    s << ", genus " << twice_genus / 2;
    if(loops == 0 && twice_genus == 0) s << " (a closed sphere-like surface: cut it open first)";
  } else {
    s << ", Euler characteristic " << euler;
  }
  s << "; a disk has 1 component, 1 border loop, genus 0";
  throw Cli_error(s.str());
}

} // namespace dlf_cli
