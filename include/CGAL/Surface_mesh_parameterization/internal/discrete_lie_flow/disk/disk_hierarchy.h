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
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/flow/coarse_to_fine_levels.h>

#include <algorithm>
#include <cstdint>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

typedef Collapse_decimation Disk_decimation;
typedef Collapse_level Disk_level;

/// The next coarser level of a disk (`coarsen_level()`): the border
/// `fixed`, every new face positive in the start `uv` (exact predicate).
inline std::size_t coarsen_disk_level(std::size_t n, const std::vector<Face>& faces, const std::vector<double>& target,
                                      const std::vector<Vec2>& uv, const std::vector<Vec3>& xyz,
                                      const std::vector<char>& fixed, Disk_level& out)
{
  return coarsen_level(n, faces, target, xyz, fixed, [&uv](int, int w, int a, int b) {
    return exact_orientation_2(uv[std::size_t(w)], uv[std::size_t(a)], uv[std::size_t(b)]) == CGAL::POSITIVE;
  }, out);
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
    Vec2 c;
    if(kernel_centroid(ring, c) && star_positive(c)) { uv[v] = c; continue; }
    return false;
  }
  return true;
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
