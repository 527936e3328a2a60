// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Disks with long zero-width seams and long thin corridors, made on index
// data (no CGAL): a closed mesh cut open along a shortest-path tree through
// its extremities (and, for genus g > 0, along a tree–cotree cut graph), and
// flat block shapes (maze, comb, spiral) and slit squares. Used by the
// cut_to_disk benchmark program and by the test suite.

#ifndef DLF_BENCHMARK_CUT_TO_DISK_H
#define DLF_BENCHMARK_CUT_TO_DISK_H

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <istream>
#include <limits>
#include <map>
#include <ostream>
#include <queue>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace dlf_cut {

typedef std::array<double, 3> Point;
typedef std::array<int, 3> Triangle;

struct Mesh
{
  std::vector<Point> points;
  std::vector<Triangle> faces;
};

/// Reads an OFF of triangles (COFF and comments allowed); false on anything else.
inline bool read_off(std::istream& in, Mesh& m)
{
  std::string head;
  if(!(in >> head) || head.find("OFF") == std::string::npos) return false;
  auto skip = [&in] {
    for(;;) {
      in >> std::ws;
      if(in.peek() != '#') return;
      std::string line;
      std::getline(in, line);
    }
  };
  skip();
  std::size_t nv = 0, nf = 0, ne = 0;
  if(!(in >> nv >> nf >> ne)) return false;
  m.points.resize(nv);
  std::string line;
  std::getline(in, line);
  for(Point& p : m.points) {
    skip();
    if(!std::getline(in, line)) return false;
    std::sscanf(line.c_str(), "%lf %lf %lf", &p[0], &p[1], &p[2]);
  }
  m.faces.resize(nf);
  for(Triangle& t : m.faces) {
    skip();
    int k = 0;
    if(!(in >> k) || k != 3 || !(in >> t[0] >> t[1] >> t[2])) return false;
    std::getline(in, line);
  }
  return true;
}

inline void write_off(std::ostream& out, const Mesh& m)
{
  out.precision(17);
  out << "OFF\n" << m.points.size() << " " << m.faces.size() << " 0\n";
  for(const Point& p : m.points) out << p[0] << " " << p[1] << " " << p[2] << "\n";
  for(const Triangle& t : m.faces) out << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
}

typedef std::pair<int, int> Edge; // (smaller, larger) vertex index

inline Edge edge(int a, int b) { return a < b ? Edge(a, b) : Edge(b, a); }

/// A CGAL selection file of edges (Seam_mesh's format): two empty lines
/// (vertices, faces), then the pairs of vertex indices.
inline void write_selection(std::ostream& out, const std::set<Edge>& seam)
{
  out << "\n\n";
  bool first = true;
  for(const Edge& e : seam) {
    out << (first ? "" : " ") << e.first << " " << e.second;
    first = false;
  }
  out << "\n";
}

inline double distance(const Point& a, const Point& b)
{
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

/// Vertex neighbours with edge lengths.
inline std::vector<std::vector<std::pair<int, double> > > adjacency(const Mesh& m)
{
  std::set<Edge> edges;
  for(const Triangle& t : m.faces)
    for(int k = 0; k < 3; ++k) edges.insert(edge(t[k], t[(k + 1) % 3]));
  std::vector<std::vector<std::pair<int, double> > > adj(m.points.size());
  for(const Edge& e : edges) {
    const double l = distance(m.points[std::size_t(e.first)], m.points[std::size_t(e.second)]);
    adj[std::size_t(e.first)].emplace_back(e.second, l);
    adj[std::size_t(e.second)].emplace_back(e.first, l);
  }
  return adj;
}

/// Dijkstra on edge lengths from `sources`: distances and the parent of
/// each vertex in the shortest-path forest (−1 at a source or unreached).
inline void dijkstra(const std::vector<std::vector<std::pair<int, double> > >& adj, const std::vector<int>& sources,
                     std::vector<double>& dist, std::vector<int>& parent)
{
  dist.assign(adj.size(), std::numeric_limits<double>::infinity());
  parent.assign(adj.size(), -1);
  typedef std::pair<double, int> Item;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item> > q;
  for(int s : sources) { dist[std::size_t(s)] = 0; q.emplace(0., s); }
  while(!q.empty()) {
    const Item it = q.top();
    q.pop();
    if(it.first > dist[std::size_t(it.second)]) continue;
    for(const auto& nb : adj[std::size_t(it.second)]) {
      const double d = it.first + nb.second;
      // Ties go to the smaller parent index: deterministic trees.
      if(d < dist[std::size_t(nb.first)]) {
        dist[std::size_t(nb.first)] = d;
        parent[std::size_t(nb.first)] = it.second;
        q.emplace(d, nb.first);
      }
    }
  }
}

/// k extremities (tips of protrusions): the vertex farthest from vertex 0,
/// then, among the vertices that are local maxima of the geodesic distance
/// from it (over their 2-ring), farthest-point sampling. Deterministic.
inline std::vector<int> extremities(const Mesh& m, std::size_t k)
{
  const auto adj = adjacency(m);
  std::vector<double> d;
  std::vector<int> parent;
  dijkstra(adj, { 0 }, d, parent);
  int first = int(std::max_element(d.begin(), d.end()) - d.begin());
  dijkstra(adj, { first }, d, parent);
  std::vector<int> candidates;
  for(std::size_t v = 0; v < adj.size(); ++v) {
    bool top = true;
    for(const auto& a : adj[v]) {
      if(d[std::size_t(a.first)] > d[v]) top = false;
      for(const auto& b : adj[std::size_t(a.first)])
        if(d[std::size_t(b.first)] > d[v]) top = false;
    }
    if(top && int(v) != first) candidates.push_back(int(v));
  }
  std::vector<int> tips(1, first);
  std::vector<double> near = d; // distance to the nearest chosen tip
  while(tips.size() < k && !candidates.empty()) {
    int best = -1;
    for(int c : candidates)
      if(best < 0 || near[std::size_t(c)] > near[std::size_t(best)]) best = c;
    if(!(near[std::size_t(best)] > 0)) break;
    tips.push_back(best);
    std::vector<double> dn;
    dijkstra(adj, { best }, dn, parent);
    for(std::size_t v = 0; v < near.size(); ++v) near[v] = (std::min)(near[v], dn[v]);
  }
  return tips;
}

/// Euler characteristic V − E + F of a mesh.
inline long euler_characteristic(const Mesh& m)
{
  std::set<Edge> edges;
  for(const Triangle& t : m.faces)
    for(int k = 0; k < 3; ++k) edges.insert(edge(t[k], t[(k + 1) % 3]));
  return long(m.points.size()) - long(edges.size()) + long(m.faces.size());
}

/// The cut graph of a closed connected mesh through `tips`: a tree of
/// shortest paths joining the tips (each tip, nearest first, by a shortest
/// path to the tree of the previous ones), plus, for genus g > 0, the 2g
/// loops of a tree–cotree decomposition (the primal tree extends the tips'
/// tree by shortest paths to it; each edge outside both trees closes a loop
/// through the first tip), with the branches that lead to no tip pruned.
/// Cutting along it leaves one disk.
///
/// With `join_nearest` false, every tip goes to the first one by its own
/// shortest path (one shortest-path tree, the primal tree as well): the
/// branches then run side by side one edge apart before they merge, and
/// every face between two such branches becomes a triangle with its three
/// corners on the border, as seams drawn independently through the
/// protrusions often do.
inline std::set<Edge> cut_graph(const Mesh& m, const std::vector<int>& tips, bool join_nearest = true)
{
  const auto adj = adjacency(m);
  const int root = tips.empty() ? 0 : tips[0];
  std::vector<int> parent(m.points.size(), -1); // toward the root, in the primal tree
  std::set<Edge> cut, tree;
  std::vector<int> seam_vertices(1, root);
  std::vector<char> joined(tips.size(), 0);
  if(!tips.empty()) joined[0] = 1;
  std::vector<double> dt;
  std::vector<int> pt;
  if(!join_nearest) {
    dijkstra(adj, { root }, dt, parent);
    for(int t : tips)
      for(int v = t; parent[std::size_t(v)] >= 0; v = parent[std::size_t(v)]) cut.insert(edge(v, parent[std::size_t(v)]));
  }
  for(std::size_t added = 1; join_nearest && added < tips.size(); ++added) {
    dijkstra(adj, seam_vertices, dt, pt);
    std::size_t next = tips.size();
    for(std::size_t k = 0; k < tips.size(); ++k)
      if(!joined[k] && (next == tips.size() || dt[std::size_t(tips[k])] < dt[std::size_t(tips[next])])) next = k;
    joined[next] = 1;
    for(int v = tips[next]; pt[std::size_t(v)] >= 0; v = pt[std::size_t(v)]) {
      parent[std::size_t(v)] = pt[std::size_t(v)];
      cut.insert(edge(v, pt[std::size_t(v)]));
      seam_vertices.push_back(v);
    }
  }
  // The primal tree: the tips' tree, then shortest paths to it.
  dijkstra(adj, seam_vertices, dt, pt);
  for(std::size_t v = 0; v < parent.size(); ++v) {
    if(parent[v] < 0) parent[v] = pt[v];
    if(parent[v] >= 0) tree.insert(edge(int(v), parent[v]));
  }
  auto path_to_root = [&](int v) {
    for(; parent[std::size_t(v)] >= 0; v = parent[std::size_t(v)]) cut.insert(edge(v, parent[std::size_t(v)]));
  };
  // Cotree: a spanning tree of the dual across the edges not in the tree.
  std::map<Edge, std::vector<int> > faces_of;
  for(std::size_t f = 0; f < m.faces.size(); ++f)
    for(int k = 0; k < 3; ++k) faces_of[edge(m.faces[f][k], m.faces[f][(k + 1) % 3])].push_back(int(f));
  std::set<Edge> cotree;
  std::vector<char> seen(m.faces.size(), 0);
  std::queue<int> q;
  q.push(0);
  seen[0] = 1;
  while(!q.empty()) {
    const int f = q.front();
    q.pop();
    for(int k = 0; k < 3; ++k) {
      const Edge e = edge(m.faces[std::size_t(f)][k], m.faces[std::size_t(f)][(k + 1) % 3]);
      if(tree.count(e)) continue;
      for(int g : faces_of[e])
        if(!seen[std::size_t(g)]) { seen[std::size_t(g)] = 1; cotree.insert(e); q.push(g); }
    }
  }
  for(const auto& ef : faces_of)
    if(!tree.count(ef.first) && !cotree.count(ef.first)) {
      cut.insert(ef.first);
      path_to_root(ef.first.first);
      path_to_root(ef.first.second);
    }
  // Prune the branches of the loops' paths that end at no tip.
  std::set<int> keep(tips.begin(), tips.end());
  for(bool pruned = true; pruned;) {
    pruned = false;
    std::map<int, int> degree;
    for(const Edge& e : cut) { ++degree[e.first]; ++degree[e.second]; }
    for(auto it = cut.begin(); it != cut.end();) {
      const bool leaf_a = degree[it->first] == 1 && !keep.count(it->first);
      const bool leaf_b = degree[it->second] == 1 && !keep.count(it->second);
      if(leaf_a || leaf_b) { it = cut.erase(it); pruned = true; }
      else ++it;
    }
  }
  return cut;
}

/// Cuts `m` open along `seam`: every vertex gets one copy per wedge of its
/// faces between seam edges (a vertex on k seam edges becomes k vertices at
/// the same position), so both sides of the seam are separate border vertices.
inline Mesh cut_open(const Mesh& m, const std::set<Edge>& seam)
{
  // Face across each directed edge.
  std::map<std::pair<int, int>, int> face_of;
  for(std::size_t f = 0; f < m.faces.size(); ++f)
    for(int k = 0; k < 3; ++k) face_of[{ m.faces[f][k], m.faces[f][(k + 1) % 3] }] = int(f);
  std::vector<std::vector<int> > faces_at(m.points.size());
  for(std::size_t f = 0; f < m.faces.size(); ++f)
    for(int k = 0; k < 3; ++k) faces_at[std::size_t(m.faces[f][k])].push_back(int(f));
  Mesh out;
  out.faces = m.faces;
  std::vector<int> copy_of_corner(3 * m.faces.size(), -1);
  for(std::size_t v = 0; v < m.points.size(); ++v) {
    if(faces_at[v].empty()) continue;
    // Walk around v: from face (v, a, b) to the face across the edge (v, b),
    // the one holding the directed edge v → b.
    // Start after a seam edge (or at a border edge, or anywhere).
    auto corner = [&](int f) {
      for(int k = 0; k < 3; ++k)
        if(m.faces[std::size_t(f)][k] == int(v)) return k;
      return -1;
    };
    int start = faces_at[v][0];
    for(int f : faces_at[v]) {
      const int k = corner(f);
      const int a = m.faces[std::size_t(f)][(k + 1) % 3];
      if(seam.count(edge(int(v), a)) || !face_of.count({ a, int(v) })) { start = f; break; }
    }
    int f = start, wedge = int(out.points.size());
    out.points.push_back(m.points[v]);
    for(std::size_t guard = 0; guard < faces_at[v].size(); ++guard) {
      const int k = corner(f);
      copy_of_corner[3 * std::size_t(f) + std::size_t(k)] = wedge;
      const int b = m.faces[std::size_t(f)][(k + 2) % 3];
      auto next = face_of.find({ int(v), b });
      if(next == face_of.end() || next->second == start) break;
      if(seam.count(edge(int(v), b))) { wedge = int(out.points.size()); out.points.push_back(m.points[v]); }
      f = next->second;
    }
  }
  for(std::size_t f = 0; f < m.faces.size(); ++f)
    for(int k = 0; k < 3; ++k) out.faces[f][std::size_t(k)] = copy_of_corner[3 * f + std::size_t(k)];
  return out;
}

/// A flat shape made of unit blocks (`open[j][i]`, row j = y), each split
/// into s × s squares of two triangles, vertices shared between blocks.
inline Mesh block_shape(const std::vector<std::vector<char> >& open, int s)
{
  Mesh m;
  std::map<std::pair<int, int>, int> index;
  auto vertex = [&](int x, int y) {
    auto it = index.find({ x, y });
    if(it != index.end()) return it->second;
    const int i = int(m.points.size());
    index[{ x, y }] = i;
    m.points.push_back({{ double(x) / s, double(y) / s, 0. }});
    return i;
  };
  for(std::size_t j = 0; j < open.size(); ++j)
    for(std::size_t i = 0; i < open[j].size(); ++i) {
      if(!open[j][i]) continue;
      for(int b = 0; b < s; ++b)
        for(int a = 0; a < s; ++a) {
          const int x = int(i) * s + a, y = int(j) * s + b;
          const int p = vertex(x, y), q = vertex(x + 1, y), r = vertex(x + 1, y + 1), t = vertex(x, y + 1);
          // Alternate the diagonals: no direction is preferred.
          if((x + y) % 2 == 0) { m.faces.push_back({{ p, q, r }}); m.faces.push_back({{ p, r, t }}); }
          else { m.faces.push_back({{ p, q, t }}); m.faces.push_back({{ q, r, t }}); }
        }
    }
  return m;
}

/// A perfect maze of n × n cells (depth-first, a fixed linear congruential
/// sequence): cells and the walls removed between them are open blocks.
inline std::vector<std::vector<char> > maze_blocks(int n, std::uint32_t seed = 1)
{
  const int N = 2 * n + 1;
  std::vector<std::vector<char> > open(std::size_t(N), std::vector<char>(std::size_t(N), 0));
  std::vector<std::pair<int, int> > stack(1, { 0, 0 });
  std::vector<char> seen(std::size_t(n * n), 0);
  seen[0] = 1;
  open[1][1] = 1;
  auto next = [&seed] { seed = seed * 1664525u + 1013904223u; return seed >> 8; };
  const int dx[4] = { 1, -1, 0, 0 }, dy[4] = { 0, 0, 1, -1 };
  while(!stack.empty()) {
    const auto c = stack.back();
    int options[4], k = 0;
    for(int d = 0; d < 4; ++d) {
      const int x = c.first + dx[d], y = c.second + dy[d];
      if(x >= 0 && y >= 0 && x < n && y < n && !seen[std::size_t(y * n + x)]) options[k++] = d;
    }
    if(k == 0) { stack.pop_back(); continue; }
    const int d = options[next() % std::uint32_t(k)];
    const int x = c.first + dx[d], y = c.second + dy[d];
    seen[std::size_t(y * n + x)] = 1;
    open[std::size_t(2 * c.second + 1 + dy[d])][std::size_t(2 * c.first + 1 + dx[d])] = 1;
    open[std::size_t(2 * y + 1)][std::size_t(2 * x + 1)] = 1;
    stack.push_back({ x, y });
  }
  return open;
}

/// A comb: a spine of `teeth`·2 − 1 blocks, teeth of `length` blocks every other block.
inline std::vector<std::vector<char> > comb_blocks(int teeth, int length)
{
  const int W = 2 * teeth - 1;
  std::vector<std::vector<char> > open(std::size_t(length + 1), std::vector<char>(std::size_t(W), 0));
  for(int i = 0; i < W; ++i) open[0][std::size_t(i)] = 1;
  for(int t = 0; t < teeth; ++t)
    for(int j = 1; j <= length; ++j) open[std::size_t(j)][std::size_t(2 * t)] = 1;
  return open;
}

/// A square spiral corridor one block wide, walls one block thick, on
/// (2·turns + 3)² blocks: legs of N − 1, N − 1, N − 1, N − 3, N − 3, N − 5, … blocks.
inline std::vector<std::vector<char> > spiral_blocks(int turns)
{
  const int N = 2 * turns + 3;
  std::vector<std::vector<char> > open(std::size_t(N), std::vector<char>(std::size_t(N), 0));
  const int dx[4] = { 1, 0, -1, 0 }, dy[4] = { 0, 1, 0, -1 };
  int x = 0, y = 0;
  open[0][0] = 1;
  for(int leg = 0;; ++leg) {
    const int len = leg < 3 ? N - 1 : N - 1 - 2 * ((leg - 1) / 2);
    if(len <= 0) break;
    for(int k = 0; k < len; ++k) {
      x += dx[leg % 4];
      y += dy[leg % 4];
      open[std::size_t(y)][std::size_t(x)] = 1;
    }
  }
  return open;
}

/// A square of n × n blocks (one square each) with `slits` zero-width slits
/// from the left side, each `length` blocks long, cut open as seams.
inline Mesh slit_square(int n, int slits, int length)
{
  std::vector<std::vector<char> > open(std::size_t(n), std::vector<char>(std::size_t(n), 1));
  Mesh m = block_shape(open, 1);
  // block_shape numbers vertices on first use: look them up by position.
  std::map<std::pair<int, int>, int> at;
  for(std::size_t v = 0; v < m.points.size(); ++v)
    at[{ int(std::lround(m.points[v][0])), int(std::lround(m.points[v][1])) }] = int(v);
  std::set<Edge> seam;
  for(int s = 1; s <= slits; ++s) {
    const int y = s * n / (slits + 1);
    for(int x = 0; x < length; ++x) seam.insert(edge(at[{ x, y }], at[{ x + 1, y }]));
  }
  return cut_open(m, seam);
}

} // namespace dlf_cut

#endif
