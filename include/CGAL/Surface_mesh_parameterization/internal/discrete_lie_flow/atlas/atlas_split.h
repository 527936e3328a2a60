// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Splitting a poor chart in two: the faces nearer (geodesically) to one of
// two far-apart seeds than to the other, the interface then smoothed so
// that no triangle is left with two interface edges or with all three
// corners on the interface (such triangles would have three border
// corners in their chart, the flow's floor).

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

/// The pieces of `P` on either side of `split_labels()`, one per connected part.
inline std::vector<Atlas_piece> split_piece(const Atlas_piece& P, const std::vector<long>& twin)
{
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
