// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Lawson flips of a triangulation of the unit sphere towards its Delaunay
// triangulation (the convex hull of the points), decided by exact predicates
// on the stored doubles. The twin structure and the flip itself are the
// planar ones (edge_flips.h); only the tests differ.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_SPHERE_EDGE_FLIPS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_SPHERE_EDGE_FLIPS_H

#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/certification.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/edge_flips.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// The four vertices of the flip of halfedge h = (f, k) with twin (g, m):
/// faces (a, b, c) and (d, c, b), the edge bc and its opposite corners a, d.
struct Flip_quad
{
  int a, b, c, d;
};

inline Flip_quad flip_quad(const Flip_triangulation& tri, int h)
{
  const int o = tri.twin[std::size_t(h)];
  const int f = h / 3, k = h % 3, g = o / 3, m = o % 3;
  const Face& F = tri.faces[std::size_t(f)];
  return { F[std::size_t(k)], F[std::size_t((k + 1) % 3)], F[std::size_t((k + 2) % 3)], tri.faces[std::size_t(g)][std::size_t(m)] };
}

/// Whether the edge of halfedge h is locally Delaunay on the sphere: d is not
/// strictly inside the circumcircle of abc. On the sphere that circle is the
/// intersection with the plane of abc, and its inside (the cap of the
/// positively oriented abc) is the side of the plane away from the centre,
/// so the test is the sign of the exact `orientation(a, b, c, d)`. A border
/// edge (no twin) is Delaunay.
inline bool sphere_edge_is_locally_delaunay(const Flip_triangulation& tri, const std::vector<Vec3>& p, int h)
{
  if(tri.twin[std::size_t(h)] < 0) return true;
  typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_3 P;
  auto pt = [&p](int v) { const Vec3& q = p[std::size_t(v)]; return P(q[0], q[1], q[2]); };
  const Flip_quad q = flip_quad(tri, h);
  return CGAL::orientation(pt(q.a), pt(q.b), pt(q.c), pt(q.d)) != CGAL::POSITIVE;
}

/// Whether vertices u and w share an edge, by a walk around u starting at
/// face f (which must contain u); bounded, and exact on border vertices too.
inline bool sphere_edge_exists(const Flip_triangulation& tri, int f, int u, int w)
{
  const int start = f;
  for(std::size_t steps = 0; steps <= tri.faces.size(); ++steps) {
    const Face& F = tri.faces[std::size_t(f)];
    int i = 0;
    while(i < 3 && F[std::size_t(i)] != u) ++i;
    if(i == 3) return false; // not a face around u: broken structure, refuse nothing
    if(F[std::size_t((i + 1) % 3)] == w || F[std::size_t((i + 2) % 3)] == w) return true;
    // Cross the edge u → F[i + 1]: halfedge 3f + (i + 2) goes from corner i to corner i + 1.
    const int t = tri.twin[std::size_t(3 * f + (i + 2) % 3)];
    if(t < 0) break;
    f = t / 3;
    if(f == start) return false;
  }
  // A border on one side: walk the other way.
  f = start;
  for(std::size_t steps = 0; steps <= tri.faces.size(); ++steps) {
    const Face& F = tri.faces[std::size_t(f)];
    int i = 0;
    while(i < 3 && F[std::size_t(i)] != u) ++i;
    if(i == 3) return false;
    if(F[std::size_t((i + 1) % 3)] == w || F[std::size_t((i + 2) % 3)] == w) return true;
    // Cross the edge F[i + 2] → u: halfedge 3f + (i + 1).
    const int t = tri.twin[std::size_t(3 * f + (i + 1) % 3)];
    if(t < 0 || t / 3 == start) return false;
    f = t / 3;
  }
  return false;
}

/// Whether flipping halfedge h keeps the triangulation valid: both new faces
/// (a, b, d) and (a, d, c) positively oriented seen from the centre (exact),
/// and the new edge ad not already present (a vertex of valence 3).
inline bool sphere_flip_is_valid(const Flip_triangulation& tri, const std::vector<Vec3>& p, int h)
{
  if(tri.twin[std::size_t(h)] < 0) return false;
  const Flip_quad q = flip_quad(tri, h);
  if(q.a == q.d) return false;
  const Vec3 &a = p[std::size_t(q.a)], &b = p[std::size_t(q.b)], &c = p[std::size_t(q.c)], &d = p[std::size_t(q.d)];
  if(exact_orientation_sphere(a, b, d) != CGAL::POSITIVE || exact_orientation_sphere(a, d, c) != CGAL::POSITIVE)
    return false;
  return !sphere_edge_exists(tri, h / 3, q.a, q.d);
}

/// Lawson flips until every edge is locally Delaunay on the sphere or its
/// flip would be invalid (bounded by `max_flips`). On points of the unit
/// sphere each flip adds the tetrahedron abcd to the enclosed volume, so the
/// exact decisions cannot cycle. Calls on_change(f) for every changed face.
template <class OnChange>
std::size_t make_delaunay_sphere(Flip_triangulation& tri, const std::vector<Vec3>& p, OnChange on_change,
                                 std::size_t max_flips)
{
  std::vector<int> stack;
  for(int h = 0; h < int(tri.twin.size()); ++h)
    if(tri.twin[std::size_t(h)] > h) stack.push_back(h);
  std::size_t flips = 0;
  while(!stack.empty() && flips < max_flips) {
    const int h = stack.back();
    stack.pop_back();
    if(tri.twin[std::size_t(h)] < 0 || sphere_edge_is_locally_delaunay(tri, p, h) || !sphere_flip_is_valid(tri, p, h))
      continue;
    const int f = h / 3, g = tri.twin[std::size_t(h)] / 3;
    tri.flip(h, on_change);
    ++flips;
    for(int e : { 3 * f + 0, 3 * f + 2, 3 * g + 0, 3 * g + 1 })
      if(tri.twin[std::size_t(e)] >= 0) stack.push_back(e);
  }
  return flips;
}

/// Edges that are not locally Delaunay on the sphere (each counted once).
inline std::size_t count_non_delaunay_edges_sphere(const Flip_triangulation& tri, const std::vector<Vec3>& p)
{
  std::size_t n = 0;
  for(int h = 0; h < int(tri.twin.size()); ++h)
    if(tri.twin[std::size_t(h)] > h && !sphere_edge_is_locally_delaunay(tri, p, h)) ++n;
  return n;
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
