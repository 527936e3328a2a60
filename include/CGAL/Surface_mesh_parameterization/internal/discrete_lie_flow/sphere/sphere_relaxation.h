// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Vertex-by-vertex relaxation of the spherical flow's energy (nonlinear
// Gauss–Seidel). A global step is as long as its most constrained face
// allows: a few needles, nearly inverted along the global direction, cap the
// step of the whole mesh and the flow crawls (handle.off: steps of 1e-6 for a
// hundred iterations). Moving one vertex at a time, each needle only limits
// its own corners, and the grid-scale mismatch between neighbouring faces,
// which the Laplacian-preconditioned directions reduce slowly, is exactly
// what such sweeps remove (the smoother of a multigrid cycle). Each move is
// a 2 × 2 Gauss–Newton step in the vertex's tangent plane, bounded by the
// exact critical root of its faces (det[p + λd, q, r] is linear in λ when one
// vertex moves), accepted only if it lowers the total energy and every
// incident face stays positive by the exact predicate.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_SPHERE_RELAXATION_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_SPHERE_RELAXATION_H

#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/area_barrier_energy.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/certification.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/parallel_ranges.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/vertex_relaxation.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/sphere/sphere_gauss_newton.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {


/// Vertices of the faces whose flat area ratio r_t = (u_t / Σu) / a_t is off
/// by more than e^`threshold`: where a sweep has work to do (a sweep over
/// every vertex costs as much as a global step on a fine mesh).
inline std::vector<std::size_t> vertices_to_relax(const std::vector<Face>& faces, const Weighted_area_energy& energy,
                                                  const std::vector<double>& u, std::size_t n, double threshold)
{
  double U = 0;
  for(double x : u) U += x;
  std::vector<char> mark(n, 0);
  for(std::size_t t = 0; t < faces.size(); ++t)
    if(std::abs(std::log((u[t] / U) / energy.share(t))) > threshold)
      for(int k = 0; k < 3; ++k) mark[std::size_t(faces[t][k])] = 1;
  std::vector<std::size_t> out;
  for(std::size_t v = 0; v < n; ++v) if(mark[v]) out.push_back(v);
  return out;
}

/// One vertex's move in a sweep of the polish energy α E(u) + κ E(w) (see
/// `relax_sphere_vertices()`): `S`, `Sw` are the running sums of E over u
/// and w, updated with the move; `u_new`, `w_new` scratch space.
inline void relax_sphere_vertex(std::size_t v, const std::vector<Face>& faces, const Vertex_faces& around,
                                const Weighted_area_energy& energy, double kappa, double mu, double flat_weight,
                                std::vector<Vec3>& p, std::vector<double>& u, std::vector<double>& w,
                                Weighted_area_energy::Sums& S, Weighted_area_energy::Sums& Sw,
                                std::vector<double>& u_new, std::vector<double>& w_new, Relaxation_outcome& out)
{
  typedef Weighted_area_energy::Sums Sums;
  const std::size_t begin = around.first[v], end = around.first[v + 1];
  if(begin == end) return;
  // Tangent frame at v, gradient and 2 × 2 Gauss–Newton matrix of E in it.
  const Vec3& q = p[v];
  Vec3 e1, e2;
  tangent_frame(q, e1, e2);
  const auto corner = [&](std::size_t f, int k, int j) -> const Vec3& { return p[std::size_t(faces[f][(k + j) % 3])]; };
  Vertex_model model;
  for(std::size_t i = begin; i < end; ++i) {
    const std::size_t f = around.of[i].first;
    const int k = around.of[i].second;
    Vec3 flat, cone;
    corner_area_gradients(q, corner(f, k, 1), corner(f, k, 2), flat, cone);
    model.add(flat_weight * energy.derivative(S, f, u[f]), flat_weight * energy.curvature(S, f, u[f]), dot(e1, flat), dot(e2, flat));
    model.add(kappa * energy.derivative(Sw, f, w[f]), kappa * energy.curvature(Sw, f, w[f]), dot(e1, cone), dot(e2, cone));
  }
  double x0, x1, slope;
  if(!model.step(x0, x1, slope)) return;
  const Vec3 d = {{ x0 * e1[0] + x1 * e2[0], x0 * e1[1] + x1 * e2[1], x0 * e1[2] + x1 * e2[2] }};
  // Exact critical root: det[q + λd, r, s] = det[q, r, s] + λ d·(r × s).
  double lambda_crit = infinite_step();
  for(std::size_t i = begin; i < end; ++i) {
    const Vec3& r = corner(around.of[i].first, around.of[i].second, 1);
    const Vec3& s = corner(around.of[i].first, around.of[i].second, 2);
    const double d0 = dot(q, cross(sub(r, q), sub(s, q)));
    const double d1 = dot(d, cross(r, s));
    if(d1 < 0) lambda_crit = (std::min)(lambda_crit, -d0 / d1);
  }
  // Corner order kept: (x, r, s) is a rotation of the face.
  Sums S_new, Sw_new;
  u_new.resize(end - begin);
  w_new.resize(end - begin);
  const auto energy_at = [&](const Vec3& x) {
    S_new = S;
    Sw_new = Sw;
    for(std::size_t i = begin; i < end; ++i) {
      const std::size_t f = around.of[i].first;
      const Vec3 &r = corner(f, around.of[i].second, 1), &s = corner(f, around.of[i].second, 2);
      const double a = signed_area_sphere(x, r, s), c = cone_area_sphere(x, r, s);
      if(!(a > 0 && c > 0)) return infinite_step();
      u_new[i - begin] = a;
      w_new[i - begin] = c;
      energy.change(S_new, f, u[f], a);
      energy.change(Sw_new, f, w[f], c);
    }
    return flat_weight * energy.value(S_new) + kappa * energy.value(Sw_new);
  };
  const auto certified = [&](const Vec3& x) {
    return moved_vertex_is_positive(around, begin, end, faces, p, x, &exact_orientation_sphere);
  };
  Vec3 moved;
  if(relaxation_line_search(flat_weight * energy.value(S) + kappa * energy.value(Sw), (std::min)(1., mu * lambda_crit), slope,
                            [&](double l) { return normalized(Vec3{{ q[0] + l * d[0], q[1] + l * d[1], q[2] + l * d[2] }}); },
                            energy_at, certified, moved, out)) {
    for(std::size_t i = begin; i < end; ++i) {
      u[around.of[i].first] = u_new[i - begin];
      w[around.of[i].first] = w_new[i - begin];
    }
    S = S_new;
    Sw = Sw_new;
    p[v] = moved;
  }
}

/// One sweep over the vertices `active` of the polish energy
/// α E(u) + κ E(w) (sphere_certified_flow.h): u the flat areas, w the cone
/// areas, E the weighted D_area `energy`, α = `flat_weight` (0: the
/// opening's energy, the D_area of the cone areas alone). `u` and `w` must
/// hold the areas of `p`; all three are updated.
inline Relaxation_outcome relax_sphere_vertices(const std::vector<Face>& faces, const Vertex_faces& around,
                                                const Weighted_area_energy& energy, double kappa, double mu,
                                                const std::vector<std::size_t>& active,
                                                std::vector<Vec3>& p, std::vector<double>& u, std::vector<double>& w,
                                                double flat_weight = 1)
{
  Relaxation_outcome out;
  Weighted_area_energy::Sums S = energy.sums(u), Sw = energy.sums(w);
  std::vector<double> u_new, w_new;
  for(std::size_t v : active)
    relax_sphere_vertex(v, faces, around, energy, kappa, mu, flat_weight, p, u, w, S, Sw, u_new, w_new, out);
  return out;
}

/// One sweep over every vertex, the interiors of `partition` on up to
/// `threads` threads, then the separator. Each interior is swept from the
/// same sums of E and sees only its own moves in them (the other regions'
/// moves change the global sums by little, and the sums are recomputed
/// before the separator), so the result does not depend on the number of
/// threads. Same energy and arguments as `relax_sphere_vertices()`.
inline Relaxation_outcome relax_sphere_vertices(const std::vector<Face>& faces, const Vertex_faces& around,
                                                const Weighted_area_energy& energy, double kappa, double mu,
                                                const Sweep_partition& partition, int threads,
                                                std::vector<Vec3>& p, std::vector<double>& u, std::vector<double>& w)
{
  const Weighted_area_energy::Sums S = energy.sums(u), Sw = energy.sums(w);
  std::vector<Relaxation_outcome> part(partition.interior.size());
  parallel_ranges(partition.interior.size(), threads, [&](std::size_t begin, std::size_t end, std::size_t) {
    std::vector<double> u_new, w_new;
    for(std::size_t r = begin; r < end; ++r) {
      Weighted_area_energy::Sums s = S, sw = Sw;
      for(std::size_t v : partition.interior[r])
        relax_sphere_vertex(v, faces, around, energy, kappa, mu, 1, p, u, w, s, sw, u_new, w_new, part[r]);
    }
  });
  Relaxation_outcome out = relax_sphere_vertices(faces, around, energy, kappa, mu, partition.separator, p, u, w);
  for(const Relaxation_outcome& r : part) {
    out.moved += r.moved;
    out.refused_by_exact_check += r.refused_by_exact_check;
  }
  return out;
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
