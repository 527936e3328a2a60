// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "cli_util.h"
#include "seam_input.h"
#include "cli_error.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <limits>
#include <numeric>
#include <queue>
#include <sstream>
#include <unordered_map>
#include <utility>

namespace dlf_cli {

namespace {


// The face on the left of each directed edge a -> b (the mesh is manifold
// and consistently oriented, read_triangle_mesh()).
class Directed_edges
{
public:
  explicit Directed_edges(const Indexed_mesh& mesh) : m_n((long long)(mesh.xyz.size()))
  {
    m_face.reserve(3 * mesh.faces.size());
    for(std::size_t f = 0; f < mesh.faces.size(); ++f)
      for(int k = 0; k < 3; ++k) m_face.emplace(key(mesh.faces[f][k], mesh.faces[f][(k + 1) % 3]), int(f));
  }
  /// The face left of a -> b, or -1.
  int face(int a, int b) const
  {
    const auto it = m_face.find(key(a, b));
    return it == m_face.end() ? -1 : it->second;
  }
  bool is_edge(int a, int b) const { return face(a, b) >= 0 || face(b, a) >= 0; }
  bool is_interior(int a, int b) const { return face(a, b) >= 0 && face(b, a) >= 0; }

private:
  long long key(int a, int b) const { return (long long)(a) * m_n + b; }
  long long m_n;
  std::unordered_map<long long, int> m_face;
};

// The indices of one line of a selection file.
std::vector<long> line_indices(const std::string& line, const std::string& path, int line_number)
{
  return selection_indices(line, path, line_number, "a vertex index (a whole number >= 0)", true);
}

std::string pair_name(long a, long b) { return "(" + std::to_string(a) + " " + std::to_string(b) + ")"; }

// Shortest paths (3D length, interior edges) joining `cones` in order, each
// to the nearest vertex of the seam so far: a tree, whatever the cones.
std::vector<Vertex_pair> join_cones(const Indexed_mesh& mesh, const Directed_edges& edges, const std::vector<int>& cones,
                                    const std::string& path)
{
  const std::size_t V = mesh.xyz.size();
  std::vector<std::vector<int> > neighbours(V);
  for(const Triangle& t : mesh.faces)
    for(int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      if(edges.is_interior(a, b) && a < b) { neighbours[std::size_t(a)].push_back(b); neighbours[std::size_t(b)].push_back(a); }
    }
  auto length = [&](int a, int b) {
    const Vec3 &p = mesh.xyz[std::size_t(a)], &q = mesh.xyz[std::size_t(b)];
    return std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
  };
  std::vector<bool> in_tree(V, false);
  in_tree[std::size_t(cones[0])] = true;
  std::vector<Vertex_pair> out;
  for(std::size_t c = 1; c < cones.size(); ++c) {
    const int goal = cones[c];
    if(in_tree[std::size_t(goal)]) continue;
    // Dijkstra from the goal to the tree; (distance, vertex) keeps ties deterministic.
    std::vector<double> dist(V, std::numeric_limits<double>::infinity());
    std::vector<int> parent(V, -1);
    typedef std::pair<double, int> Item;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item> > queue;
    dist[std::size_t(goal)] = 0;
    queue.push(Item(0, goal));
    int reached = -1;
    while(!queue.empty()) {
      const Item top = queue.top();
      queue.pop();
      const int v = top.second;
      if(top.first > dist[std::size_t(v)]) continue;
      if(in_tree[std::size_t(v)]) { reached = v; break; }
      for(int w : neighbours[std::size_t(v)]) {
        const double d = top.first + length(v, w);
        if(d < dist[std::size_t(w)]) { dist[std::size_t(w)] = d; parent[std::size_t(w)] = v; queue.push(Item(d, w)); }
      }
    }
    if(reached < 0)
      throw Cli_error(quoted(path) + ": line 1: no path of interior edges joins vertex " + std::to_string(goal) +
                      " to vertex " + std::to_string(cones[0]) + " (are they on different components?)");
    for(int v = reached; v != goal; v = parent[std::size_t(v)]) {
      out.push_back({{ parent[std::size_t(v)], v }});
      in_tree[std::size_t(v)] = true;
    }
    in_tree[std::size_t(goal)] = true;
  }
  return out;
}

// The seam edges of `pairs` (a0 b0 a1 b1 ...), each checked to be an
// interior edge of the mesh; `where(k)` names the k-th pair in messages.
std::vector<Vertex_pair> checked_seam_edges(const std::vector<long>& pairs, const Indexed_mesh& mesh,
                                            const Directed_edges& edges, const std::function<std::string(std::size_t)>& where)
{
  const long V = long(mesh.xyz.size());
  std::vector<std::pair<int, int> > seen;
  for(std::size_t k = 0; k + 1 < pairs.size(); k += 2) {
    const long a = pairs[k], b = pairs[k + 1];
    const std::string at = where(k / 2) + " " + pair_name(a, b) + ": ";
    for(long v : { a, b })
      if(v < 0 || v >= V)
        throw Cli_error(at + "vertex " + std::to_string(v) + " does not exist (the mesh has " + std::to_string(V) +
                        " vertices)");
    if(a == b) throw Cli_error(at + "not an edge (the same vertex twice)");
    if(!edges.is_edge(int(a), int(b))) throw Cli_error(at + "no edge of the mesh joins these vertices");
    if(!edges.is_interior(int(a), int(b)))
      throw Cli_error(at + "a border edge of the mesh (a seam cuts along interior edges)");
    seen.emplace_back(int(std::min(a, b)), int(std::max(a, b)));
  }
  // An edge listed twice is one seam (CGAL's Seam_mesh ignores the repeat).
  std::sort(seen.begin(), seen.end());
  seen.erase(std::unique(seen.begin(), seen.end()), seen.end());
  std::vector<Vertex_pair> out;
  for(const auto& e : seen) out.push_back({{ e.first, e.second }});
  return out;
}

} // namespace

Seam_selection seam_selection_of_pairs(const std::vector<long>& pairs, const Indexed_mesh& mesh, const std::string& name)
{
  if(pairs.size() % 2 != 0) throw Cli_error(name + ": an odd number of vertex indices; seam edges are pairs");
  Seam_selection s;
  s.edges = checked_seam_edges(pairs, mesh, Directed_edges(mesh),
                               [&](std::size_t k) { return name + ": edge " + std::to_string(k); });
  if(s.edges.empty()) throw Cli_error(name + ": no seam edges: nothing to cut along");
  return s;
}

Seam_selection read_seam_selection(const std::string& path, const Indexed_mesh& mesh)
{
  std::ifstream in(path);
  if(!in) throw Cli_error(quoted(path) + ": cannot open (no such file, or not readable)");
  std::vector<std::string> lines;
  for(std::string line; std::getline(in, line); ) lines.push_back(line);
  for(std::size_t k = 3; k < lines.size(); ++k)
    if(lines[k].find_first_not_of(" \t\r") != std::string::npos)
      throw Cli_error(quoted(path) + ": line " + std::to_string(k + 1) + ": unexpected; a selection file has 3 lines "
                      "(vertices, faces, edges as pairs of vertex indices)");
  lines.resize(3);
  const std::vector<long> vertex_line = line_indices(lines[0], path, 1);
  line_indices(lines[1], path, 2); // faces: checked, not used
  const std::vector<long> edge_line = line_indices(lines[2], path, 3);

  const long V = long(mesh.xyz.size());
  const Directed_edges edges(mesh);
  Seam_selection s;
  if(edge_line.size() % 2 != 0)
    throw Cli_error(quoted(path) + ": line 3 has " + std::to_string(edge_line.size()) +
                    " indices, an odd number: seam edges are pairs of vertex indices");
  s.edges = checked_seam_edges(edge_line, mesh, edges, [&](std::size_t k) {
    return quoted(path) + ": line 3, pair " + std::to_string(k + 1);
  });

  std::vector<int> cones;
  for(long v : vertex_line) {
    if(v >= V)
      throw Cli_error(quoted(path) + ": line 1: vertex " + std::to_string(v) + " does not exist (the mesh has " +
                      std::to_string(V) + " vertices)");
    if(std::find(cones.begin(), cones.end(), int(v)) == cones.end()) cones.push_back(int(v));
  }
  if(s.edges.empty()) {
    if(cones.size() < 2)
      throw Cli_error(quoted(path) + ": no seam edges (line 3 is empty) and " + std::to_string(cones.size()) +
                      " vertex on line 1 to join: nothing to cut along");
    s.edges = join_cones(mesh, edges, cones, path);
    s.cones = cones.size();
  }
  return s;
}

Seam_cut cut_along_seams(const Indexed_mesh& mesh, const Seam_selection& seams)
{
  const std::size_t V = mesh.xyz.size(), F = mesh.faces.size();
  const Directed_edges edges(mesh);
  std::unordered_map<long long, bool> on_seam;
  for(const Vertex_pair& e : seams.edges) {
    on_seam[(long long)(e[0]) * (long long)(V) + e[1]] = true;
    on_seam[(long long)(e[1]) * (long long)(V) + e[0]] = true;
  }
  // Corners 3f + k; the corners of a vertex around which no seam separates
  // them are one side: join them across every interior edge that is no seam.
  std::vector<std::size_t> parent(3 * F);
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  auto find = [&parent](std::size_t i) {
    while(parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  auto corner = [&](int f, int v) {
    const Triangle& t = mesh.faces[std::size_t(f)];
    return 3 * std::size_t(f) + std::size_t(t[0] == v ? 0 : t[1] == v ? 1 : 2);
  };
  for(std::size_t f = 0; f < F; ++f)
    for(int k = 0; k < 3; ++k) {
      const int a = mesh.faces[f][k], b = mesh.faces[f][(k + 1) % 3];
      const int g = edges.face(b, a);
      if(g < 0 || a > b || on_seam.count((long long)(a) * (long long)(V) + b)) continue;
      parent[find(corner(int(f), a))] = find(corner(g, a));
      parent[find(corner(int(f), b))] = find(corner(g, b));
    }

  Seam_cut cut;
  cut.seams = seams;
  std::vector<int> side(3 * F, -1);
  std::vector<bool> named(V, false);
  cut.input_vertex.resize(V);
  std::iota(cut.input_vertex.begin(), cut.input_vertex.end(), 0);
  cut.mesh.faces.resize(F);
  for(std::size_t c = 0; c < 3 * F; ++c) {
    const int v = mesh.faces[c / 3][c % 3];
    int& s = side[find(c)];
    if(s < 0) {
      // The first side met keeps the input's number; other sides follow.
      if(!named[std::size_t(v)]) { s = v; named[std::size_t(v)] = true; }
      else { s = int(cut.input_vertex.size()); cut.input_vertex.push_back(v); }
    }
    cut.mesh.faces[c / 3][c % 3] = s;
  }
  cut.mesh.xyz.reserve(cut.input_vertex.size());
  for(int v : cut.input_vertex) cut.mesh.xyz.push_back(mesh.xyz[std::size_t(v)]);
  return cut;
}

Seam_cut read_and_cut(const Indexed_mesh& mesh, const std::string& mesh_path, const std::string& seam_path,
                      const std::function<void(const Indexed_mesh&, const std::string&)>& check)
{
  return checked_cut(mesh, mesh_path, read_seam_selection(seam_path, mesh), quoted(seam_path), check);
}

Seam_cut checked_cut(const Indexed_mesh& mesh, const std::string& mesh_path, const Seam_selection& seams,
                     const std::string& seam_name, const std::function<void(const Indexed_mesh&, const std::string&)>& check)
{
  Seam_cut cut = cut_along_seams(mesh, seams);
  try {
    check(cut.mesh, mesh_path);
  } catch(const Cli_error& e) {
    // "'MESH': not a disk..." becomes "'MESH' cut along ...: not a disk...".
    const std::size_t n = cut.seams.edges.size();
    const std::string cut_name = " cut along the " + std::to_string(n) + " seam edge" + (n == 1 ? "" : "s") + " of " +
      seam_name + (cut.seams.cones ? " (shortest paths joining the " + std::to_string(cut.seams.cones) +
                                             " vertices of its line 1)" : std::string());
    std::string message = e.what();
    const std::string prefix = quoted(mesh_path);
    if(message.compare(0, prefix.size(), prefix) == 0) message.insert(prefix.size(), cut_name);
    else message += " (" + cut_name.substr(1) + ")";
    throw Cli_error(message, e.code());
  }
  return cut;
}

} // namespace dlf_cli
