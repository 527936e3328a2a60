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
    const int a = (std::abs(q[0]) <= std::abs(q[1]) && std::abs(q[0]) <= std::abs(q[2])) ? 0
                  : (std::abs(q[1]) <= std::abs(q[2]) ? 1 : 2);
    Vec3 axis{{ 0, 0, 0 }};
    axis[std::size_t(a)] = 1;
    const double sa = dot(axis, q);
    const Vec3 e1 = normalized(Vec3{{ axis[0] - sa * q[0], axis[1] - sa * q[1], axis[2] - sa * q[2] }});
    const Vec3 e2 = cross(q, e1);
    double g0 = 0, g1 = 0, h00 = 0, h01 = 0, h11 = 0;
    for(std::size_t i = begin; i < end; ++i) {
      const std::size_t f = around.of[i].first;
      const int k = around.of[i].second;
      const Vec3 G = barrier_area_gradients(p, faces[f], h0)[std::size_t(k)];
      const double x = dot(e1, G), y = dot(e2, G);
      const double c = energy.weight(f);
      const double dE = K - U * c / (u[f] * u[f]);
      const double w = 2 * U * c / (u[f] * u[f] * u[f]);
      g0 += dE * x; g1 += dE * y;
      h00 += w * x * x; h01 += w * x * y; h11 += w * y * y;
    }
    const double reg = 1e-9 * (h00 + h11);
    h00 += reg; h11 += reg;
    const double det = h00 * h11 - h01 * h01;
    if(!(det > 0)) continue;
    const double x0 = -(h11 * g0 - h01 * g1) / det, x1 = -(h00 * g1 - h01 * g0) / det;
    const double slope = g0 * x0 + g1 * x1;
    if(!(slope < 0)) continue;
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
    double lambda = (std::min)(1., mu * lambda_crit);
    const double E = 1 + U * K;
    u_new.resize(end - begin);
    for(int halvings = 0; halvings < 8; ++halvings, lambda *= 0.5) {
      const Vec3 moved = normalized(Vec3{{ q[0] + lambda * d[0], q[1] + lambda * d[1], q[2] + lambda * d[2] }});
      double dU = 0, dK = 0;
      bool positive = true;
      for(std::size_t i = begin; i < end && positive; ++i) {
        const Face& t = faces[around.of[i].first];
        const int k = around.of[i].second;
        const Vec3& r = p[std::size_t(t[(k + 1) % 3])];
        const Vec3& s = p[std::size_t(t[(k + 2) % 3])];
        // Corner order kept: (moved, r, s) is a rotation of the face.
        const double un = barrier_area_sphere(moved, r, s, h0);
        if(!(un > 0)) { positive = false; break; }
        u_new[i - begin] = un;
        dU += un - u[around.of[i].first];
        dK += energy.weight(around.of[i].first) * (1 / un - 1 / u[around.of[i].first]);
      }
      if(!positive) continue;
      const double E_new = 1 + (U + dU) * (K + dK);
      if(!(E_new <= E + 1e-4 * lambda * slope)) continue;
      bool certified = true;
      for(std::size_t i = begin; i < end && certified; ++i) {
        const Face& t = faces[around.of[i].first];
        const int k = around.of[i].second;
        certified = exact_orientation_sphere(moved, p[std::size_t(t[(k + 1) % 3])], p[std::size_t(t[(k + 2) % 3])]) ==
                    CGAL::POSITIVE;
      }
      if(!certified) { ++out.refused_by_exact_check; continue; }
      p[v] = moved;
      for(std::size_t i = begin; i < end; ++i) u[around.of[i].first] = u_new[i - begin];
      U += dU;
      K += dK;
      ++out.moved;
      break;
    }
  }
  return out;
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
