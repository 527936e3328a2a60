// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Distortion metrics of a piecewise-linear map from the input triangles to
// domain triangles (planar, or flat triangles between sphere points), with
// the definitions of doc/design.md (the paper's Table 1, made precise).

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_DISTORTION_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_DISTORTION_H

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_report.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/certification.h>

#include <algorithm>
#include <cmath>
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
  double log_sum = 0, log_sq = 0;
  std::size_t counted = 0;
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

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
