// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Edge-split vertices of a closed mesh: a vertex of degree 4 lying on the
// straight 3D segment between two opposite neighbours is the split point of
// that segment (triangle strips converted to triangles, T-junctions closed by
// a CAD mesher, fans of needles). Removing it and restoring the segment as an
// edge (its four faces become two, their targets summed) gives a coarser
// mesh with the same shape and the same target measure. A map of the coarse
// mesh is prolongated by putting each removed vertex back on the great-circle
// arc between the images of its two neighbours, at the fraction of the
// segment its faces' targets give: each face keeps its orientation (it is a
// positive part of a positive coarse face) and, to second order, its share.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_SPHERE_SPLIT_VERTICES_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_SPHERE_SPLIT_VERTICES_H

#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/geometry.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/sphere/sphere_problem.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// When the certified flow starts from the coarse mesh (`sphere_map.h`).
struct Split_vertex_settings
{
  /// The sine of the largest angle between a split vertex's two spokes and
  /// a straight line (0.2: about 11.5°). Exact edge splits are straight up
  /// to rounding; split points moved off their edges (a scanner's noise, a
  /// smoothing pass) are nearly straight and slow the flow just as much.
  /// The coarse mesh then only approximates the shape, which costs nothing
  /// in certainty: the prolongated map is certified or not used, and the
  /// fine flow corrects the shares (doc/sphere.md, "Edge-split vertices").
  double sin_tolerance = 0.2;
  /// Coarsen only when at least this fraction of the vertices go: a few
  /// split vertices do not slow the flow, and the coarse flow is paid in full.
  double least_fraction = 0.1;
};

/// A removed edge-split vertex `v`: it lies on the segment from `a` to `b`, at
/// the fraction `t` of it from `a` by its faces' targets.
struct Split_vertex
{
  int v = -1, a = -1, b = -1;
  double t = 0.5;
};

/// The coarse problem of `coarsen_split_vertices()` and how to prolongate.
struct Split_vertex_coarsening
{
  Sphere_problem coarse;              ///< the remaining vertices, renumbered; summed targets
  std::vector<int> coarse_index;      ///< per fine vertex: its coarse index, or −1 if removed
  std::vector<Split_vertex> removed;  ///< in removal order (prolongation goes backwards)
};

/// The ring of the degree-4 vertex `v` from its four faces `inc`,
/// counter-clockwise (face (v, x, y) links x to y): `face_of[r]` is the face
/// (v, ring[r], ring[r + 1]). False when the faces do not close one ring of
/// four distinct vertices.
inline bool degree_four_ring(const std::vector<Face>& faces, const std::vector<int>& inc, int v,
                             std::array<int, 4>& ring, std::array<int, 4>& face_of)
{
  std::array<int, 4> x, y;
  for(std::size_t i = 0; i < 4; ++i) {
    const Face& t = faces[std::size_t(inc[i])];
    const int k = t[0] == v ? 0 : (t[1] == v ? 1 : 2);
    x[i] = t[(k + 1) % 3];
    y[i] = t[(k + 2) % 3];
  }
  ring[0] = x[0];
  face_of[0] = inc[0];
  for(std::size_t r = 1; r < 4; ++r) {
    const std::size_t i = std::size_t(std::find(x.begin(), x.end(), ring[r - 1]) - x.begin());
    if(i == 4) return false;
    ring[r] = y[i];
    const std::size_t j = std::size_t(std::find(x.begin(), x.end(), ring[r]) - x.begin());
    if(j == 4) return false;
    face_of[r] = inc[j];
  }
  if(y[std::size_t(std::find(x.begin(), x.end(), ring[3]) - x.begin())] != ring[0]) return false;
  for(std::size_t i = 0; i < 4; ++i)
    for(std::size_t j = i + 1; j < 4; ++j)
      if(ring[i] == ring[j]) return false;
  return true;
}

/// The coarse problem left by the removals: the vertices of `P` not
/// `removed`, renumbered (`out.coarse_index`), and the `alive` faces with
/// their targets.
inline void coarse_split_problem(const Sphere_problem& P, const std::vector<Face>& faces,
                                 const std::vector<double>& target, const std::vector<char>& alive,
                                 const std::vector<char>& removed, Split_vertex_coarsening& out)
{
  out.coarse_index.assign(P.xyz.size(), -1);
  int m = 0;
  for(std::size_t v = 0; v < P.xyz.size(); ++v)
    if(!removed[v]) {
      out.coarse_index[v] = m++;
      out.coarse.xyz.push_back(P.xyz[v]);
    }
  for(std::size_t f = 0; f < faces.size(); ++f)
    if(alive[f]) {
      const Face& t = faces[f];
      out.coarse.faces.push_back(Face{{ out.coarse_index[std::size_t(t[0])], out.coarse_index[std::size_t(t[1])],
                                        out.coarse_index[std::size_t(t[2])] }});
      out.coarse.target.push_back(target[f]);
    }
}

/// Removes edge-split vertices of `P` (targets filled) while there are any:
/// degree 4, the two spokes to one pair of opposite neighbours at an angle
/// within `sin_tolerance` (its sine) of π, and those two neighbours not
/// already joined by an edge (the coarse mesh stays a closed manifold of the
/// same genus). A vertex whose neighbour was removed is looked at again, so
/// a segment split at several points loses all of them.
inline Split_vertex_coarsening coarsen_split_vertices(const Sphere_problem& P,
                                                      double sin_tolerance = Split_vertex_settings().sin_tolerance)
{
  const std::size_t n = P.xyz.size();
  std::vector<Face> faces = P.faces;
  std::vector<double> target = P.target;
  std::vector<char> alive(faces.size(), 1), removed(n, 0);
  std::vector<std::vector<int> > incident(n);
  for(std::size_t f = 0; f < faces.size(); ++f)
    for(int k = 0; k < 3; ++k) incident[std::size_t(faces[f][k])].push_back(int(f));
  Split_vertex_coarsening out;
  auto try_remove = [&](int v) {
    std::vector<int>& inc = incident[std::size_t(v)];
    inc.erase(std::remove_if(inc.begin(), inc.end(), [&alive](int f) { return !alive[std::size_t(f)]; }), inc.end());
    if(inc.size() != 4) return false;
    std::array<int, 4> ring, face_of;
    if(!degree_four_ring(faces, inc, v, ring, face_of)) return false;
    // face_of[r] is (v, ring[r], ring[r + 1]). Which opposite pair is straight?
    const Vec3& pv = P.xyz[std::size_t(v)];
    auto straight = [&](int a, int b) {
      const Vec3 u = sub(P.xyz[std::size_t(a)], pv), w = sub(P.xyz[std::size_t(b)], pv);
      return dot(u, w) < 0 && norm3(cross(u, w)) <= sin_tolerance * norm3(u) * norm3(w);
    };
    std::size_t s = 4;
    if(straight(ring[0], ring[2])) s = 0;
    else if(straight(ring[1], ring[3])) s = 1;
    if(s == 4) return false;
    const int n0 = ring[s], n1 = ring[s + 1], n2 = ring[(s + 2) % 4], n3 = ring[(s + 3) % 4];
    for(int f : incident[std::size_t(n0)]) {
      if(!alive[std::size_t(f)]) continue;
      const Face& t = faces[std::size_t(f)];
      if(t[0] == n2 || t[1] == n2 || t[2] == n2) return false; // n0 n2 is an edge already
    }
    const double T01 = target[std::size_t(face_of[s])], T12 = target[std::size_t(face_of[s + 1])];
    const double T23 = target[std::size_t(face_of[(s + 2) % 4])], T30 = target[std::size_t(face_of[(s + 3) % 4])];
    Split_vertex sv;
    sv.v = v;
    sv.a = n0;
    sv.b = n2;
    sv.t = 0.5 * (T01 / (T01 + T12) + T30 / (T30 + T23));
    out.removed.push_back(sv);
    for(int f : face_of) alive[std::size_t(f)] = 0;
    removed[std::size_t(v)] = 1;
    const Face halves[2] = { Face{{ n0, n1, n2 }}, Face{{ n0, n2, n3 }} };
    const double sums[2] = { T01 + T12, T23 + T30 };
    for(int h = 0; h < 2; ++h) {
      const int id = int(faces.size());
      faces.push_back(halves[h]);
      target.push_back(sums[h]);
      alive.push_back(1);
      for(int k = 0; k < 3; ++k) incident[std::size_t(halves[h][k])].push_back(id);
    }
    return true;
  };
  std::vector<int> queue;
  for(std::size_t v = n; v-- > 0; ) queue.push_back(int(v));
  while(!queue.empty()) {
    const int v = queue.back();
    queue.pop_back();
    if(removed[std::size_t(v)]) continue;
    const std::size_t before = out.removed.size();
    if(!try_remove(v)) continue;
    const Split_vertex& sv = out.removed[before];
    // Its neighbours' rings changed: look at them again.
    for(int f : incident[std::size_t(sv.a)])
      if(alive[std::size_t(f)])
        for(int k = 0; k < 3; ++k) queue.push_back(faces[std::size_t(f)][k]);
  }
  coarse_split_problem(P, faces, target, alive, removed, out);
  return out;
}

/// The fine map from the coarse one `q` (`coarse_index` order): each removed
/// vertex back on the chord between its neighbours' images at its fraction,
/// projected onto the sphere (on their great-circle arc), the last removed
/// first (its neighbours are then all placed).
inline std::vector<Vec3> prolongate_split_vertices(const Split_vertex_coarsening& c, const std::vector<Vec3>& q)
{
  std::vector<Vec3> p(c.coarse_index.size(), Vec3{{ 0, 0, 0 }});
  for(std::size_t v = 0; v < p.size(); ++v)
    if(c.coarse_index[v] >= 0) p[v] = q[std::size_t(c.coarse_index[v])];
  for(std::size_t i = c.removed.size(); i-- > 0; ) {
    const Split_vertex& s = c.removed[i];
    const Vec3 &a = p[std::size_t(s.a)], &b = p[std::size_t(s.b)];
    p[std::size_t(s.v)] = normalized(Vec3{{ (1 - s.t) * a[0] + s.t * b[0], (1 - s.t) * a[1] + s.t * b[1],
                                            (1 - s.t) * a[2] + s.t * b[2] }});
  }
  return p;
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
