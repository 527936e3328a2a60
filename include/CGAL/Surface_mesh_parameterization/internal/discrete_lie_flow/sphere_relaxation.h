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

#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/area_barrier_energy.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/certification.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/disk_problem.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/sphere_gauss_newton.h>

#include <array>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {


/// Vertices of the faces whose area ratio r_t = (u_t / Σu) / √c_t is off by
/// more than e^`threshold`: where a sweep has work to do (a sweep over every
/// vertex costs as much as a global step on a fine mesh).
inline std::vector<std::size_t> vertices_to_relax(const std::vector<Face>& faces, const Area_barrier_energy& energy,
                                                  const std::vector<double>& u, std::size_t n, double threshold)
{
  double U = 0;
  for(double x : u) U += x;
  std::vector<char> mark(n, 0);
  for(std::size_t t = 0; t < faces.size(); ++t)
    if(std::abs(std::log((u[t] / U) / std::sqrt(energy.weight(t)))) > threshold)
      for(int k = 0; k < 3; ++k) mark[std::size_t(faces[t][k])] = 1;
  std::vector<std::size_t> out;
  for(std::size_t v = 0; v < n; ++v) if(mark[v]) out.push_back(v);
  return out;
}

/// One sweep over the vertices `active` of the energy E = 1 + U Σ c_t/u_t on
/// the damped flat areas u (barrier_area_sphere with `h0`). `u` must hold
/// the areas of `p`; both are updated.
inline Relaxation_outcome relax_sphere_vertices(const std::vector<Face>& faces, const Vertex_faces& around,
                                                const Area_barrier_energy& energy, double h0, double mu,
                                                const std::vector<std::size_t>& active,
                                                std::vector<Vec3>& p, std::vector<double>& u)
{
  Relaxation_outcome out;
  double U = 0, K = 0;
  for(std::size_t t = 0; t < u.size(); ++t) { U += u[t]; K += energy.weight(t) / u[t]; }
  std::vector<double> u_new;
  for(std::size_t v : active) {
    const std::size_t begin = around.first[v], end = around.first[v + 1];
    if(begin == end) continue;
    // Tangent frame at v, gradient and 2 × 2 Gauss–Newton matrix of E in it.
    const Vec3& q = p[v];
    Vec3 e1, e2;
    tangent_frame(q, e1, e2);
    Vertex_model model;
    for(std::size_t i = begin; i < end; ++i) {
      const std::size_t f = around.of[i].first;
      const Vec3 G = barrier_area_gradient(p, faces[f], around.of[i].second, h0);
      const double c = energy.weight(f);
      model.add(K - U * c / (u[f] * u[f]), 2 * U * c / (u[f] * u[f] * u[f]), dot(e1, G), dot(e2, G));
    }
    double x0, x1, slope;
    if(!model.step(x0, x1, slope)) continue;
    const Vec3 d = {{ x0 * e1[0] + x1 * e2[0], x0 * e1[1] + x1 * e2[1], x0 * e1[2] + x1 * e2[2] }};
    // Exact critical root: det[q + λd, r, s] = det[q, r, s] + λ d·(r × s).
    double lambda_crit = infinite_step();
    for(std::size_t i = begin; i < end; ++i) {
      const Face& t = faces[around.of[i].first];
      const int k = around.of[i].second;
      const Vec3& r = p[std::size_t(t[(k + 1) % 3])];
      const Vec3& s = p[std::size_t(t[(k + 2) % 3])];
      const double d0 = dot(q, cross(sub(r, q), sub(s, q)));
      const double d1 = dot(d, cross(r, s));
      if(d1 < 0) lambda_crit = (std::min)(lambda_crit, -d0 / d1);
    }
    const auto corner = [&](std::size_t f, int k, int j) -> const Vec3& { return p[std::size_t(faces[f][(k + j) % 3])]; };
    Vec3 moved;
    // Corner order kept: (moved, r, s) is a rotation of the face.
    if(relaxation_line_search(around, begin, end, energy, (std::min)(1., mu * lambda_crit), slope,
                              [&](double l) { return normalized(Vec3{{ q[0] + l * d[0], q[1] + l * d[1], q[2] + l * d[2] }}); },
                              [&](std::size_t f, int k, const Vec3& x) { return barrier_area_sphere(x, corner(f, k, 1), corner(f, k, 2), h0); },
                              [&](std::size_t f, int k, const Vec3& x) {
                                return exact_orientation_sphere(x, corner(f, k, 1), corner(f, k, 2)) == CGAL::POSITIVE;
                              },
                              u, u_new, U, K, moved, out))
      p[v] = moved;
  }
  return out;
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
