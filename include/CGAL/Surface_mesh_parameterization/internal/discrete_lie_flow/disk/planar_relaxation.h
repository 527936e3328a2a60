// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Vertex-by-vertex relaxation of the planar certified flow's energy: the
// planar counterpart of sphere_relaxation.h (read there why). A global step
// is as long as its stiffest face allows; with a density, a few stiff faces
// far from the region cap every step while the region's deficit shrinks by
// 0.01% per iteration (mushroom.off, factor 16). One vertex at a time, each
// face only limits its own corners. Interior vertices (and a floating
// border's) only: boundary vertices keep to their curve through the global
// steps.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_PLANAR_RELAXATION_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_PLANAR_RELAXATION_H

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_options.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/area_barrier_energy.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/certification.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/parallel_ranges.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/vertex_relaxation.h>

#include <cmath>
#include <thread>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// The threads of the disk's vertex sweeps (`Discrete_lie_flow_disk_options::threads`):
/// one below `parallel_from` faces.
inline int disk_sweep_threads(const Discrete_lie_flow_options& opt, std::size_t faces, std::size_t parallel_from = 100000)
{
  if(opt.disk.threads > 0) return opt.disk.threads;
  if(faces < parallel_from) return 1;
  const unsigned h = std::thread::hardware_concurrency();
  return h == 0 ? 1 : (h > 8 ? 8 : int(h));
}

/// The running sums of E = 1 + U K a sweep keeps up to date: U = Σ u_t, K = Σ c_t / u_t.
struct Planar_sweep_sums
{
  double U = 0, K = 0;
  Planar_sweep_sums(const Area_barrier_energy& energy, const std::vector<double>& u)
  {
    for(std::size_t t = 0; t < u.size(); ++t) { U += u[t]; K += energy.weight(t) / u[t]; }
  }
};

/// One vertex's move of a sweep: a 2 × 2 Gauss–Newton step of E, bounded by
/// the exact critical root of its faces, accepted when E passes Armijo and
/// the exact predicate finds every face of the vertex positive.
inline void relax_planar_vertex(std::size_t v, const std::vector<Face>& faces, const Vertex_faces& around,
                                const Area_barrier_energy& energy, double mu, std::vector<Vec2>& uv,
                                std::vector<double>& u, Planar_sweep_sums& S, std::vector<double>& u_new,
                                Relaxation_outcome& out)
{
  const std::size_t begin = around.first[v], end = around.first[v + 1];
  if(begin == end) return;
  const double U = S.U, K = S.K;
  // ∂u_t/∂p_v = ½ (y_r − y_s, x_s − x_r) for the face (v, r, s).
  Vertex_model model;
  for(std::size_t i = begin; i < end; ++i) {
    const std::size_t f = around.of[i].first;
    const int k = around.of[i].second;
    const Vec2& r = uv[std::size_t(faces[f][(k + 1) % 3])];
    const Vec2& s = uv[std::size_t(faces[f][(k + 2) % 3])];
    const double c = energy.weight(f);
    model.add(K - U * c / (u[f] * u[f]), 2 * U * c / (u[f] * u[f] * u[f]), 0.5 * (r[1] - s[1]), 0.5 * (s[0] - r[0]));
  }
  Vec2 d;
  double slope;
  if(!model.step(d[0], d[1], slope)) return;
  // The area of (v + λd, r, s) is linear in λ: exact critical root.
  double lambda_crit = infinite_step();
  for(std::size_t i = begin; i < end; ++i) {
    const std::size_t f = around.of[i].first;
    const int k = around.of[i].second;
    const Vec2& r = uv[std::size_t(faces[f][(k + 1) % 3])];
    const Vec2& s = uv[std::size_t(faces[f][(k + 2) % 3])];
    const double rate = 0.5 * (d[0] * (r[1] - s[1]) + d[1] * (s[0] - r[0]));
    if(rate < 0) lambda_crit = (std::min)(lambda_crit, -u[f] / rate);
  }
  // The area in the face's own vertex order, as signed_areas_2() computes
  // it: the rounding must not depend on which corner moved, or a face
  // accepted here could come out non-positive when the areas are recomputed.
  const auto moved_area = [&](std::size_t f, int k, const Vec2& x) {
    const Vec2& a = k == 0 ? x : uv[std::size_t(faces[f][0])];
    const Vec2& b = k == 1 ? x : uv[std::size_t(faces[f][1])];
    const Vec2& c = k == 2 ? x : uv[std::size_t(faces[f][2])];
    return signed_area_2(a, b, c);
  };
  double dU = 0, dK = 0;
  u_new.resize(end - begin);
  const auto energy_at = [&](const Vec2& x) {
    dU = dK = 0;
    for(std::size_t i = begin; i < end; ++i) {
      const std::size_t f = around.of[i].first;
      const double un = moved_area(f, around.of[i].second, x);
      if(!(un > 0)) return infinite_step();
      u_new[i - begin] = un;
      dU += un - u[f];
      dK += energy.weight(f) * (1 / un - 1 / u[f]);
    }
    return 1 + (U + dU) * (K + dK);
  };
  const auto certified = [&](const Vec2& x) {
    return moved_vertex_is_positive(around, begin, end, faces, uv, x, &exact_orientation_2);
  };
  Vec2 moved;
  if(relaxation_line_search(1 + U * K, (std::min)(1., mu * lambda_crit), slope,
                            [&](double l) { return Vec2{{ uv[v][0] + l * d[0], uv[v][1] + l * d[1] }}; },
                            energy_at, certified, moved, out)) {
    for(std::size_t i = begin; i < end; ++i) u[around.of[i].first] = u_new[i - begin];
    S.U += dU;
    S.K += dK;
    uv[v] = moved;
  }
}

/// One sweep over the vertices with `movable[v]` of E = 1 + U Σ c_t/u_t on
/// the signed areas u of `uv` (kept up to date, as `uv`).
inline Relaxation_outcome relax_planar_vertices(const std::vector<Face>& faces, const Vertex_faces& around,
                                                const Area_barrier_energy& energy, double mu,
                                                const std::vector<char>& movable,
                                                std::vector<Vec2>& uv, std::vector<double>& u)
{
  Relaxation_outcome out;
  Planar_sweep_sums S(energy, u);
  std::vector<double> u_new;
  for(std::size_t v = 0; v < uv.size(); ++v)
    if(movable[v]) relax_planar_vertex(v, faces, around, energy, mu, uv, u, S, u_new, out);
  out.energy = 1 + S.U * S.K;
  return out;
}

/// One sweep over the vertices of `partition` (movable ones only: the
/// partition holds no other), its interiors on up to `threads` threads,
/// then its separator. Each interior starts from the same sums of E and
/// sees only its own moves in them; the sums are recomputed before the
/// separator: the result does not depend on the number of threads.
inline Relaxation_outcome relax_planar_vertices(const std::vector<Face>& faces, const Vertex_faces& around,
                                                const Area_barrier_energy& energy, double mu,
                                                const Sweep_partition& partition, int threads,
                                                std::vector<Vec2>& uv, std::vector<double>& u)
{
  const Planar_sweep_sums S0(energy, u);
  std::vector<Relaxation_outcome> part(partition.interior.size());
  parallel_ranges(partition.interior.size(), threads, [&](std::size_t begin, std::size_t end, std::size_t) {
    std::vector<double> u_new;
    for(std::size_t r = begin; r < end; ++r) {
      Planar_sweep_sums S = S0;
      for(std::size_t v : partition.interior[r]) relax_planar_vertex(v, faces, around, energy, mu, uv, u, S, u_new, part[r]);
    }
  });
  Relaxation_outcome out;
  Planar_sweep_sums S(energy, u);
  std::vector<double> u_new;
  for(std::size_t v : partition.separator) relax_planar_vertex(v, faces, around, energy, mu, uv, u, S, u_new, out);
  for(const Relaxation_outcome& r : part) {
    out.moved += r.moved;
    out.refused_by_exact_check += r.refused_by_exact_check;
  }
  out.energy = 1 + S.U * S.K;
  return out;
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
