// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The order of points along a Morton (Z-order) curve of their bounding box:
// consecutive points lie close together, so passes over them in this order
// touch memory that lies close together, and consecutive runs of it are
// spatially compact regions.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_MORTON_ORDER_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_MORTON_ORDER_H

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// The indices of `x` sorted along a Morton curve (21 bits per coordinate;
/// ties by index, so the order depends on the points alone).
inline std::vector<std::size_t> morton_order(const std::vector<std::array<double, 3> >& x)
{
  std::array<double, 3> lo = x.empty() ? std::array<double, 3>{{ 0, 0, 0 }} : x[0], hi = lo;
  for(const std::array<double, 3>& p : x)
    for(std::size_t c = 0; c < 3; ++c) { lo[c] = (std::min)(lo[c], p[c]); hi[c] = (std::max)(hi[c], p[c]); }
  auto spread = [](std::uint64_t v) { // 21 bits to every third of 63
    v &= 0x1fffff;
    v = (v | v << 32) & 0x1f00000000ffffULL;
    v = (v | v << 16) & 0x1f0000ff0000ffULL;
    v = (v | v << 8) & 0x100f00f00f00f00fULL;
    v = (v | v << 4) & 0x10c30c30c30c30c3ULL;
    v = (v | v << 2) & 0x1249249249249249ULL;
    return v;
  };
  std::vector<std::pair<std::uint64_t, std::size_t> > key(x.size());
  for(std::size_t v = 0; v < x.size(); ++v) {
    std::uint64_t k = 0;
    for(std::size_t c = 0; c < 3; ++c) {
      const double span = hi[c] - lo[c];
      const double q = span > 0 ? (x[v][c] - lo[c]) / span * 2097151. : 0.;
      k |= spread(std::uint64_t(q)) << c;
    }
    key[v] = std::make_pair(k, v);
  }
  std::sort(key.begin(), key.end());
  std::vector<std::size_t> order(x.size());
  for(std::size_t i = 0; i < key.size(); ++i) order[i] = key[i].second;
  return order;
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
