// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Gauss–Newton direction of the spherical flow, for the last digits.
// The Sobolev gradient balances the flow's smooth modes but not the
// grid-scale ones: on a closed mesh F ≈ 2V, so the face areas are nearly as
// many as the tangential degrees of freedom, and the mismatch between
// neighbouring faces is what a Laplacian metric reduces slowly (measured: the
// Sobolev/L-BFGS flow plateaued at D_area 2.001–2.01 on cow, homer, camel,
// armadillo). The Gauss–Newton model of E = Σ e_t(u_t) in the tangent planes,
// H = Jᵀ diag(e_t'') J (J = ∂u/∂p restricted to the tangent planes),
// regularised by ε times the Sobolev metric (Levenberg–Marquardt: the
// metric fixes the rotations, which do not change any area, and ε adapts to
// how well the model predicted the last step), converges quadratically.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_SPHERE_GAUSS_NEWTON_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_SPHERE_GAUSS_NEWTON_H

#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/cotangent_laplacian.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/sphere/sphere_problem.h>

#include <Eigen/Sparse>

#include <array>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// An orthonormal basis (e1, e2) of the tangent plane at the unit vector q:
/// the axis least aligned with q, projected (never close to parallel), and q × e1.
inline void tangent_frame(const Vec3& q, Vec3& e1, Vec3& e2)
{
  const int a = (std::abs(q[0]) <= std::abs(q[1]) && std::abs(q[0]) <= std::abs(q[2])) ? 0
                : (std::abs(q[1]) <= std::abs(q[2]) ? 1 : 2);
  Vec3 t{{ 0, 0, 0 }};
  t[std::size_t(a)] = 1;
  const double s = dot(t, q);
  e1 = normalized(Vec3{{ t[0] - s * q[0], t[1] - s * q[1], t[2] - s * q[2] }});
  e2 = cross(q, e1);
}

/// The tangent frames at every unit vector.
struct Tangent_frames
{
  std::vector<Vec3> e1, e2;

  explicit Tangent_frames(const std::vector<Vec3>& p) : e1(p.size()), e2(p.size())
  {
    for(std::size_t i = 0; i < p.size(); ++i) tangent_frame(p[i], e1[i], e2[i]);
  }

  std::array<double, 2> coordinates(std::size_t i, const Vec3& v) const { return {{ dot(e1[i], v), dot(e2[i], v) }}; }
  Vec3 vector(std::size_t i, double x, double y) const
  {
    return {{ x * e1[i][0] + y * e2[i][0], x * e1[i][1] + y * e2[i][1], x * e1[i][2] + y * e2[i][2] }};
  }
};

/// Calls `add(i, j, v)` for every contribution to H + ε S in the tangent
/// frames (2 unknowns per vertex, x of vertex i at 2i, 2i + 1), always in
/// the same order: H = Σ_t (w_t g_t g_tᵀ + w'_t g'_t g'_tᵀ) with g_t, g'_t
/// the tangential gradients of face t's flat and cone areas and w, w' the
/// energy's curvatures in them (the polish energy of sphere_certified_flow.h), S the
/// Sobolev metric `K` (n × n, one copy per coordinate) seen through the
/// frames. Returns tr(H) / tr(S) in `ratio`; ε = `eps_relative` × ratio.
template <class Add>
void sphere_gauss_newton_contributions(const std::vector<Vec3>& p, const std::vector<Face>& faces,
                                       const std::vector<double>& w_flat, const std::vector<double>& w_cone,
                                       const Tangent_frames& T, const Sparse_matrix& K, double eps_relative,
                                       double& ratio, Add&& add)
{
  double trace_H = 0;
  std::array<std::array<double, 2>, 3> g, gc;
  for(std::size_t f = 0; f < faces.size(); ++f) {
    const Face& t = faces[f];
    for(int k = 0; k < 3; ++k) {
      const std::size_t v = std::size_t(t[k]);
      Vec3 flat, cone;
      corner_area_gradients(p[v], p[std::size_t(t[(k + 1) % 3])], p[std::size_t(t[(k + 2) % 3])], flat, cone);
      g[std::size_t(k)] = T.coordinates(v, flat);
      gc[std::size_t(k)] = T.coordinates(v, cone);
    }
    for(int k = 0; k < 3; ++k)
      for(int l = 0; l < 3; ++l)
        for(int a = 0; a < 2; ++a)
          for(int b = 0; b < 2; ++b) {
            const std::size_t i = std::size_t(k), j = std::size_t(l), x = std::size_t(a), y = std::size_t(b);
            const double v = w_flat[f] * g[i][x] * g[j][y] + w_cone[f] * gc[i][x] * gc[j][y];
            add(2 * t[k] + a, 2 * t[l] + b, v);
            if(k == l && a == b) trace_H += v;
          }
  }
  double trace_S = 0;
  for(int k = 0; k < K.outerSize(); ++k)
    for(Sparse_matrix::InnerIterator it(K, k); it; ++it)
      if(it.row() == it.col()) trace_S += 2 * it.value();
  ratio = trace_S > 0 ? trace_H / trace_S : 1;
  const double eps = eps_relative * ratio;
  for(int k = 0; k < K.outerSize(); ++k)
    for(Sparse_matrix::InnerIterator it(K, k); it; ++it) {
      const std::size_t i = std::size_t(it.row()), j = std::size_t(it.col());
      // S_ij = K_ij Tᵢᵀ Tⱼ (2 × 2)
      const double m00 = dot(T.e1[i], T.e1[j]), m01 = dot(T.e1[i], T.e2[j]);
      const double m10 = dot(T.e2[i], T.e1[j]), m11 = dot(T.e2[i], T.e2[j]);
      const double v = eps * it.value();
      add(int(2 * i), int(2 * j), v * m00);
      add(int(2 * i), int(2 * j + 1), v * m01);
      add(int(2 * i + 1), int(2 * j), v * m10);
      add(int(2 * i + 1), int(2 * j + 1), v * m11);
    }
}

/// H + ε S (see sphere_gauss_newton_contributions) as a matrix.
inline Sparse_matrix sphere_gauss_newton_matrix(const std::vector<Vec3>& p, const std::vector<Face>& faces,
                                                const std::vector<double>& w_flat, const std::vector<double>& w_cone,
                                                const Tangent_frames& T, const Sparse_matrix& K, double eps_relative,
                                                double& ratio)
{
  const std::size_t n = p.size();
  std::vector<Eigen::Triplet<double> > trip;
  trip.reserve(faces.size() * 36 + std::size_t(K.nonZeros()) * 4);
  sphere_gauss_newton_contributions(p, faces, w_flat, w_cone, T, K, eps_relative, ratio,
                                    [&trip](int i, int j, double v) { trip.emplace_back(i, j, v); });
  Sparse_matrix A(Eigen::Index(2 * n), Eigen::Index(2 * n));
  A.setFromTriplets(trip.begin(), trip.end());
  A.makeCompressed();
  return A;
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
