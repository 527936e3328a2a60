// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The coarse levels of a disk for the coarse-to-fine flow: each level
// removes an independent set of interior vertices by half-edge collapses
// that keep the border, the topology and the start map fold-free; the
// removed faces' targets go to their neighbours, so every level carries the
// whole target area. doc/coarse_to_fine.md says why each rule is there.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_DISK_HIERARCHY_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_DISK_HIERARCHY_H

#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/certification.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/geometry.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/vertex_relaxation.h>

#include <algorithm>
#include <cstdint>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// The vertices one level removed from the level above, each with its ring
/// there: counter-clockwise, the collapse's target first. The star of a
/// removed vertex v in the level above is {(v, ring[i], ring[i+1])}.
struct Disk_decimation
{
  std::vector<int> removed;
  std::vector<std::size_t> ring_first{ 0 }; ///< CSR offsets into `ring`
  std::vector<int> ring;
};

/// One coarse level: faces in the finest level's vertex numbering, and
/// their targets (the sum of the targets of the finer faces they replace).
struct Disk_level
{
  std::vector<Face> faces;
  std::vector<double> target;
  Disk_decimation from_above; ///< how this level was made from the finer one
};

/// The ring of interior vertex `v` (counter-clockwise, as its star's faces
/// run), or false when the star is not one closed fan of at most `most` faces.
inline bool vertex_ring(const Vertex_faces& around, const std::vector<Face>& faces, std::size_t v, std::size_t most,
                        std::vector<int>& ring)
{
  const std::size_t begin = around.first[v], end = around.first[v + 1], k = end - begin;
  ring.clear();
  if(k < 3 || k > most) return false;
  int a[32], b[32];
  for(std::size_t i = 0; i < k; ++i) {
    const Face& f = faces[around.of[begin + i].first];
    const int c = around.of[begin + i].second;
    a[i] = f[(c + 1) % 3];
    b[i] = f[(c + 2) % 3];
  }
  int cur = a[0];
  for(std::size_t step = 0; step < k; ++step) {
    ring.push_back(cur);
    std::size_t i = 0;
    while(i < k && a[i] != cur) ++i;
    if(i == k) return false;
    cur = b[i];
  }
  if(cur != a[0]) return false;
  std::vector<int> sorted(ring);
  std::sort(sorted.begin(), sorted.end());
  return std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end();
}

/// Whether the edge (w, x) is one of the level's faces' edges.
inline bool level_has_edge(const Vertex_faces& around, const std::vector<Face>& faces, int w, int x)
{
  for(std::size_t i = around.first[std::size_t(w)]; i < around.first[std::size_t(w) + 1]; ++i) {
    const Face& f = faces[around.of[i].first];
    if(f[0] == x || f[1] == x || f[2] == x) return true;
  }
  return false;
}

/// The faces of the level made by the collapses `v` → `into[v]` (−1: kept)
/// of `out.from_above`: the faces with the target as a corner go; the
/// others of the star keep their shape in the ring with v moved onto the
/// target, and share out the targets of the two that went.
inline void collapse_level_faces(const std::vector<Face>& faces, const std::vector<double>& target,
                                 const std::vector<int>& into, Disk_level& out)
{
  const Disk_decimation& D = out.from_above;
  std::vector<double> dropped(into.size(), 0);
  std::vector<int> owner;
  out.faces.clear();
  out.target.clear();
  for(std::size_t f = 0; f < faces.size(); ++f) {
    Face t = faces[f];
    int corner = -1;
    for(int c = 0; c < 3; ++c) if(into[std::size_t(t[c])] >= 0) corner = c;
    if(corner < 0) { out.faces.push_back(t); out.target.push_back(target[f]); owner.push_back(-1); continue; }
    const int v = t[corner], w = into[std::size_t(v)];
    if(t[0] == w || t[1] == w || t[2] == w) { dropped[std::size_t(v)] += target[f]; continue; }
    t[corner] = w;
    out.faces.push_back(t);
    out.target.push_back(target[f]);
    owner.push_back(v);
  }
  for(std::size_t r = 0; r < D.removed.size(); ++r) {
    const std::size_t v = std::size_t(D.removed[r]);
    dropped[v] /= double(D.ring_first[r + 1] - D.ring_first[r] - 2); // the faces left of its star
  }
  for(std::size_t f = 0; f < out.faces.size(); ++f)
    if(owner[f] >= 0) out.target[f] += dropped[std::size_t(owner[f])];
}

/// Makes the next coarser level of (`faces`, `target`) on `n` vertices:
/// removes an independent set of vertices without `fixed[v]` (the border),
/// each by the collapse into a ring vertex that keeps the mesh a manifold
/// disk (no ring vertex joined twice to the target), joins no two fixed
/// vertices and leaves every new face positive in `uv` (exact predicate). Returns the number of vertices removed.
inline std::size_t coarsen_disk_level(std::size_t n, const std::vector<Face>& faces, const std::vector<double>& target,
                                      const std::vector<Vec2>& uv, const std::vector<Vec3>& xyz,
                                      const std::vector<char>& fixed, Disk_level& out)
{
  // Rings of more than 10 give fans of long thin triangles; most vertices have 6.
  const std::size_t most = 10;
  const Vertex_faces around(n, faces);
  std::vector<char> state(n, 0); // 1: in a removed vertex's ring (kept), 2: removed
  std::vector<int> into(n, -1);
  std::unordered_set<std::uint64_t> added; // edges the accepted collapses made
  const auto key = [](int p, int q) {
    return (std::uint64_t(std::uint32_t((std::min)(p, q))) << 32) | std::uint32_t((std::max)(p, q));
  };
  Disk_decimation& D = out.from_above;
  std::vector<int> ring;
  std::vector<std::pair<double, std::size_t> > order;
  for(std::size_t v = 0; v < n; ++v) {
    if(fixed[v] || state[v] != 0 || !vertex_ring(around, faces, v, most, ring)) continue;
    const std::size_t k = ring.size();
    order.clear();
    for(std::size_t j = 0; j < k; ++j) {
      const Vec3 e = sub(xyz[std::size_t(ring[j])], xyz[v]);
      order.emplace_back(dot(e, e), j);
    }
    std::sort(order.begin(), order.end());
    std::size_t chosen = k;
    for(const auto& candidate : order) {
      const std::size_t j = candidate.second;
      const int w = ring[j];
      bool ok = true;
      for(std::size_t i = 0; i < k && ok; ++i) {
        const std::size_t i1 = (i + 1) % k;
        if(i == j || i1 == j) continue;
        ok = exact_orientation_2(uv[std::size_t(w)], uv[std::size_t(ring[i])], uv[std::size_t(ring[i1])]) == CGAL::POSITIVE;
        // Ring vertices other than w's two ring neighbours become joined to
        // w: once only, and not across the border (a chord between two
        // border vertices makes a triangle whose three corners the border
        // holds, whose area the flow can hardly reach).
        if(ok && i != (j + 1) % k)
          ok = !(fixed[std::size_t(w)] && fixed[std::size_t(ring[i])]) && !level_has_edge(around, faces, w, ring[i]) &&
               added.count(key(w, ring[i])) == 0;
      }
      if(ok) { chosen = j; break; }
    }
    if(chosen == k) continue;
    std::rotate(ring.begin(), ring.begin() + std::ptrdiff_t(chosen), ring.end());
    state[v] = 2;
    into[v] = ring[0];
    for(std::size_t i = 0; i < k; ++i) {
      state[std::size_t(ring[i])] = 1;
      if(i >= 2 && i + 1 < k) added.insert(key(ring[0], ring[i]));
    }
    D.removed.push_back(int(v));
    D.ring.insert(D.ring.end(), ring.begin(), ring.end());
    D.ring_first.push_back(D.ring.size());
  }
  collapse_level_faces(faces, target, into, out);
  return D.removed.size();
}

/// Places every vertex `D` removed back into its ring in `uv` (the ring's
/// positions are the coarser level's map): at the point of the coarse
/// triangle that held it in the start map `start`, with the same
/// barycentric coordinates; else inside its ring's kernel. Returns false
/// when some vertex finds no position with a positive star (exact
/// predicate); `uv` then holds a map that must not be used.
inline bool prolong_disk_level(const Disk_decimation& D, const std::vector<Vec2>& start, std::vector<Vec2>& uv)
{
  std::vector<Vec2> ring;
  const auto star_positive = [&](const Vec2& p) {
    for(std::size_t i = 0; i < ring.size(); ++i)
      if(exact_orientation_2(p, ring[i], ring[(i + 1) % ring.size()]) != CGAL::POSITIVE) return false;
    return true;
  };
  for(std::size_t r = 0; r < D.removed.size(); ++r) {
    const std::size_t v = std::size_t(D.removed[r]);
    const std::size_t b = D.ring_first[r], k = D.ring_first[r + 1] - b;
    ring.resize(k);
    for(std::size_t i = 0; i < k; ++i) ring[i] = uv[std::size_t(D.ring[b + i])];
    // The fan from ring[0] covered the ring's polygon in the coarse level.
    double best = -infinite_step();
    Vec2 p = ring[0];
    for(std::size_t i = 1; i + 1 < k; ++i) {
      const Vec2 &a = start[std::size_t(D.ring[b])], &c = start[std::size_t(D.ring[b + i])], &d = start[std::size_t(D.ring[b + i + 1])];
      const double A = signed_area_2(a, c, d);
      if(!(A > 0)) continue;
      const double l0 = signed_area_2(start[v], c, d) / A, l1 = signed_area_2(a, start[v], d) / A, l2 = 1 - l0 - l1;
      const double least = (std::min)(l0, (std::min)(l1, l2));
      if(least > best) {
        best = least;
        for(int x = 0; x < 2; ++x) p[std::size_t(x)] = l0 * ring[0][std::size_t(x)] + l1 * ring[i][std::size_t(x)] + l2 * ring[i + 1][std::size_t(x)];
      }
    }
    if(star_positive(p)) { uv[v] = p; continue; }
    // The kernel: the ring's polygon clipped by each edge's half-plane.
    std::vector<Vec2> poly(ring), next;
    for(std::size_t i = 0; i < k && poly.size() >= 3; ++i) {
      const Vec2 &e0 = ring[i], &e1 = ring[(i + 1) % k];
      const auto side = [&](const Vec2& q) { return (e1[0] - e0[0]) * (q[1] - e0[1]) - (e1[1] - e0[1]) * (q[0] - e0[0]); };
      next.clear();
      for(std::size_t j = 0; j < poly.size(); ++j) {
        const Vec2 &q0 = poly[j], &q1 = poly[(j + 1) % poly.size()];
        const double s0 = side(q0), s1 = side(q1);
        if(s0 >= 0) next.push_back(q0);
        if((s0 > 0 && s1 < 0) || (s0 < 0 && s1 > 0)) {
          const double t = s0 / (s0 - s1);
          next.push_back(Vec2{{ q0[0] + t * (q1[0] - q0[0]), q0[1] + t * (q1[1] - q0[1]) }});
        }
      }
      poly.swap(next);
    }
    Vec2 c{{ 0, 0 }};
    for(const Vec2& q : poly) { c[0] += q[0] / double(poly.size()); c[1] += q[1] / double(poly.size()); }
    if(poly.size() >= 3 && star_positive(c)) { uv[v] = c; continue; }
    return false;
  }
  return true;
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
