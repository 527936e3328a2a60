// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the disk's and the sphere's coarse-to-fine starts share
// (disk/coarse_to_fine.h, sphere/sphere_coarse_to_fine.h): their settings,
// the coarsest level's own numbering, options and record, the fallback
// position of a vertex put back into its ring (the centroid of the ring's
// kernel) and the schedule of the vertex sweeps on a finer level.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_COARSE_TO_FINE_LEVELS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_COARSE_TO_FINE_LEVELS_H

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_options.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_report.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/vertex_relaxation.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/flow/flow_driver.h>

#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// Internal knobs of a coarse-to-fine start (doc/coarse_to_fine.md).
struct Coarse_to_fine_settings
{
  /// Coarsen while the level has more than this share of the smallest
  /// mesh that flows coarse to fine (`coarse_to_fine_faces`): 20,000 faces
  /// by default, where a factorization costs little.
  double coarsest_share = 0.2;
  /// A level that removes less than this share of the vertices left ends the hierarchy.
  double least_removed = 0.05;
  /// The coarsest level flows to this share of the caller's tolerance: its
  /// map carried down loses some of it to the finer faces.
  double coarse_tolerance_share = 0.5;
  /// Vertex sweeps on each finer level: first over the vertices put back,
  /// then over all until D_area − 2 is within `level_goal_share` of the
  /// caller's tolerance (on the caller's mesh: `finest_goal_share`, so that
  /// its flow has nothing left to do), or a sweep took off less than
  /// `least_sweep_gain` of D_area − 2, or `most_sweeps` ran. A sweep costs a
  /// small fraction of an iteration of the flow (doc/coarse_to_fine.md).
  std::size_t put_back_sweeps = 2;
  double finest_goal_share = 0.97;
  double level_goal_share = 2;
  double least_sweep_gain = 0.05;
  std::size_t most_sweeps = 16;
  /// On the caller's mesh, where a sweep costs 1–2% of an iteration of the flow.
  double finest_least_sweep_gain = 0.02;
  std::size_t finest_most_sweeps = 40;
  /// Regions of the sweeps' split for threads (`Sweep_partition`): fixed,
  /// so that the map does not depend on the number of threads.
  std::size_t sweep_parts = 8;
};

/// The coarsest level on vertices of its own: its `faces` (over the
/// caller's numbering) renumbered in place, in the order they first use
/// their vertices; `xyz` gets those vertices' points from `fine_xyz`,
/// `index[v]` is a caller's vertex's coarse number (−1 off the level) and
/// `vertex_of[i]` the caller's vertex of coarse vertex i.
inline void renumber_coarsest_level(std::vector<Face>& faces, const std::vector<Vec3>& fine_xyz,
                                    std::vector<Vec3>& xyz, std::vector<int>& index, std::vector<int>& vertex_of)
{
  index.assign(fine_xyz.size(), -1);
  for(Face& f : faces)
    for(int& v : f) {
      if(index[std::size_t(v)] < 0) {
        index[std::size_t(v)] = int(vertex_of.size());
        vertex_of.push_back(v);
        xyz.push_back(fine_xyz[std::size_t(v)]);
      }
      v = index[std::size_t(v)];
    }
}

/// The coarsest level's flow options: the caller's `opt` without callback
/// or history, to `coarse_tolerance_share` of its tolerance, and no test of
/// the density's shares (the finest level's faces hold its regions).
inline Discrete_lie_flow_options coarsest_level_options(const Discrete_lie_flow_options& opt,
                                                        const Coarse_to_fine_settings& s)
{
  Discrete_lie_flow_options coarse = opt;
  coarse.callback = nullptr;
  coarse.record_history = false;
  coarse.tolerance = opt.tolerance * s.coarse_tolerance_share;
  coarse.certified.share_tolerance = 0;
  return coarse;
}

/// The report's record of the coarsest level's flow.
inline Discrete_lie_flow_level coarsest_level_record(std::size_t vertices, std::size_t faces, const Flow_outcome& flowed)
{
  Discrete_lie_flow_level level;
  level.vertices = vertices;
  level.faces = faces;
  level.iterations = flowed.iterations;
  level.d_area = flowed.final_d_area;
  return level;
}

/// The centroid of the kernel of the counterclockwise polygon `ring` (the
/// polygon clipped by each of its edges' half-planes): where a vertex put
/// back into its ring sees every ring edge from the inside. False when the
/// kernel has fewer than three corners.
inline bool kernel_centroid(const std::vector<Vec2>& ring, Vec2& centroid)
{
  const std::size_t k = ring.size();
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
  if(poly.size() < 3) return false;
  centroid = Vec2{{ 0, 0 }};
  for(const Vec2& q : poly) { centroid[0] += q[0] / double(poly.size()); centroid[1] += q[1] / double(poly.size()); }
  return true;
}

/// The sweeps of a finer level of `F` once its removed vertices are back:
/// `put_back_sweeps` over `removed`, then over the vertices with
/// `movable[v]` and a face until `done(E)`, a sweep took off less than the
/// least gain of E − 2, or the most sweeps ran (the finest level's settings
/// on the caller's mesh). `sweep(partition)` runs one sweep and returns its
/// outcome, `measure()` is the level's energy E, `energy(outcome)` the
/// energy after a sweep. Returns the energy after the last sweep.
template <class Sweep, class Measure, class Energy, class Done>
double sweep_finer_level(const std::vector<std::size_t>& order, const std::vector<Face>& F, const Vertex_faces& around,
                         const std::vector<int>& removed, const std::vector<char>& movable, bool finest,
                         const Coarse_to_fine_settings& s, Sweep sweep, Measure measure, Energy energy, Done done)
{
  const std::size_t n = movable.size();
  std::vector<char> keep(n, 0);
  for(int v : removed) keep[std::size_t(v)] = 1;
  {
    const Sweep_partition put_back(order, F, s.sweep_parts, &keep);
    for(std::size_t k = 0; k < s.put_back_sweeps; ++k) sweep(put_back);
  }
  for(std::size_t v = 0; v < n; ++v) keep[v] = movable[v] && around.first[v + 1] > around.first[v];
  const Sweep_partition all(order, F, s.sweep_parts, &keep);
  const std::size_t most = finest ? s.finest_most_sweeps : s.most_sweeps;
  const double least_gain = finest ? s.finest_least_sweep_gain : s.least_sweep_gain;
  double E = measure();
  for(std::size_t k = 0; k < most && !done(E); ++k) {
    const Relaxation_outcome r = sweep(all);
    const double E_new = energy(r);
    const double gain = E - E_new;
    E = E_new;
    if(r.moved == 0 || gain < least_gain * (E + gain - 2)) break;
  }
  return E;
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
