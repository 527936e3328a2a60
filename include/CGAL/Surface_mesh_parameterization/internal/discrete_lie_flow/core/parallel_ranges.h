// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Loops split over a few std::threads, for the volumetric flow's per-tet and
// per-vertex passes. Nothing here adds floating-point numbers across
// ranges: a caller that wants results independent of the number of threads
// writes one value per element and gathers in a fixed order afterwards
// (doc/volume.md, "Speed of the flow at 1M tetrahedra").

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_PARALLEL_RANGES_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_PARALLEL_RANGES_H

#include <algorithm>
#include <array>
#include <cstddef>
#include <thread>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// Below this many tets the automatic setting of the volumetric flow runs
/// on one thread: starting threads for every pass then costs about what
/// they save (measured, doc/volume.md).
constexpr std::size_t single_flow_thread_below = 150000;

/// The threads of the volumetric flow: `requested` > 0 that many; 0
/// automatic: one below `single_flow_thread_below` tets, else the hardware
/// threads (at most 8).
inline int volume_flow_threads(int requested, std::size_t tets)
{
  if(requested > 0) return requested;
  if(tets < single_flow_thread_below) return 1;
  const unsigned h = std::thread::hardware_concurrency();
  return h == 0 ? 1 : (h > 8 ? 8 : int(h));
}

/// Calls f(begin, end, range) on `threads` contiguous ranges covering
/// [0, n), the first range on the calling thread; returns when all are done.
template <class F>
void parallel_ranges(std::size_t n, int threads, const F& f)
{
  const std::size_t k = threads > 1 && n >= std::size_t(threads) ? std::size_t(threads) : 1;
  if(k == 1) { f(std::size_t(0), n, std::size_t(0)); return; }
  std::vector<std::thread> pool;
  pool.reserve(k - 1);
  for(std::size_t r = 1; r < k; ++r)
    pool.emplace_back([&f, n, k, r]() { f(n * r / k, n * (r + 1) / k, r); });
  f(std::size_t(0), n / k, std::size_t(0));
  for(std::thread& t : pool) t.join();
}

/// K sums over [0, n) that do not depend on the number of threads: f(begin,
/// end, sums) adds the terms of [begin, end) into sums[0..K); the ranges are
/// fixed blocks of 2,048 elements, added in order.
template <std::size_t K, class F>
std::array<double, K> blocked_sums(std::size_t n, int threads, const F& f)
{
  const std::size_t B = 2048, blocks = (n + B - 1) / B;
  std::vector<std::array<double, K> > part(blocks);
  parallel_ranges(blocks, threads, [&](std::size_t begin, std::size_t end, std::size_t) {
    for(std::size_t b = begin; b < end; ++b) {
      std::array<double, K> s;
      s.fill(0.);
      f(b * B, (std::min)(n, (b + 1) * B), s);
      part[b] = s;
    }
  });
  std::array<double, K> total;
  total.fill(0.);
  for(const std::array<double, K>& s : part)
    for(std::size_t k = 0; k < K; ++k) total[k] += s[k];
  return total;
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
