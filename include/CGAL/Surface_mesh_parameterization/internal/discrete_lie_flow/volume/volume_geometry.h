// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What every volumetric flow measures on its tets: the signed volumes, the
// cubic of a tet whose corners move linearly and its first root (the
// critical step), and the border triangles seen from the centre.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_VOLUME_GEOMETRY_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_VOLUME_GEOMETRY_H

#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/critical_step.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/volume/volume_mesh.h>

#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// Coefficients (a, b, c, d) of det[p1 − p0 + λ(d1 − d0), p2 − p0 + λ(d2 − d0), p3 − p0 + λ(d3 − d0)],
/// six times the volume of a tet whose corners move linearly (difference
/// form: d is the current determinant).
inline std::array<double, 4> tet_volume_cubic(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3,
                                              const Vec3& d0, const Vec3& d1, const Vec3& d2, const Vec3& d3)
{
  const Vec3 a1 = sub(p1, p0), a2 = sub(p2, p0), a3 = sub(p3, p0);
  const Vec3 b1 = sub(d1, d0), b2 = sub(d2, d0), b3 = sub(d3, d0);
  auto det = [](const Vec3& x, const Vec3& y, const Vec3& z) { return dot(x, cross(y, z)); };
  return {{ det(b1, b2, b3),
            det(a1, b2, b3) + det(b1, a2, b3) + det(b1, b2, a3),
            det(b1, a2, a3) + det(a1, b2, a3) + det(a1, a2, b3),
            det(a1, a2, a3) }};
}

/// The first λ > 0 at which a positive tet moving along (d0, …, d3) degenerates, +∞ if never.
inline double critical_step_tet(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3,
                                const Vec3& d0, const Vec3& d1, const Vec3& d2, const Vec3& d3)
{
  const std::array<double, 4> c = tet_volume_cubic(p0, p1, p2, p3, d0, d1, d2, d3);
  return smallest_positive_root(c[0], c[1], c[2], c[3]);
}

/// Border triangles that the exact predicate does not find positive seen
/// from the centre: orientation(O, a, b, c) ≠ POSITIVE.
inline std::size_t count_bad_border_faces(const std::vector<Vec3>& x, const std::vector<std::array<int, 3> >& faces)
{
  std::size_t n = 0;
  const Vec3 o = {{ 0, 0, 0 }};
  for(const auto& f : faces)
    if(exact_tet_orientation(o, x[std::size_t(f[0])], x[std::size_t(f[1])], x[std::size_t(f[2])]) != POSITIVE) ++n;
  return n;
}

/// Six times the signed volumes of all tets (doubles).
inline void tet_dets(const std::vector<Vec3>& x, const std::vector<Tet>& tets, std::vector<double>& u)
{
  u.resize(tets.size());
  for(std::size_t t = 0; t < tets.size(); ++t) {
    const Tet& k = tets[t];
    u[t] = tet_det(x[std::size_t(k[0])], x[std::size_t(k[1])], x[std::size_t(k[2])], x[std::size_t(k[3])]);
  }
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
