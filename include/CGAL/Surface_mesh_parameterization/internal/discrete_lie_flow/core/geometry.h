// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The base types of the flows, in index form: points in the plane and in
// space, triangles as vertex-index triples, and the few vector operations
// every other header builds on. Conventions: doc/design.md, "Conventions".

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_GEOMETRY_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_GEOMETRY_H

#include <array>
#include <cmath>
#include <limits>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

typedef std::array<double, 2> Vec2;
typedef std::array<double, 3> Vec3;
/// A triangle by the indices of its corners, counter-clockwise in the domain.
typedef std::array<int, 3> Face;

/// The step bound of a triangle that never degenerates.
inline constexpr double infinite_step() { return std::numeric_limits<double>::infinity(); }

inline Vec3 cross(const Vec3& u, const Vec3& v)
{
  return {{ u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0] }};
}
inline double dot(const Vec3& u, const Vec3& v) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; }
inline Vec3 sub(const Vec3& u, const Vec3& v) { return {{ u[0] - v[0], u[1] - v[1], u[2] - v[2] }}; }
inline double norm3(const Vec3& v) { return std::sqrt(dot(v, v)); }

inline Vec3 normalized(const Vec3& v)
{
  const double l = std::sqrt(dot(v, v));
  return {{ v[0] / l, v[1] / l, v[2] / l }};
}

/// Area of a triangle in space.
inline double triangle_area_3(const Vec3& a, const Vec3& b, const Vec3& c)
{
  return 0.5 * norm3(cross(sub(b, a), sub(c, a)));
}

/// Signed area of a planar triangle (positive counter-clockwise), in doubles.
inline double signed_area_2(const Vec2& a, const Vec2& b, const Vec2& c)
{
  return 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
