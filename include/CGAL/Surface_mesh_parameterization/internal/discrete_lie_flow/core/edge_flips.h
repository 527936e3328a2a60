// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Lawson flips of a planar triangulation to Delaunay (paper mode), decided
// by exact predicates: an interior edge is flipped when the opposite vertex
// lies strictly inside the circumcircle and the quad is strictly convex.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_EDGE_FLIPS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_EDGE_FLIPS_H

#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/certification.h>

#include <algorithm>
#include <map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// A triangulation with twin pointers: halfedge 3f+k is the edge of face f
/// opposite to its corner k, from corner k+1 to corner k+2; twin[h] is the
/// opposite halfedge, −1 on the boundary.
struct Flip_triangulation
{
  std::vector<Face> faces;
  std::vector<int> twin;

  explicit Flip_triangulation(const std::vector<Face>& f) : faces(f), twin(3 * f.size(), -1)
  {
    std::map<std::pair<int, int>, int> open;
    for(std::size_t t = 0; t < faces.size(); ++t)
      for(int k = 0; k < 3; ++k) {
        const int a = faces[t][(k + 1) % 3], b = faces[t][(k + 2) % 3];
        const auto it = open.find(std::make_pair(b, a));
        if(it != open.end()) {
          twin[3 * t + k] = it->second;
          twin[it->second] = int(3 * t + k);
          open.erase(it);
        } else {
          open.emplace(std::make_pair(a, b), int(3 * t + k));
        }
      }
  }

  bool is_locally_delaunay(const std::vector<Vec2>& uv, int h) const
  {
    const int o = twin[h];
    if(o < 0) return true;
    const int f = h / 3, k = h % 3, g = o / 3, m = o % 3;
    typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_2 P;
    auto pt = [&](int v) { return P(uv[v][0], uv[v][1]); };
    const int a = faces[f][k], b = faces[f][(k + 1) % 3], c = faces[f][(k + 2) % 3], d = faces[g][m];
    if(CGAL::side_of_oriented_circle(pt(a), pt(b), pt(c), pt(d)) != CGAL::ON_POSITIVE_SIDE) return true;
    // Only a strictly convex quad can be flipped.
    return !(CGAL::orientation(pt(a), pt(b), pt(d)) == CGAL::POSITIVE &&
             CGAL::orientation(pt(a), pt(d), pt(c)) == CGAL::POSITIVE);
  }

  /// Flips halfedge h = (f, k) with twin (g, m): faces (a, b, c) and (d, c, b)
  /// become (a, b, d) and (a, d, c). Calls on_change(f) and on_change(g).
  template <class OnChange>
  void flip(int h, OnChange on_change)
  {
    const int o = twin[h];
    const int f = h / 3, k = h % 3, g = o / 3, m = o % 3;
    const int a = faces[f][k], b = faces[f][(k + 1) % 3], c = faces[f][(k + 2) % 3], d = faces[g][m];
    // outer halfedges: b→c... names by the edges they carry
    const int t_ab = twin[3 * f + (k + 2) % 3]; // edge a→b of f (opposite c)
    const int t_ca = twin[3 * f + (k + 1) % 3]; // edge c→a of f (opposite b)
    const int t_db = twin[3 * g + (m + 1) % 3]; // in g = (d, c, b): edge b→d (opposite c)
    const int t_cd = twin[3 * g + (m + 2) % 3]; // edge d→c (opposite b)
    faces[f] = {{ a, b, d }}; // halfedges: 0: b→d, 1: d→a, 2: a→b
    faces[g] = {{ a, d, c }}; // halfedges: 0: d→c, 1: c→a, 2: a→d
    auto link = [&](int x, int y) { twin[x] = y; if(y >= 0) twin[y] = x; };
    link(3 * f + 0, t_db);
    link(3 * f + 1, 3 * g + 2);
    link(3 * f + 2, t_ab);
    link(3 * g + 0, t_cd);
    link(3 * g + 1, t_ca);
    on_change(f);
    on_change(g);
  }

  /// Lawson flips until every interior edge is locally Delaunay (bounded by
  /// `max_flips`, which exact predicates never reach on a valid triangulation).
  template <class OnChange>
  std::size_t make_delaunay(const std::vector<Vec2>& uv, OnChange on_change, std::size_t max_flips)
  {
    std::vector<int> stack;
    for(int h = 0; h < int(twin.size()); ++h)
      if(twin[h] > h) stack.push_back(h);
    std::size_t flips = 0;
    while(!stack.empty() && flips < max_flips) {
      const int h = stack.back();
      stack.pop_back();
      if(is_locally_delaunay(uv, h)) continue;
      const int f = h / 3, g = twin[h] / 3;
      flip(h, on_change);
      ++flips;
      for(int e : { 3 * f + 0, 3 * f + 2, 3 * g + 0, 3 * g + 1 })
        if(twin[e] >= 0) stack.push_back(e);
    }
    return flips;
  }
};

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
