// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Validity of a domain triangulation, decided only by CGAL's exact
// orientation predicates evaluated on the very doubles that are stored.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_CERTIFICATION_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_CERTIFICATION_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/geometry.h>

#include <array>
#include <atomic>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// Exact orientation of the planar triangle (a, b, c).
inline CGAL::Orientation exact_orientation_2(const Vec2& a, const Vec2& b, const Vec2& c)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_2 P;
  return CGAL::orientation(P(a[0], a[1]), P(b[0], b[1]), P(c[0], c[1]));
}

/// Exact orientation of the spherical triangle (a, b, c) seen from the origin:
/// the sign of det[a, b, c].
inline CGAL::Orientation exact_orientation_sphere(const Vec3& a, const Vec3& b, const Vec3& c)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_3 P;
  return CGAL::orientation(P(0, 0, 0), P(a[0], a[1], a[2]), P(b[0], b[1], b[2]), P(c[0], c[1], c[2]));
}

/// Counts of a triangulation's faces by exact orientation.
struct Orientation_count
{
  std::size_t inverted = 0;    ///< negatively oriented
  std::size_t degenerate = 0;  ///< collinear (zero area)
  int first_bad = -1;          ///< index of the first face that is not positive, -1 if none
  bool all_positive() const { return inverted == 0 && degenerate == 0; }
};

template <class Point, class Orient>
Orientation_count count_orientations(const std::vector<Point>& pts, const std::vector<Face>& faces,
                                     Orient orient, bool stop_at_first = false)
{
  Orientation_count r;
  for(std::size_t f = 0; f < faces.size(); ++f) {
    const Face& t = faces[f];
    const CGAL::Orientation o = orient(pts[t[0]], pts[t[1]], pts[t[2]]);
    if(o == CGAL::POSITIVE) continue;
    if(o == CGAL::NEGATIVE) ++r.inverted; else ++r.degenerate;
    if(r.first_bad < 0) r.first_bad = int(f);
    if(stop_at_first) break;
  }
  return r;
}

/// Exact orientation counts of planar domain faces.
inline Orientation_count count_orientations_2(const std::vector<Vec2>& uv, const std::vector<Face>& faces,
                                              bool stop_at_first = false)
{
  return count_orientations(uv, faces, &exact_orientation_2, stop_at_first);
}

/// Exact orientation counts of spherical domain faces.
inline Orientation_count count_orientations_sphere(const std::vector<Vec3>& p, const std::vector<Face>& faces,
                                                   bool stop_at_first = false)
{
  return count_orientations(p, faces, &exact_orientation_sphere, stop_at_first);
}

/// Test seam: the next `n` trial steps that reach the exact check are refused
/// whatever their map (`forced_trial_refusals() = n`). The flows' refusal path
/// (count the refusal, halve the step, go on) is otherwise reached only by a
/// rounding event at the level of a triangle's last bits, which no input can
/// be built to produce on every floating-point kernel. 0 outside tests.
inline std::atomic<std::size_t>& forced_trial_refusals()
{
  static std::atomic<std::size_t> n{0};
  return n;
}

/// Takes one forced refusal if any is left (thread-safe: the volume's checks
/// may run concurrently).
inline bool take_forced_trial_refusal()
{
  std::atomic<std::size_t>& n = forced_trial_refusals();
  std::size_t k = n.load(std::memory_order_relaxed);
  while(k > 0 && !n.compare_exchange_weak(k, k - 1, std::memory_order_relaxed)) {}
  return k > 0;
}

/// The last word on a flow's trial step in the plane: every face positive.
inline bool certified_trial_2(const std::vector<Vec2>& uv, const std::vector<Face>& faces)
{
  return !take_forced_trial_refusal() && count_orientations_2(uv, faces, true).all_positive();
}

/// The last word on a flow's trial step on the sphere: every face positive.
inline bool certified_trial_sphere(const std::vector<Vec3>& p, const std::vector<Face>& faces)
{
  return !take_forced_trial_refusal() && count_orientations_sphere(p, faces, true).all_positive();
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
