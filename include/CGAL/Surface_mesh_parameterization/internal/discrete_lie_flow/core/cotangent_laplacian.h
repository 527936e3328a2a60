// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The cotangent (P1 finite element) stiffness matrix of a planar domain mesh
// and the gradient of a P1 function.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_COTANGENT_LAPLACIAN_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_COTANGENT_LAPLACIAN_H

#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/certification.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/sparse_solver.h>

#include <CGAL/assertions.h>

#include <Eigen/Sparse>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// Half cotangents of the three angles of a positively oriented triangle:
/// w[k] = ½ cot(angle at corner k), the weight of the opposite edge
/// (corner k+1, corner k+2). Stiffness: L_ij = −Σ w over the edge's triangles,
/// L_ii = −Σ_j L_ij, positive semi-definite with the constants as kernel.
template <class Point>
std::array<double, 3> half_cotangents(const Point& p0, const Point& p1, const Point& p2)
{
  const Point* p[3] = { &p0, &p1, &p2 };
  std::array<double, 3> w;
  // twice the area, shared by the three angles
  const double ax = p1[0] - p0[0], ay = p1[1] - p0[1], bx = p2[0] - p0[0], by = p2[1] - p0[1];
  const double twice_area = ax * by - ay * bx;
  for(int k = 0; k < 3; ++k) {
    const Point& a = *p[k];
    const Point& b = *p[(k + 1) % 3];
    const Point& c = *p[(k + 2) % 3];
    const double ux = b[0] - a[0], uy = b[1] - a[1], vx = c[0] - a[0], vy = c[1] - a[1];
    w[k] = 0.5 * (ux * vx + uy * vy) / twice_area;
  }
  return w;
}

/// Gradient of the P1 function with values h at the corners of the
/// positively oriented triangle (p0, p1, p2): Σ_k h_k rot90(p_{k+2} − p_{k+1}) / (2 area).
inline Vec2 p1_gradient(const Vec2& p0, const Vec2& p1, const Vec2& p2, double h0, double h1, double h2)
{
  const double twice_area = (p1[0] - p0[0]) * (p2[1] - p0[1]) - (p1[1] - p0[1]) * (p2[0] - p0[0]);
  const Vec2* p[3] = { &p0, &p1, &p2 };
  const double h[3] = { h0, h1, h2 };
  Vec2 g{{ 0, 0 }};
  for(int k = 0; k < 3; ++k) {
    const Vec2& a = *p[(k + 1) % 3];
    const Vec2& b = *p[(k + 2) % 3];
    g[0] += h[k] * -(b[1] - a[1]);
    g[1] += h[k] * (b[0] - a[0]);
  }
  g[0] /= twice_area; g[1] /= twice_area;
  return g;
}

/// Cotangent stiffness matrix of the faces over `uv` (n × n, full symmetric storage).
inline Sparse_matrix cotangent_stiffness(const std::vector<Vec2>& uv, const std::vector<Face>& faces)
{
  std::vector<Eigen::Triplet<double> > trip;
  trip.reserve(faces.size() * 9);
  for(const Face& t : faces) {
    const std::array<double, 3> w = half_cotangents(uv[t[0]], uv[t[1]], uv[t[2]]);
    for(int k = 0; k < 3; ++k) {
      const int i = t[(k + 1) % 3], j = t[(k + 2) % 3];
      trip.emplace_back(i, j, -w[k]);
      trip.emplace_back(j, i, -w[k]);
      trip.emplace_back(i, i, w[k]);
      trip.emplace_back(j, j, w[k]);
    }
  }
  Sparse_matrix L(Eigen::Index(uv.size()), Eigen::Index(uv.size()));
  L.setFromTriplets(trip.begin(), trip.end());
  return L;
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
