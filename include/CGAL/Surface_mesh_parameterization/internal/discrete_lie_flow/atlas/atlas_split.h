// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Splitting a poor chart in two. First choice: a cut along a fenced
// shortest path (atlas_cut_graph.h) between the two points of the outer
// border where the geodesic bisector of two far-apart seeds meets it, so
// that no triangle gets three border corners. Where no such path exists:
// the faces nearer to one seed than to the other, the interface smoothed
// so that no triangle has two interface edges or all three corners on
// borders, islands joined to their side.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_ATLAS_SPLIT_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_ATLAS_SPLIT_H

#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/atlas/atlas_cut_graph.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/atlas/atlas_mesh.h>

#include <algorithm>
#include <limits>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// Labels 0 / 1 per face of the connected piece `P`: a geodesic Voronoi
/// split between two far-apart vertices, smoothed.
inline std::vector<char> split_labels(const Atlas_piece& P, const std::vector<long>& twin)
{
  // Distances on the piece's own edges: the caps of its holes are not crossed.
  Closed_surface S = close_surface(P, piece_topology(P, twin));
  for(std::size_t h = 0; h < S.length.size(); ++h)
    if(std::size_t(S.from(h)) >= S.real_vertices || std::size_t(S.to(h)) >= S.real_vertices)
      S.length[h] = std::numeric_limits<double>::infinity();
  std::vector<double> d0, d1;
  std::vector<long> via;
  cut_dijkstra(S, { P.faces[0][0] }, d0, via);
  auto farthest = [&S](const std::vector<double>& d) {
    int best = 0;
    for(std::size_t v = 0; v < S.real_vertices; ++v)
      if(std::isfinite(d[v]) && d[v] > d[std::size_t(best)]) best = int(v);
    return best;
  };
  const int a = farthest(d0);
  cut_dijkstra(S, { a }, d0, via);
  const int b = farthest(d0);
  cut_dijkstra(S, { b }, d1, via);
  const std::size_t F = P.faces.size();
  std::vector<char> label(F, 0);
  for(std::size_t f = 0; f < F; ++f) {
    double s0 = 0, s1 = 0;
    for(int v : P.faces[f]) { s0 += d0[std::size_t(v)]; s1 += d1[std::size_t(v)]; }
    label[f] = s1 < s0 ? 1 : 0;
  }
  // Smooth: a face with two neighbours across of the other label joins
  // them; a face with all corners on the interface too. Each change moves
  // a face to the side it borders most; a few passes settle it.
  for(int pass = 0; pass < 20; ++pass) {
    // Corners on the interface or on the piece's border are border corners of a half.
    std::vector<char> on_interface(P.xyz.size(), 0);
    for(std::size_t h = 0; h < twin.size(); ++h)
      if(twin[h] < 0 || label[h / 3] != label[std::size_t(twin[h]) / 3]) {
        on_interface[std::size_t(P.faces[h / 3][h % 3])] = 1;
        on_interface[std::size_t(P.faces[h / 3][(h % 3 + 1) % 3])] = 1;
      }
    bool changed = false;
    for(std::size_t f = 0; f < F; ++f) {
      int other = 0, corners = 0;
      for(std::size_t k = 0; k < 3; ++k) {
        const long o = twin[3 * f + k];
        if(o >= 0 && label[std::size_t(o) / 3] != label[f]) ++other;
        if(on_interface[std::size_t(P.faces[f][k])]) ++corners;
      }
      if(other >= 2 || (other >= 1 && corners == 3)) { label[f] = char(1 - label[f]); changed = true; }
    }
    if(!changed) break;
  }
  // Islands: every connected part of a side but its largest joins the other side.
  for(int pass = 0; pass < 4; ++pass) {
    std::vector<int> part(F, -1);
    std::vector<std::size_t> size;
    std::vector<std::size_t> stack;
    for(std::size_t f0 = 0; f0 < F; ++f0) {
      if(part[f0] >= 0) continue;
      part[f0] = int(size.size());
      size.push_back(0);
      stack.assign(1, f0);
      while(!stack.empty()) {
        const std::size_t f = stack.back();
        stack.pop_back();
        ++size.back();
        for(std::size_t k = 0; k < 3; ++k) {
          const long o = twin[3 * f + k];
          if(o >= 0 && part[std::size_t(o) / 3] < 0 && label[std::size_t(o) / 3] == label[f]) {
            part[std::size_t(o) / 3] = part[f0];
            stack.push_back(std::size_t(o) / 3);
          }
        }
      }
    }
    std::size_t biggest[2] = { 0, 0 };
    int keep[2] = { -1, -1 };
    for(std::size_t f = 0; f < F; ++f) {
      const int side = label[f];
      if(size[std::size_t(part[f])] > biggest[side]) { biggest[side] = size[std::size_t(part[f])]; keep[side] = part[f]; }
    }
    bool changed = false;
    for(std::size_t f = 0; f < F; ++f)
      if(part[f] != keep[int(label[f])]) { label[f] = char(1 - label[f]); changed = true; }
    if(!changed) break;
  }
  return label;
}

/// A cut of the piece `P` (a disk, or genus 0 with holes) along a fenced
/// path across its outer border, between the points where the geodesic
/// bisector of two far-apart vertices meets it; per halfedge, empty if none.
inline std::vector<char> chord_seam(const Atlas_piece& P, const std::vector<long>& twin)
{
  const Piece_topology T = piece_topology(P, twin);
  if(T.loops.empty()) return std::vector<char>();
  const Closed_surface S = close_surface(P, T);
  Closed_surface D = S; // distances on the piece's own edges
  for(std::size_t h = 0; h < D.length.size(); ++h)
    if(std::size_t(D.from(h)) >= D.real_vertices || std::size_t(D.to(h)) >= D.real_vertices)
      D.length[h] = std::numeric_limits<double>::infinity();
  std::vector<double> d0, d1;
  std::vector<long> via;
  cut_dijkstra(D, { P.faces[0][0] }, d0, via);
  auto farthest = [&D](const std::vector<double>& d) {
    int best = 0;
    for(std::size_t v = 0; v < D.real_vertices; ++v)
      if(std::isfinite(d[v]) && d[v] > d[std::size_t(best)]) best = int(v);
    return best;
  };
  const int p = farthest(d0);
  cut_dijkstra(D, { p }, d0, via);
  const int q = farthest(d0);
  cut_dijkstra(D, { q }, d1, via);
  // The outer (longest) loop, and where d0 − d1 changes sign along it.
  std::size_t outer = 0;
  double longest = -1;
  for(std::size_t l = 0; l < T.loops.size(); ++l) {
    double len = 0;
    for(std::size_t h : T.loops[l]) len += S.length[h];
    if(len > longest) { longest = len; outer = l; }
  }
  const std::vector<std::size_t>& loop = T.loops[outer];
  // Where d0 − d1 changes sign along the loop: the two changes (one each
  // way) farthest apart along it.
  std::vector<long> up, down;
  for(std::size_t k = 0; k < loop.size(); ++k) {
    const int u = P.faces[loop[k] / 3][loop[k] % 3], w = P.faces[loop[k] / 3][(loop[k] % 3 + 1) % 3];
    const double fu = d0[std::size_t(u)] - d1[std::size_t(u)], fw = d0[std::size_t(w)] - d1[std::size_t(w)];
    if(fu < 0 && fw >= 0) up.push_back(long(k));
    if(fu >= 0 && fw < 0) down.push_back(long(k));
  }
  long ka = -1, kb = -1, apart = -1;
  const long n = long(loop.size());
  for(long i : up)
    for(long j : down) {
      const long d = (std::min)(std::abs(i - j), n - std::abs(i - j));
      if(d > apart) { apart = d; ka = i; kb = j; }
    }
  if(ka < 0 || n < 12) return std::vector<char>();
  // From the border vertices near the first place to those near the second
  // (a path can leave a border vertex only between two triangles whose third
  // corners are inside), fenced off every other border vertex and the caps.
  std::vector<char> mark(S.vertices(), 0);
  for(std::size_t h = 0; h < S.twin.size(); ++h)
    if(std::size_t(S.to(h)) >= S.real_vertices) mark[std::size_t(S.from(h))] = 3;
  for(std::size_t v = S.real_vertices; v < S.vertices(); ++v) mark[v] = 3;
  const long window = (std::min)(8L, apart / 3);
  std::vector<int> start;
  for(long d = -window; d <= window; ++d) {
    const std::size_t ha = loop[std::size_t(((ka + d) % n + n) % n)], hb = loop[std::size_t(((kb + d) % n + n) % n)];
    const int va = P.faces[ha / 3][ha % 3], vb = P.faces[hb / 3][hb % 3];
    if(mark[std::size_t(va)] == 3) { mark[std::size_t(va)] = 1; start.push_back(va); }
    if(mark[std::size_t(vb)] == 3) mark[std::size_t(vb)] = 2;
  }
  // Along the bisector: an edge costs more the farther it is from it.
  Closed_surface B = S;
  const double diameter = d0[std::size_t(q)];
  for(std::size_t h = 0; h < B.length.size(); ++h) {
    const std::size_t u = std::size_t(B.from(h)), w = std::size_t(B.to(h));
    if(u < B.real_vertices && w < B.real_vertices)
      B.length[h] *= 1 + 20 * std::abs(d0[u] - d1[u] + d0[w] - d1[w]) / (2 * diameter);
  }
  const std::vector<long> path = fenced_path(B, start, mark);
  if(path.empty()) return std::vector<char>();
  std::vector<char> seam(twin.size(), 0);
  for(long h : path) {
    if(twin[std::size_t(h)] < 0) return std::vector<char>();
    seam[std::size_t(h)] = seam[std::size_t(twin[std::size_t(h)])] = 1;
  }
  return seam;
}

/// The pieces of `P` on either side of a chord (`chord_seam()`), else of
/// `split_labels()`, one per connected part.
inline std::vector<Atlas_piece> split_piece(const Atlas_piece& P, const std::vector<long>& twin)
{
  const std::vector<char> chord = chord_seam(P, twin);
  if(!chord.empty()) {
    Atlas_piece opened = P;
    open_along(opened, twin, chord);
    std::vector<Atlas_piece> parts = split_components(opened);
    std::size_t smallest = P.faces.size();
    for(const Atlas_piece& part : parts) smallest = (std::min)(smallest, part.faces.size());
    if(parts.size() >= 2 && smallest * 100 >= 15 * P.faces.size()) return parts; // else: a corner, not a half
  }
  const std::vector<char> label = split_labels(P, twin);
  std::vector<Atlas_piece> out;
  for(char side = 0; side < 2; ++side) {
    std::vector<std::size_t> keep;
    for(std::size_t f = 0; f < label.size(); ++f)
      if(label[f] == side) keep.push_back(f);
    if(keep.empty()) continue;
    for(Atlas_piece& part : split_components(sub_piece(P, keep))) out.push_back(std::move(part));
  }
  return out;
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
