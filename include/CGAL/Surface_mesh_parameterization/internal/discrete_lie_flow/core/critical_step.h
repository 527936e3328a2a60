// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Closed-form critical steps: the smallest positive λ at which a triangle
// moving linearly (p_k + λ d_k) becomes degenerate (paper §5.4, Eq. (4)).

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_CRITICAL_STEP_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_CRITICAL_STEP_H

#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/geometry.h>

#include <array>
#include <cmath>
#include <limits>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// Smallest root λ > 0 of `a λ² + b λ + c`, or +∞ when there is none.
/// Uses the cancellation-free pair `q = -(b + sign(b)·sqrt(Δ))/2`, roots
/// `q/a` and `c/q`, so `a ≈ 0` degrades gracefully to the linear root `-c/b`.
/// A root at exactly 0 (c == 0) is not positive: the triangle is already
/// degenerate, which the caller has to refuse before asking for a step.
inline double smallest_positive_root(double a, double b, double c)
{
  double best = infinite_step();
  auto take = [&best](double r) { if(r > 0 && r < best) best = r; };
  if(a == 0) {
    if(b != 0) take(-c / b);
    return best;
  }
  const double disc = b * b - 4 * a * c;
  if(disc < 0) return best;
  const double sq = std::sqrt(disc);
  const double q = -0.5 * (b + (b >= 0 ? sq : -sq));
  if(q != 0) {
    take(q / a);
    take(c / q);
  } else {
    // b == 0 and disc == 0, hence c == 0: a double root at 0.
  }
  return best;
}

/// Smallest root λ > 0 of `a λ³ + b λ² + c λ + d`, or +∞.
/// Real roots are bracketed between the critical points of the cubic and
/// polished by safeguarded Newton–bisection, which stays accurate for
/// near-multiple roots where the trigonometric formula loses half the digits.
inline double smallest_positive_root(double a, double b, double c, double d)
{
  if(a == 0) return smallest_positive_root(b, c, d);
  auto f = [&](double x) { return ((a * x + b) * x + c) * x + d; };
  auto df = [&](double x) { return (3 * a * x + 2 * b) * x + c; };
  // Interval [0, R] with R a Cauchy bound on the roots' magnitude.
  const double R = 1 + std::max(std::abs(b / a), std::max(std::abs(c / a), std::abs(d / a)));
  // Critical points split (0, R] into monotone pieces.
  double cuts[4];
  int n = 0;
  cuts[n++] = 0;
  {
    const double r1 = smallest_positive_root(3 * a, 2 * b, c);
    if(r1 < R) {
      cuts[n++] = r1;
      // second critical point: the other root of 3aλ² + 2bλ + c
      const double prod = c / (3 * a);
      const double r2 = (r1 != 0) ? prod / r1 : infinite_step();
      if(r2 > r1 && r2 < R) cuts[n++] = r2;
    }
  }
  cuts[n++] = R;
  for(int k = 0; k + 1 < n; ++k) {
    double lo = cuts[k], hi = cuts[k + 1];
    double flo = f(lo), fhi = f(hi);
    if(flo == 0 && lo > 0) return lo;
    if(fhi == 0) return hi;
    if((flo < 0) == (fhi < 0)) continue;
    double x = 0.5 * (lo + hi);
    for(int it = 0; it < 200; ++it) {
      const double fx = f(x);
      if(fx == 0) break;
      if((fx < 0) == (flo < 0)) { lo = x; flo = fx; } else { hi = x; }
      const double dfx = df(x);
      double nx = (dfx != 0) ? x - fx / dfx : 0.5 * (lo + hi);
      if(!(nx > lo && nx < hi)) nx = 0.5 * (lo + hi);
      if(nx == x || hi - lo <= 4 * std::numeric_limits<double>::epsilon() * hi) { x = nx; break; }
      x = nx;
    }
    if(x > 0) return x;
  }
  return infinite_step();
}

/// Coefficients (a, b, c) of twice the signed area of the planar triangle
/// (p0 + λ d0, p1 + λ d1, p2 + λ d2), in difference form so that c is the
/// current (accurate) doubled area.
inline std::array<double, 3> doubled_area_quadratic(const Vec2& p0, const Vec2& p1, const Vec2& p2,
                                                    const Vec2& d0, const Vec2& d1, const Vec2& d2)
{
  const double ex = p1[0] - p0[0], ey = p1[1] - p0[1];
  const double fx = p2[0] - p0[0], fy = p2[1] - p0[1];
  const double gx = d1[0] - d0[0], gy = d1[1] - d0[1];
  const double hx = d2[0] - d0[0], hy = d2[1] - d0[1];
  return {{ gx * hy - gy * hx,
            ex * hy - ey * hx + gx * fy - gy * fx,
            ex * fy - ey * fx }};
}

/// Critical step of a positively oriented planar triangle moving along
/// (d0, d1, d2): the first λ > 0 where its signed area vanishes, +∞ if never.
inline double critical_step_2(const Vec2& p0, const Vec2& p1, const Vec2& p2,
                              const Vec2& d0, const Vec2& d1, const Vec2& d2)
{
  const std::array<double, 3> q = doubled_area_quadratic(p0, p1, p2, d0, d1, d2);
  return smallest_positive_root(q[0], q[1], q[2]);
}

/// Coefficients (a, b, c, d) of det[p0 + λ t0, p1 + λ t1, p2 + λ t2], the
/// orientation of a spherical triangle seen from the centre. Written in the
/// difference form det[p0, p1 − p0, p2 − p0], whose rounding error scales with
/// the triangle and not with the unit vectors.
inline std::array<double, 4> orientation_cubic(const Vec3& p0, const Vec3& p1, const Vec3& p2,
                                               const Vec3& t0, const Vec3& t1, const Vec3& t2)
{
  const Vec3 e = sub(p1, p0), f = sub(p2, p0);
  const Vec3 g = sub(t1, t0), h = sub(t2, t0);
  // det[P + λT, E + λG, F + λH] expanded by multilinearity.
  const Vec3 ef = cross(e, f), eh = cross(e, h), gf = cross(g, f), gh = cross(g, h);
  return {{ dot(t0, gh),
            dot(p0, gh) + dot(t0, eh) + dot(t0, gf),
            dot(p0, eh) + dot(p0, gf) + dot(t0, ef),
            dot(p0, ef) }};
}

/// Critical step of a positively oriented spherical triangle (unit vectors
/// moving as p_k + λ t_k, re-normalised afterwards: normalising by positive
/// lengths does not change the sign of the determinant).
inline double critical_step_sphere(const Vec3& p0, const Vec3& p1, const Vec3& p2,
                                   const Vec3& t0, const Vec3& t1, const Vec3& t2)
{
  const std::array<double, 4> c = orientation_cubic(p0, p1, p2, t0, t1, t2);
  return smallest_positive_root(c[0], c[1], c[2], c[3]);
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
