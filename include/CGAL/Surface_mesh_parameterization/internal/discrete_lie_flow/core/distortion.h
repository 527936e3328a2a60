// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Distortion metrics of a piecewise-linear map from the input triangles to
// domain triangles (planar, or flat triangles between sphere points), with
// the definitions of doc/design.md (the paper's Table 1, made precise).

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_DISTORTION_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_DISTORTION_H

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_report.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/certification.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

typedef Discrete_lie_flow_distortion Distortion_metrics;

/// The smallest angle (radians) of a triangle in 3D.
inline double min_angle_3(const Vec3& a, const Vec3& b, const Vec3& c)
{
  const Vec3* p[3] = { &a, &b, &c };
  double m = M_PI;
  for(int k = 0; k < 3; ++k) {
    const Vec3 u = sub(*p[(k + 1) % 3], *p[k]), v = sub(*p[(k + 2) % 3], *p[k]);
    m = (std::min)(m, std::atan2(norm3(cross(u, v)), dot(u, v)));
  }
  return m;
}

/// |μ| of the affine map taking the planar triangle a to the planar triangle
/// b: with J its Jacobian, f_z = ½(J00 + J11) + ½i(J10 − J01) and
/// f_z̄ = ½(J00 − J11) + ½i(J10 + J01). −1 when a or b is degenerate.
inline double affine_beltrami(const Vec2& a0, const Vec2& a1, const Vec2& a2,
                              const Vec2& b0, const Vec2& b1, const Vec2& b2)
{
  const double a00 = a1[0] - a0[0], a01 = a2[0] - a0[0], a10 = a1[1] - a0[1], a11 = a2[1] - a0[1];
  const double b00 = b1[0] - b0[0], b01 = b2[0] - b0[0], b10 = b1[1] - b0[1], b11 = b2[1] - b0[1];
  const double da = a00 * a11 - a01 * a10, db = b00 * b11 - b01 * b10;
  if(da == 0 || db == 0 || !std::isfinite(da) || !std::isfinite(db)) return -1;
  // J = B A⁻¹; the common factor 1/da cancels in the ratio.
  const double j00 = b00 * a11 - b01 * a10, j01 = -b00 * a01 + b01 * a00;
  const double j10 = b10 * a11 - b11 * a10, j11 = -b10 * a01 + b11 * a00;
  const double fz = std::hypot(j00 + j11, j10 - j01), fzbar = std::hypot(j00 - j11, j10 + j01);
  return fz > 0 ? fzbar / fz : std::numeric_limits<double>::infinity();
}

/// The third corner of the triangle (a, b, c) in its own plane, with a at
/// the origin and b on the positive x axis (c above it).
inline Vec2 in_plane(const Vec3& a, const Vec3& b, const Vec3& c)
{
  const Vec3 u = sub(b, a), v = sub(c, a);
  const double lu = norm3(u);
  if(!(lu > 0)) return {{ 0., 0. }};
  return {{ dot(u, v) / lu, norm3(cross(u, v)) / lu }};
}

/// The paper's Table 1 "Wasserstein distance" and Area_total: the L² and
/// L¹ distances between the faces' shares `A / sumA` and `Ad / sumAd`.
inline void share_distances(const std::vector<double>& A, const std::vector<double>& Ad, double sumA, double sumAd,
                            Distortion_metrics& m)
{
  for(std::size_t f = 0; f < A.size(); ++f) {
    const double share_in = A[f] / sumA, share_out = sumAd > 0 ? Ad[f] / sumAd : 0.;
    m.wasserstein_table1 += (share_in - share_out) * (share_in - share_out);
    m.area_total += std::abs(share_in - share_out);
  }
  m.wasserstein_table1 = std::sqrt(m.wasserstein_table1);
}

/// |μ| = |f_z̄| / |f_z| of the affine map of the triangle (q0, q1, q2) onto
/// (p0, p1, p2), each laid out in its own plane; an inverted face is
/// mirrored, so |μ| > 1; +∞ for a sliver that rounding flattened.
inline double face_beltrami(const Vec3& q0, const Vec3& q1, const Vec3& q2, const Vec3& p0, const Vec3& p1,
                            const Vec3& p2, bool inverted)
{
  const Vec2 q2d[3] = { {{ 0., 0. }}, {{ norm3(sub(q1, q0)), 0. }}, in_plane(q0, q1, q2) };
  Vec2 p2d[3] = { {{ 0., 0. }}, {{ norm3(sub(p1, p0)), 0. }}, in_plane(p0, p1, p2) };
  if(inverted) p2d[2][1] = -p2d[2][1];
  const double mu = affine_beltrami(q2d[0], q2d[1], q2d[2], p2d[0], p2d[1], p2d[2]);
  return mu < 0 ? std::numeric_limits<double>::infinity() : mu;
}

/// Metrics of the map xyz → dom over `faces`. `dom` holds domain points in 3D
/// (z = 0 for planar maps). `orientation_positive(f)` tells the exact sign of
/// face f on the domain (+1, 0, −1). `density` is per face, empty for ρ ≡ 1.
template <class OrientationOfFace>
Distortion_metrics distortion_metrics(const std::vector<Vec3>& xyz, const std::vector<Vec3>& dom,
                                      const std::vector<Face>& faces, const std::vector<double>& density,
                                      OrientationOfFace orientation_of_face)
{
  Distortion_metrics m;
  const std::size_t F = faces.size();
  if(F == 0) return m;
  std::vector<double> A(F), Ad(F);
  std::vector<int> sgn(F);
  double sumA = 0, sumAd = 0;
  long balance = 0;
  for(std::size_t f = 0; f < F; ++f) {
    const Face& t = faces[f];
    const double rho = density.empty() ? 1. : density[f];
    A[f] = rho * triangle_area_3(xyz[t[0]], xyz[t[1]], xyz[t[2]]);
    Ad[f] = triangle_area_3(dom[t[0]], dom[t[1]], dom[t[2]]);
    sgn[f] = orientation_of_face(f);
    balance += sgn[f];
    sumA += A[f];
    sumAd += Ad[f];
  }
  const int majority = balance >= 0 ? 1 : -1;
  const double scale2 = sumAd > 0 ? sumA / sumAd : 1.; // s² with s the uniform domain scale
  double min_angle = M_PI;
  double log_sum = 0, log_sq = 0, beltrami_sum = 0;
  std::size_t counted = 0;
  share_distances(A, Ad, sumA, sumAd, m);
  for(std::size_t f = 0; f < F; ++f) {
    const Face& t = faces[f];
    if(sgn[f] == 0 || Ad[f] == 0 || A[f] == 0) { ++m.degenerate_faces; continue; }
    const bool inverted = sgn[f] != majority;
    if(inverted) ++m.inverted_faces;
    const double rho = density.empty() ? 1. : density[f];
    const Vec3 &q0 = xyz[t[0]], &q1 = xyz[t[1]], &q2 = xyz[t[2]];
    const Vec3 &p0 = dom[t[0]], &p1 = dom[t[1]], &p2 = dom[t[2]];
    // |J|_F² = Σ_k cot θ_k |e'_k|² / (2 A), θ_k the source angles; per unit density.
    const Vec3* q[3] = { &q0, &q1, &q2 };
    const Vec3* p[3] = { &p0, &p1, &p2 };
    const double area3 = A[f] / rho;
    double frob = 0;
    for(int k = 0; k < 3; ++k) {
      const Vec3 u = sub(*q[(k + 1) % 3], *q[k]), v = sub(*q[(k + 2) % 3], *q[k]);
      const double cot = dot(u, v) / norm3(cross(u, v));
      const Vec3 e = sub(*p[(k + 2) % 3], *p[(k + 1) % 3]);
      frob += cot * dot(e, e);
    }
    frob = frob / (2 * area3) * scale2 / rho;
    const double det = Ad[f] / A[f] * scale2; // σ1σ2 against the ρ-scaled triangle
    const double disc = std::sqrt((std::max)(0., frob - 2 * det));
    const double sum = std::sqrt(frob + 2 * det);
    const double s1 = 0.5 * (sum + disc), s2 = 0.5 * (sum - disc);
    const double w = A[f] / sumA;
    m.d_area += w * (det + 1 / det);
    const double s2signed = inverted ? -s2 : s2;
    m.arap += w * ((s1 - 1) * (s1 - 1) + (s2signed - 1) * (s2signed - 1));
    m.symmetric_dirichlet += s1 * s1 + 1 / (s1 * s1) + s2 * s2 + 1 / (s2 * s2);
    // |μ| from the triangles in their own planes: the σ above lose half the
    // digits near a conformal map.
    const double mu = face_beltrami(q0, q1, q2, p0, p1, p2, inverted);
    beltrami_sum += mu;
    m.beltrami_weighted_mean += w * mu;
    m.beltrami_max = (std::max)(m.beltrami_max, mu);
    const double la = std::log(det);
    log_sum += std::abs(la);
    log_sq += la * la;
    m.log_area_max_abs = (std::max)(m.log_area_max_abs, std::abs(la));
    ++counted;
    const double a = min_angle_3(p0, p1, p2);
    min_angle = (std::min)(min_angle, a);
    if(a < M_PI / 180) ++m.faces_below_1_degree;
  }
  if(counted > 0) {
    m.log_area_mean_abs = log_sum / double(counted);
    m.log_area_rms = std::sqrt(log_sq / double(counted));
    m.beltrami_mean = beltrami_sum / double(counted);
  }
  m.min_angle_degrees = min_angle * 180 / M_PI;
  return m;
}

/// Metrics of a planar map `uv` of the triangles `faces` over `xyz`.
inline Distortion_metrics planar_distortion(const std::vector<Vec3>& xyz, const std::vector<Vec2>& uv,
                                            const std::vector<Face>& faces,
                                            const std::vector<double>& density = std::vector<double>())
{
  std::vector<Vec3> dom(uv.size());
  for(std::size_t i = 0; i < uv.size(); ++i) dom[i] = {{ uv[i][0], uv[i][1], 0. }};
  return distortion_metrics(xyz, dom, faces, density, [&](std::size_t f) {
    const Face& t = faces[f];
    return int(exact_orientation_2(uv[t[0]], uv[t[1]], uv[t[2]]));
  });
}

/// Metrics of a spherical map (points on the unit sphere; flat domain triangles).
inline Distortion_metrics spherical_distortion(const std::vector<Vec3>& xyz, const std::vector<Vec3>& sph,
                                               const std::vector<Face>& faces,
                                               const std::vector<double>& density = std::vector<double>())
{
  return distortion_metrics(xyz, sph, faces, density, [&](std::size_t f) {
    const Face& t = faces[f];
    return int(exact_orientation_sphere(sph[t[0]], sph[t[1]], sph[t[2]]));
  });
}

/// The difference of the planar maps `a` and `b` of `faces` over `xyz`.
inline Discrete_lie_flow_map_difference map_difference(const std::vector<Vec3>& xyz, const std::vector<Vec2>& a,
                                                       const std::vector<Vec2>& b, const std::vector<Face>& faces,
                                                       const std::vector<double>& density = std::vector<double>())
{
  Discrete_lie_flow_map_difference d;
  std::vector<double> mass(xyz.size(), 0.), area(faces.size());
  double total = 0;
  for(std::size_t f = 0; f < faces.size(); ++f) {
    const Face& t = faces[f];
    area[f] = (density.empty() ? 1. : density[f]) * triangle_area_3(xyz[t[0]], xyz[t[1]], xyz[t[2]]);
    for(int k = 0; k < 3; ++k) mass[std::size_t(t[k])] += area[f] / 3;
    total += area[f];
  }
  if(!(total > 0)) return d;
  double cost = 0;
  for(std::size_t i = 0; i < xyz.size(); ++i) {
    const double dx = b[i][0] - a[i][0], dy = b[i][1] - a[i][1];
    cost += mass[i] / total * (dx * dx + dy * dy);
  }
  d.transport_cost = std::sqrt(cost);
  double sum = 0, weight = 0;
  std::size_t counted = 0;
  for(std::size_t f = 0; f < faces.size(); ++f) {
    const Face& t = faces[f];
    const double mu = affine_beltrami(a[t[0]], a[t[1]], a[t[2]], b[t[0]], b[t[1]], b[t[2]]);
    if(mu < 0) { ++d.faces_not_compared; continue; }
    sum += mu;
    d.beltrami_weighted_mean += area[f] / total * mu;
    weight += area[f] / total;
    d.beltrami_max = (std::max)(d.beltrami_max, mu);
    ++counted;
  }
  if(counted > 0) {
    d.beltrami_mean = sum / double(counted);
    d.beltrami_weighted_mean /= weight;
  }
  return d;
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
