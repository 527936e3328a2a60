// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The seam that opens a connected piece into a disk: a tree of shortest
// paths through the piece's tips (closed pieces), and the 2g loops of a
// tree–cotree decomposition (pieces of genus g > 0, their holes capped by
// virtual fans, so the seam runs through every hole), pruned of branches
// that end nowhere and shortened: a seam turning around one triangle
// (a–b–c) takes the triangle's third edge instead, so no triangle keeps
// two seam edges (three corners on the border).

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_ATLAS_CUT_GRAPH_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_ATLAS_CUT_GRAPH_H

#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/atlas/atlas_mesh.h>

#include <algorithm>
#include <functional>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// A closed surface in halfedge form for the cut: the piece, plus one
/// virtual vertex and fan per border loop.
struct Closed_surface
{
  std::vector<Face> faces;
  std::vector<long> twin;
  std::vector<double> length;        ///< per halfedge: 3D length, 0 on a virtual spoke
  std::vector<std::size_t> out_begin; ///< CSR of outgoing halfedges per vertex
  std::vector<std::size_t> out;
  std::size_t real_vertices = 0, real_faces = 0;
  std::size_t vertices() const { return out_begin.size() - 1; }
  int from(std::size_t h) const { return faces[h / 3][h % 3]; }
  int to(std::size_t h) const { return faces[h / 3][(h % 3 + 1) % 3]; }
  std::size_t edge(std::size_t h) const { return (std::min)(h, std::size_t(twin[h])); }
};

inline Closed_surface close_surface(const Atlas_piece& P, const Piece_topology& T)
{
  Closed_surface S;
  S.faces = P.faces;
  S.real_vertices = P.xyz.size();
  S.real_faces = P.faces.size();
  int center = int(P.xyz.size());
  for(const std::vector<std::size_t>& loop : T.loops) {
    for(std::size_t h : loop) // border a → b: the cap face (b, a, centre) has the piece's orientation
      S.faces.push_back({{ P.faces[h / 3][(h % 3 + 1) % 3], P.faces[h / 3][h % 3], center }});
    ++center;
  }
  S.twin = halfedge_twins(S.faces);
  const std::size_t V = std::size_t(center), H = S.twin.size();
  S.length.assign(H, 0.);
  S.out_begin.assign(V + 1, 0);
  for(std::size_t h = 0; h < H; ++h) {
    const int a = S.from(h), b = S.to(h);
    if(std::size_t(a) < S.real_vertices && std::size_t(b) < S.real_vertices)
      S.length[h] = norm3(sub(P.xyz[std::size_t(a)], P.xyz[std::size_t(b)]));
    ++S.out_begin[std::size_t(a) + 1];
  }
  for(std::size_t v = 0; v < V; ++v) S.out_begin[v + 1] += S.out_begin[v];
  S.out.resize(H);
  std::vector<std::size_t> fill(S.out_begin.begin(), S.out_begin.end() - 1);
  for(std::size_t h = 0; h < H; ++h) S.out[fill[std::size_t(S.from(h))]++] = h;
  return S;
}

/// Dijkstra on edge lengths from `sources`: distances and, per vertex, the
/// halfedge that reached it (−1 at a source or unreached).
inline void cut_dijkstra(const Closed_surface& S, const std::vector<int>& sources, std::vector<double>& dist,
                         std::vector<long>& via)
{
  dist.assign(S.vertices(), std::numeric_limits<double>::infinity());
  via.assign(S.vertices(), -1);
  typedef std::pair<double, int> Item;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item> > q;
  for(int s : sources) { dist[std::size_t(s)] = 0; q.emplace(0., s); }
  while(!q.empty()) {
    const Item it = q.top();
    q.pop();
    if(it.first > dist[std::size_t(it.second)]) continue;
    for(std::size_t k = S.out_begin[std::size_t(it.second)]; k < S.out_begin[std::size_t(it.second) + 1]; ++k) {
      const std::size_t h = S.out[k];
      const int b = S.to(h);
      const double d = it.first + S.length[h];
      if(d < dist[std::size_t(b)]) { dist[std::size_t(b)] = d; via[std::size_t(b)] = long(h); q.emplace(d, b); }
    }
  }
}

/// Up to `k` tips of a closed piece (extremities of protrusions): the
/// vertex farthest from vertex 0, then farthest-point sampling among the
/// local maxima (over the 2-ring) of the geodesic distance from it.
inline std::vector<int> piece_tips(const Closed_surface& S, std::size_t k)
{
  std::vector<double> d, near;
  std::vector<long> via;
  cut_dijkstra(S, { 0 }, d, via);
  const int first = int(std::max_element(d.begin(), d.end()) - d.begin());
  cut_dijkstra(S, { first }, d, via);
  std::vector<int> candidates;
  for(std::size_t v = 0; v < S.vertices(); ++v) {
    bool top = int(v) != first;
    for(std::size_t i = S.out_begin[v]; top && i < S.out_begin[v + 1]; ++i) {
      const int a = S.to(S.out[i]);
      if(d[std::size_t(a)] > d[v]) top = false;
      for(std::size_t j = S.out_begin[std::size_t(a)]; top && j < S.out_begin[std::size_t(a) + 1]; ++j)
        if(d[std::size_t(S.to(S.out[j]))] > d[v]) top = false;
    }
    if(top) candidates.push_back(int(v));
  }
  std::vector<int> tips(1, first);
  near = d;
  while(tips.size() < k && !candidates.empty()) {
    int best = candidates[0];
    for(int c : candidates)
      if(near[std::size_t(c)] > near[std::size_t(best)]) best = c;
    if(!(near[std::size_t(best)] > 0)) break;
    tips.push_back(best);
    std::vector<double> dn;
    cut_dijkstra(S, { best }, dn, via);
    for(std::size_t v = 0; v < near.size(); ++v) near[v] = (std::min)(near[v], dn[v]);
  }
  return tips;
}

/// A shortest path from the `start` vertices (marked 1) to the seam
/// (marked 2) that leaves no triangle with all three corners on seams or
/// borders: it leaves the start and reaches the seam across edges whose
/// two triangles have their third corner free (mark 0), and in between
/// touches no vertex next to the start, to the seam (but for its last
/// step), or to a rim of a hole not joined yet (mark 3). The halfedges from
/// the start to the seam; empty if there is none.
inline std::vector<long> fenced_path(const Closed_surface& S, const std::vector<int>& start, const std::vector<char>& mark)
{
  const std::size_t V = S.vertices();
  std::vector<char> near_seam(V, 0), near_other(V, 0);
  for(std::size_t h = 0; h < S.twin.size(); ++h) {
    const int a = S.from(h), b = S.to(h);
    if(mark[std::size_t(a)] == 2) near_seam[std::size_t(b)] = 1;
    if(mark[std::size_t(a)] == 1 || mark[std::size_t(a)] == 3) near_other[std::size_t(b)] = 1;
  }
  auto good = [&](std::size_t h) {
    const std::size_t o = std::size_t(S.twin[h]);
    return mark[std::size_t(S.faces[h / 3][(h % 3 + 2) % 3])] == 0 && mark[std::size_t(S.faces[o / 3][(o % 3 + 2) % 3])] == 0;
  };
  std::vector<double> dist(V, std::numeric_limits<double>::infinity());
  std::vector<long> via(V, -1);
  typedef std::pair<double, int> Item;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item> > q;
  for(int s : start) { dist[std::size_t(s)] = 0; q.emplace(0., s); }
  int end = -1;
  while(!q.empty()) {
    const Item it = q.top();
    q.pop();
    const std::size_t u = std::size_t(it.second);
    if(it.first > dist[u]) continue;
    if(mark[u] == 2) { end = int(u); break; }
    for(std::size_t k = S.out_begin[u]; k < S.out_begin[u + 1]; ++k) {
      const std::size_t h = S.out[k];
      const std::size_t v = std::size_t(S.to(h));
      bool ok;
      if(mark[v] == 2) ok = good(h);
      else if(mark[v] != 0) ok = false;
      else if(mark[u] == 1) ok = good(h); // leaving the start
      else ok = !near_other[v] && !near_seam[u]; // next to the seam, the only way is onto it
      if(!ok) continue;
      const double d = it.first + S.length[h];
      if(d < dist[v]) { dist[v] = d; via[v] = long(h); q.emplace(d, int(v)); }
    }
  }
  std::vector<long> path;
  if(end < 0) return path;
  for(int v = end; via[std::size_t(v)] >= 0; v = S.from(std::size_t(via[std::size_t(v)]))) path.push_back(via[std::size_t(v)]);
  std::reverse(path.begin(), path.end());
  return path;
}

/// The tips' tree of the cut graph of `S`: from `tips[0]`, each next tip,
/// the nearest, joined by a fenced path to the tree so far (a plain
/// shortest path where no fenced one exists). Its edges are set in `cut`
/// (per canonical halfedge), `parent[v]` the halfedge into each of its
/// vertices from its parent (towards the seam); returns its vertices.
inline std::vector<int> join_tips(const Closed_surface& S, const std::vector<int>& tips, std::vector<char>& cut,
                                  std::vector<long>& parent)
{
  const std::size_t V = S.vertices();
  std::vector<double> dist;
  std::vector<long> via;
  std::vector<int> on_tree(1, tips[0]);
  std::vector<char> joined(tips.size(), 0);
  joined[0] = 1;
  // Fencing marks: 0 free, 1 the start, 2 on the seam (and the rims of
  // joined holes), 3 the rims of holes not joined yet.
  std::vector<char> mark(V, 0);
  std::vector<int> loop_of(V, -1); // the hole of a rim vertex (capped pieces)
  std::vector<std::vector<int> > rim(tips.size());
  for(std::size_t k = 0; k < tips.size(); ++k)
    if(std::size_t(tips[k]) >= S.real_vertices)
      for(std::size_t i = S.out_begin[std::size_t(tips[k])]; i < S.out_begin[std::size_t(tips[k]) + 1]; ++i) {
        rim[k].push_back(S.to(S.out[i]));
        loop_of[std::size_t(S.to(S.out[i]))] = int(k);
      }
  auto set_mark = [&](std::size_t k, char m) {
    mark[std::size_t(tips[k])] = m;
    for(int r : rim[k]) mark[std::size_t(r)] = m;
  };
  for(std::size_t k = 1; k < tips.size(); ++k) set_mark(k, 3);
  set_mark(0, 2);
  auto spoke = [&](int center, int r) { // the halfedge centre → r
    for(std::size_t i = S.out_begin[std::size_t(center)]; i < S.out_begin[std::size_t(center) + 1]; ++i)
      if(S.to(S.out[i]) == r) return long(S.out[i]);
    return -1L;
  };
  std::vector<char> in_graph(V, 0);
  in_graph[std::size_t(tips[0])] = 1;
  // Adds the path `hs` (halfedges from the start towards the seam) with
  // parents pointing towards the seam, and the spokes that tie it to the centres.
  auto add_path = [&](std::vector<long> hs, int center) {
    if(center >= 0) hs.insert(hs.begin(), spoke(center, S.from(std::size_t(hs.front()))));
    const int end = S.to(std::size_t(hs.back()));
    if(!in_graph[std::size_t(end)] && loop_of[std::size_t(end)] >= 0) hs.push_back(S.twin[std::size_t(spoke(tips[std::size_t(loop_of[std::size_t(end)])], end))]);
    for(long h : hs) {
      const int a = S.from(std::size_t(h)), b = S.to(std::size_t(h));
      if(!in_graph[std::size_t(a)]) { parent[std::size_t(a)] = S.twin[std::size_t(h)]; in_graph[std::size_t(a)] = 1; on_tree.push_back(a); }
      cut[S.edge(std::size_t(h))] = 1;
      mark[std::size_t(a)] = mark[std::size_t(b)] = 2;
    }
  };
  for(std::size_t added = 1; added < tips.size(); ++added) {
    cut_dijkstra(S, on_tree, dist, via);
    std::size_t next = tips.size();
    for(std::size_t k = 0; k < tips.size(); ++k)
      if(!joined[k] && (next == tips.size() || dist[std::size_t(tips[k])] < dist[std::size_t(tips[next])])) next = k;
    joined[next] = 1;
    if(in_graph[std::size_t(tips[next])]) continue;
    const bool capped = std::size_t(tips[next]) >= S.real_vertices;
    std::vector<int> start = capped ? rim[next] : std::vector<int>(1, tips[next]);
    set_mark(next, 1);
    std::vector<long> hs = fenced_path(S, start, mark);
    set_mark(next, 2);
    if(!hs.empty()) {
      add_path(hs, capped ? tips[next] : -1);
      continue;
    }
    // No fenced path: the plain shortest path to the tree.
    for(int v = tips[next]; via[std::size_t(v)] >= 0; v = S.from(std::size_t(via[std::size_t(v)]))) {
      const long h = S.twin[std::size_t(via[std::size_t(v)])];
      const int a = S.from(std::size_t(h)), b = S.to(std::size_t(h));
      parent[std::size_t(a)] = S.twin[std::size_t(h)];
      cut[S.edge(std::size_t(h))] = 1;
      in_graph[std::size_t(a)] = in_graph[std::size_t(b)] = 1;
      mark[std::size_t(a)] = mark[std::size_t(b)] = 2;
      on_tree.push_back(a);
    }
  }
  return on_tree;
}

/// The cotree of `S`: a spanning tree of the dual across the edges outside
/// the primal `tree` (flags per canonical halfedge, both).
inline std::vector<char> dual_cotree(const Closed_surface& S, const std::vector<char>& tree)
{
  std::vector<char> seen(S.faces.size(), 0), cotree(S.twin.size(), 0);
  std::vector<std::size_t> stack(1, 0);
  seen[0] = 1;
  while(!stack.empty()) {
    const std::size_t f = stack.back();
    stack.pop_back();
    for(std::size_t k = 0; k < 3; ++k) {
      const std::size_t h = 3 * f + k;
      if(tree[S.edge(h)]) continue;
      const std::size_t g = std::size_t(S.twin[h]) / 3;
      if(!seen[g]) { seen[g] = 1; cotree[S.edge(h)] = 1; stack.push_back(g); }
    }
  }
  return cotree;
}

/// Prunes from `cut` the branches that end at no tip.
inline void prune_cut(const Closed_surface& S, const std::vector<char>& is_tip, std::vector<char>& cut)
{
  const std::size_t V = S.vertices();
  std::vector<int> degree(V, 0);
  for(std::size_t h = 0; h < cut.size(); ++h)
    if(cut[h]) { ++degree[std::size_t(S.from(h))]; ++degree[std::size_t(S.to(h))]; }
  std::vector<int> leaves;
  for(std::size_t v = 0; v < V; ++v)
    if(degree[v] == 1 && !is_tip[v]) leaves.push_back(int(v));
  while(!leaves.empty()) {
    const int v = leaves.back();
    leaves.pop_back();
    if(degree[std::size_t(v)] != 1) continue;
    for(std::size_t i = S.out_begin[std::size_t(v)]; i < S.out_begin[std::size_t(v) + 1]; ++i) {
      const std::size_t e = S.edge(S.out[i]);
      if(!cut[e]) continue;
      cut[e] = 0;
      --degree[std::size_t(v)];
      const int w = S.to(S.out[i]);
      if(--degree[std::size_t(w)] == 1 && !is_tip[std::size_t(w)]) leaves.push_back(w);
      break;
    }
  }
}

/// The cut graph of the closed surface `S` through `tips` (at least one),
/// as a flag per canonical halfedge (`S.edge(h)`). Cutting along it
/// leaves one disk; with one tip and genus 0 it is empty.
inline std::vector<char> cut_graph(const Closed_surface& S, const std::vector<int>& tips)
{
  const std::size_t V = S.vertices(), H = S.twin.size();
  std::vector<char> cut(H, 0), tree(H, 0), is_tip(V, 0);
  for(int t : tips) is_tip[std::size_t(t)] = 1;
  std::vector<long> parent(V, -1); // halfedge into v from its parent, in the primal tree
  // The primal tree: the tips' tree, then shortest paths to it.
  std::vector<double> dist;
  std::vector<long> via;
  cut_dijkstra(S, join_tips(S, tips, cut, parent), dist, via);
  for(std::size_t v = 0; v < V; ++v) {
    if(parent[v] < 0) parent[v] = via[v];
    if(parent[v] >= 0) tree[S.edge(std::size_t(parent[v]))] = 1;
  }
  const std::vector<char> cotree = dual_cotree(S, tree);
  // Every edge in neither tree closes a loop through the root: the loop
  // goes into the cut with the tree paths from both its ends.
  auto to_root = [&](int v) {
    for(; parent[std::size_t(v)] >= 0; v = S.from(std::size_t(parent[std::size_t(v)]))) {
      const std::size_t e = S.edge(std::size_t(parent[std::size_t(v)]));
      if(cut[e]) break; // the rest of the way is in the cut already
      cut[e] = 1;
    }
  };
  for(std::size_t h = 0; h < H; ++h)
    if(S.edge(h) == h && !tree[h] && !cotree[h]) {
      cut[h] = 1;
      to_root(S.from(h));
      to_root(S.to(h));
    }
  prune_cut(S, is_tip, cut);
  return cut;
}

/// Shortens `cut`: where two seam edges a–b, b–c bound one real triangle
/// and b is on no other seam edge, the seam takes a–c (shorter, by the
/// triangle inequality; a tip passed through is left aside, the seam still
/// runs to the tips beyond it). Repeated until no such triangle is left.
/// Returns the number of replacements.
inline std::size_t shorten_cut(const Closed_surface& S, std::vector<char>& cut)
{
  const std::size_t V = S.vertices();
  std::vector<int> degree(V, 0);
  for(std::size_t h = 0; h < cut.size(); ++h)
    if(cut[h]) { ++degree[std::size_t(S.from(h))]; ++degree[std::size_t(S.to(h))]; }
  auto real_edge = [&](std::size_t h) { return std::size_t(S.twin[h]) / 3 < S.real_faces; };
  std::size_t replaced = 0;
  for(bool changed = true; changed;) {
    changed = false;
    for(std::size_t f = 0; f < S.real_faces; ++f)
      for(std::size_t k = 0; k < 3; ++k) {
        // b is corner k: its edges are the incoming prev and the outgoing 3f + k.
        const std::size_t hin = prev_in_face(3 * f + k), hout = 3 * f + k, third = next_in_face(3 * f + k);
        const std::size_t b = std::size_t(S.faces[f][k]);
        if(!cut[S.edge(hin)] || !cut[S.edge(hout)] || cut[S.edge(third)]) continue;
        if(degree[b] != 2 || !real_edge(hin) || !real_edge(hout) || !real_edge(third)) continue;
        cut[S.edge(hin)] = cut[S.edge(hout)] = 0;
        cut[S.edge(third)] = 1;
        degree[b] = 0;
        ++replaced;
        changed = true;
      }
  }
  return replaced;
}

/// The real triangles of `S` whose three corners lie on the cut or on a
/// border (a rim of a cap): after the cut, each has three border corners.
inline std::vector<std::size_t> cut_tbc_faces(const Closed_surface& S, const std::vector<char>& cut)
{
  std::vector<char> on(S.vertices(), 0);
  for(std::size_t h = 0; h < cut.size(); ++h) {
    const bool virtual_edge = std::size_t(S.to(h)) >= S.real_vertices;
    if(cut[S.edge(h)] || virtual_edge) on[std::size_t(S.from(h))] = 1;
  }
  std::vector<std::size_t> out;
  for(std::size_t f = 0; f < S.real_faces; ++f)
    if(on[std::size_t(S.faces[f][0])] && on[std::size_t(S.faces[f][1])] && on[std::size_t(S.faces[f][2])]) out.push_back(f);
  return out;
}

/// Whether cutting `P` along `cut` (of its closed surface `S`) leaves one disk.
inline bool cut_leaves_disk(const Atlas_piece& P, const std::vector<long>& twin, const Closed_surface& S,
                            const std::vector<char>& cut)
{
  std::vector<char> seam(twin.size(), 0);
  for(std::size_t h = 0; h < twin.size(); ++h) seam[h] = twin[h] >= 0 && cut[S.edge(h)];
  Atlas_piece opened = P;
  const std::vector<long> t0 = twin;
  open_along(opened, t0, seam);
  std::vector<long> t = halfedge_twins(opened.faces);
  std::vector<int> component;
  if(face_components(opened.faces, t, component) != 1) return false;
  return piece_topology(opened, t).disk();
}

/// Removes the cut edges at the vertices of `window` and joins their loose
/// ends again by fenced paths (`fenced_path()`): the first end is the seam,
/// the rest of the cut and the rims are fenced off. False if some end
/// cannot be joined.
inline bool reroute_window(const Closed_surface& S, const std::vector<int>& window, std::vector<char>& trial)
{
  std::vector<char> removed_at(S.vertices(), 0);
  for(int c : window)
    for(std::size_t i = S.out_begin[std::size_t(c)]; i < S.out_begin[std::size_t(c) + 1]; ++i) {
      const std::size_t h = S.out[i];
      if(trial[S.edge(h)] && std::size_t(S.to(h)) < S.real_vertices) {
        trial[S.edge(h)] = 0;
        removed_at[std::size_t(c)] = removed_at[std::size_t(S.to(h))] = 1;
      }
    }
  std::vector<int> degree(S.vertices(), 0);
  for(std::size_t h = 0; h < trial.size(); ++h)
    if(trial[h] && S.edge(h) == h) { ++degree[std::size_t(S.from(h))]; ++degree[std::size_t(S.to(h))]; }
  std::vector<int> ends;
  for(std::size_t v = 0; v < S.vertices(); ++v)
    if(removed_at[v] && degree[v] > 0) ends.push_back(int(v));
  if(ends.size() < 2) return false;
  std::vector<char> mark(S.vertices(), 0);
  for(std::size_t h = 0; h < trial.size(); ++h)
    if(trial[S.edge(h)] || std::size_t(S.to(h)) >= S.real_vertices) mark[std::size_t(S.from(h))] = 3;
  for(std::size_t v = S.real_vertices; v < S.vertices(); ++v) mark[v] = 3;
  mark[std::size_t(ends[0])] = 2;
  for(std::size_t k = 1; k < ends.size(); ++k) {
    if(mark[std::size_t(ends[k])] == 2) continue;
    mark[std::size_t(ends[k])] = 1;
    const std::vector<long> path = fenced_path(S, { ends[k] }, mark);
    if(path.empty()) return false;
    for(long h : path) {
      trial[S.edge(std::size_t(h))] = 1;
      mark[std::size_t(S.from(std::size_t(h)))] = mark[std::size_t(S.to(std::size_t(h)))] = 2;
    }
  }
  return true;
}

/// Reroutes the cut around each triangle that it would leave with three
/// border corners: the cut edges at the triangle's corners are removed and
/// their loose ends joined again by fenced paths (`fenced_path()`), which
/// keep a triangle between seams. A change is kept only if the cut still
/// leaves one disk and fewer such triangles. Returns the triangles left.
inline std::size_t repair_cut(const Atlas_piece& P, const std::vector<long>& twin, const Closed_surface& S,
                              std::vector<char>& cut)
{
  std::vector<std::size_t> bad = cut_tbc_faces(S, cut);
  std::vector<char> tried(S.real_faces, 0);
  for(std::size_t round = 0; round < 16 * bad.size() + 8 && !bad.empty(); ++round) {
    std::size_t f = S.real_faces;
    for(std::size_t g : bad)
      if(!tried[g]) { f = g; break; }
    if(f == S.real_faces) break;
    tried[f] = 1;
    bool fixed = false;
    // Windows of growing size around the triangle: its corners, then their
    // neighbours, then theirs.
    std::vector<int> window(S.faces[f].begin(), S.faces[f].end());
    for(int radius = 1; radius <= 5 && !fixed; ++radius) {
      if(radius > 1) {
        const std::vector<int> inner = window;
        for(int c : inner)
          for(std::size_t i = S.out_begin[std::size_t(c)]; i < S.out_begin[std::size_t(c) + 1]; ++i)
            if(std::size_t(S.to(S.out[i])) < S.real_vertices) window.push_back(S.to(S.out[i]));
        std::sort(window.begin(), window.end());
        window.erase(std::unique(window.begin(), window.end()), window.end());
      }
      std::vector<char> trial = cut;
      if(!reroute_window(S, window, trial)) continue;
      shorten_cut(S, trial);
      const std::vector<std::size_t> now = cut_tbc_faces(S, trial);
      if(now.size() < bad.size() && cut_leaves_disk(P, twin, S, trial)) {
        cut.swap(trial);
        bad = now;
        fixed = true;
      }
    }
    if(fixed) std::fill(tried.begin(), tried.end(), 0); // the cut changed: the others may be fixable now
  }
  return bad.size();
}

/// The seam of a connected piece that is not a disk nor a genus-0 piece with
/// holes: per halfedge of `P`, whether it is cut (both halves flagged).
/// Closed pieces are cut through `tips` tips (at least 2); pieces with
/// holes and handles through their holes. `seam_length` receives the 3D
/// length of the seam's edges.
inline std::vector<char> piece_seam(const Atlas_piece& P, const std::vector<long>& twin, const Piece_topology& T,
                                    std::size_t tips_wanted, double& seam_length)
{
  const Closed_surface S = close_surface(P, T);
  std::vector<int> tips;
  if(T.loops.empty()) tips = piece_tips(S, (std::max)(std::size_t(2), tips_wanted));
  else
    for(std::size_t l = 0; l < T.loops.size(); ++l) tips.push_back(int(S.real_vertices + l));
  std::vector<char> cut = cut_graph(S, tips);
  shorten_cut(S, cut);
  repair_cut(P, twin, S, cut);
  std::vector<char> seam(twin.size(), 0);
  seam_length = 0;
  for(std::size_t h = 0; h < twin.size(); ++h)
    if(twin[h] >= 0 && cut[S.edge(h)]) {
      seam[h] = 1;
      if(std::size_t(twin[h]) > h) seam_length += S.length[h];
    }
  return seam;
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
