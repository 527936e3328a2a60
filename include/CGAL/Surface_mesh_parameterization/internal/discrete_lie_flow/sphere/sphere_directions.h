// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the spherical flows move along: the Sobolev metric of the flat
// triangles between sphere points (cotangent stiffness plus a lumped mass),
// the gradients of per-face energies of the cone and flat areas, the
// gradient of a P1 function on a flat triangle in space, and the projection
// onto the tangent planes.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_SPHERE_DIRECTIONS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_SPHERE_DIRECTIONS_H

#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/geometry.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/sparse_solver.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/sphere/sphere_problem.h>

#include <Eigen/Sparse>

#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// Calls `add(i, j, v)` for every contribution to the cotangent stiffness
/// plus `mass_weight` × lumped mass of the flat triangles between the
/// (positively oriented) sphere points `p`, always in the same order.
template <class Add>
void sphere_sobolev_contributions(const std::vector<Vec3>& p, const std::vector<Face>& faces, double mass_weight, Add&& add)
{
  for(std::size_t f = 0; f < faces.size(); ++f) {
    const Face& t = faces[f];
    const Vec3* q[3] = { &p[std::size_t(t[0])], &p[std::size_t(t[1])], &p[std::size_t(t[2])] };
    const Vec3 N = cross(sub(*q[1], *q[0]), sub(*q[2], *q[0]));
    const double twice_area = std::sqrt(dot(N, N));
    for(int k = 0; k < 3; ++k) {
      const Vec3 u = sub(*q[(k + 1) % 3], *q[k]), v = sub(*q[(k + 2) % 3], *q[k]);
      const double w = 0.5 * dot(u, v) / twice_area; // ½ cot of the angle at corner k
      const int i = t[(k + 1) % 3], j = t[(k + 2) % 3];
      add(i, j, -w);
      add(j, i, -w);
      add(i, i, w);
      add(j, j, w);
      add(t[k], t[k], mass_weight * twice_area / 6);
    }
  }
}

/// Cotangent stiffness plus `mass_weight` × lumped mass of the flat triangles
/// between the (positively oriented) sphere points `p`.
inline Sparse_matrix sphere_sobolev_matrix(const std::vector<Vec3>& p, const std::vector<Face>& faces, double mass_weight)
{
  std::vector<Eigen::Triplet<double> > trip;
  trip.reserve(faces.size() * 15);
  sphere_sobolev_contributions(p, faces, mass_weight, [&trip](int i, int j, double v) { trip.emplace_back(i, j, v); });
  Sparse_matrix K(Eigen::Index(p.size()), Eigen::Index(p.size()));
  K.setFromTriplets(trip.begin(), trip.end());
  K.makeCompressed();
  return K;
}

/// ∂E/∂p from per-face ∂E/∂u_t for the cone areas u_t = ½ det[p0, p1, p2]:
/// ∂u/∂p_k = ½ p_{k+1} × p_{k+2}, evaluated as ½ (N + p_k × (p_{k+2} − p_{k+1}))
/// with N = (p1 − p0) × (p2 − p0), which keeps its relative accuracy on tiny faces.
inline void cone_position_gradient(const std::vector<Vec3>& p, const std::vector<Face>& faces,
                                   const std::vector<double>& dE, std::vector<Vec3>& g)
{
  g.assign(p.size(), Vec3{{ 0, 0, 0 }});
  for(std::size_t f = 0; f < faces.size(); ++f) {
    const Face& t = faces[f];
    const Vec3 N = cross(sub(p[std::size_t(t[1])], p[std::size_t(t[0])]), sub(p[std::size_t(t[2])], p[std::size_t(t[0])]));
    for(int k = 0; k < 3; ++k) {
      const Vec3& pk = p[std::size_t(t[k])];
      const Vec3 c = cross(pk, sub(p[std::size_t(t[(k + 2) % 3])], p[std::size_t(t[(k + 1) % 3])]));
      Vec3& gk = g[std::size_t(t[k])];
      for(int j = 0; j < 3; ++j) gk[j] += 0.5 * dE[f] * (N[j] + c[j]);
    }
  }
}

/// ∂E/∂p of the polish energy from per-face ∂E/∂u_t on the flat areas
/// (`dE_flat`) and on the cone areas (`dE_cone`, the cone weight included).
inline void polish_position_gradient(const std::vector<Vec3>& p, const std::vector<Face>& faces,
                                     const std::vector<double>& dE_flat, const std::vector<double>& dE_cone,
                                     std::vector<Vec3>& g)
{
  g.assign(p.size(), Vec3{{ 0, 0, 0 }});
  for(std::size_t f = 0; f < faces.size(); ++f) {
    const Face& t = faces[f];
    for(int k = 0; k < 3; ++k) {
      Vec3 flat, cone;
      corner_area_gradients(p[std::size_t(t[k])], p[std::size_t(t[(k + 1) % 3])], p[std::size_t(t[(k + 2) % 3])], flat, cone);
      Vec3& gk = g[std::size_t(t[k])];
      for(std::size_t j = 0; j < 3; ++j) gk[j] += dE_flat[f] * flat[j] + dE_cone[f] * cone[j];
    }
  }
}

/// Removes the normal component: v ← v − (v·p) p.
inline void project_to_tangent(const std::vector<Vec3>& p, std::vector<Vec3>& v)
{
  for(std::size_t i = 0; i < p.size(); ++i) {
    const double s = dot(v[i], p[i]);
    for(int j = 0; j < 3; ++j) v[i][j] -= s * p[i][j];
  }
}

/// Gradient of the P1 function with values h at the corners of the flat
/// triangle (p0, p1, p2) in 3D: Σ_k h_k N × (p_{k+2} − p_{k+1}) / |N|², with
/// N = (p1 − p0) × (p2 − p0) (the planar rot90 formula in the triangle's plane).
inline Vec3 p1_gradient_3(const Vec3& p0, const Vec3& p1, const Vec3& p2, double h0, double h1, double h2)
{
  const Vec3 N = cross(sub(p1, p0), sub(p2, p0));
  const double nn = dot(N, N);
  const Vec3 g = cross(N, Vec3{{ h0 * (p2[0] - p1[0]) + h1 * (p0[0] - p2[0]) + h2 * (p1[0] - p0[0]),
                                 h0 * (p2[1] - p1[1]) + h1 * (p0[1] - p2[1]) + h2 * (p1[1] - p0[1]),
                                 h0 * (p2[2] - p1[2]) + h1 * (p0[2] - p2[2]) + h2 * (p1[2] - p0[2]) }});
  return {{ g[0] / nn, g[1] / nn, g[2] / nn }};
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
