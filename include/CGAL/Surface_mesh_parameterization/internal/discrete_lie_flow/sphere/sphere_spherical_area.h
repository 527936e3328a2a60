// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The spherical area of a triangle between unit vectors, as an area element
// of the spherical flow's opening. The cone area ½ det[a, b, c] vanishes for
// a triangle whose plane passes through the centre whichever side of it the
// triangle covers: a face spread over nearly a hemisphere (corners near one
// great circle) looks as small to it as a degenerate one, so an opening on
// cone areas can leave a few faces holding most of the sphere while their
// energy looks right (doc/sphere.md, "Fans of needles in the opening").
// The spherical area 2 atan2(det[a, b, c], 1 + a·b + b·c + c·a) (the
// Van Oosterom–Strackee formula) sees such a face as large; it is positive
// exactly when the determinant is (so it keeps the orientation predicate's
// sign) and agrees with the cone area to second order on small triangles.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_SPHERE_SPHERICAL_AREA_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_SPHERE_SPHERICAL_AREA_H

#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/sphere/sphere_problem.h>

#include <cmath>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// Area of the spherical triangle (a, b, c) of unit vectors, in (0, 2π) when
/// det[a, b, c] > 0, in (−2π, 0) when it is negative, 0 when it vanishes.
/// The determinant in the difference form of `cone_area_sphere()`.
inline double spherical_area_sphere(const Vec3& a, const Vec3& b, const Vec3& c)
{
  return 2 * std::atan2(2 * cone_area_sphere(a, b, c), 1 + dot(a, b) + dot(b, c) + dot(c, a));
}

inline void spherical_areas_sphere(const std::vector<Vec3>& p, const std::vector<Face>& faces, std::vector<double>& out)
{
  out.resize(faces.size());
  for(std::size_t f = 0; f < faces.size(); ++f)
    out[f] = spherical_area_sphere(p[std::size_t(faces[f][0])], p[std::size_t(faces[f][1])], p[std::size_t(faces[f][2])]);
}

/// ∂E/∂p from per-face ∂E/∂u_t on the spherical areas: with N = det[a, b, c]
/// and D = 1 + a·b + b·c + c·a, ∂u/∂a = 2 (D b × c − N (b + c)) / (N² + D²).
inline void spherical_position_gradient(const std::vector<Vec3>& p, const std::vector<Face>& faces,
                                        const std::vector<double>& dE, std::vector<Vec3>& g)
{
  g.assign(p.size(), Vec3{{ 0, 0, 0 }});
  for(std::size_t f = 0; f < faces.size(); ++f) {
    const Face& t = faces[f];
    const Vec3 &p0 = p[std::size_t(t[0])], &p1 = p[std::size_t(t[1])], &p2 = p[std::size_t(t[2])];
    const double N = 2 * cone_area_sphere(p0, p1, p2), D = 1 + dot(p0, p1) + dot(p1, p2) + dot(p2, p0);
    const double s = 2 * dE[f] / (N * N + D * D);
    for(int k = 0; k < 3; ++k) {
      const Vec3 &a = p[std::size_t(t[k])], &b = p[std::size_t(t[(k + 1) % 3])], &c = p[std::size_t(t[(k + 2) % 3])];
      Vec3 flat, cone;
      corner_area_gradients(a, b, c, flat, cone); // cone = ½ b × c, accurate on tiny faces
      Vec3& gk = g[std::size_t(t[k])];
      for(std::size_t j = 0; j < 3; ++j) gk[j] += s * (2 * D * cone[j] - N * (b[j] + c[j]));
    }
  }
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
