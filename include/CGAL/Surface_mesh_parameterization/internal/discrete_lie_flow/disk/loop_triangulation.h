// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A hole's fill built on the start's own uv polygon by a constrained
// Delaunay triangulation, so that a caller's start can be kept where a fan
// from one virtual vertex cannot: a simple hole polygon that no single point
// sees whole. The fill is checked combinatorially here (it closes the
// caller's loop edge by edge) and by the exact predicate by the caller.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_LOOP_TRIANGULATION_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_LOOP_TRIANGULATION_H

#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/disk/disk_problem.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/geometry.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_face_base_2.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// The constrained Delaunay triangulation of closed uv polygons, each
/// vertex carrying its index in the problem, each face its nesting depth
/// (the constraints crossed from the unbounded face).
class Loop_triangulation
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  typedef CGAL::Triangulation_vertex_base_with_info_2<int, K> Vb;
  typedef CGAL::Triangulation_face_base_with_info_2<int, K> Fbi;
  typedef CGAL::Constrained_triangulation_face_base_2<K, Fbi> Fb;
  typedef CGAL::Triangulation_data_structure_2<Vb, Fb> Tds;
  // Crossing loops, or a vertex on another's edge, are refused, not split:
  // a fill may use the loops' vertices only.
  typedef CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::No_constraint_intersection_tag> CDT;

public:
  /// Inserts the closed polygon `loop` (indices into `uv`); false when a
  /// point repeats one already inserted or an edge meets another loop.
  bool add_loop(const std::vector<Vec2>& uv, const std::vector<int>& loop)
  {
    if(loop.size() < 3) return false;
    std::vector<CDT::Vertex_handle> vh;
    for(int v : loop)
      if(!add_point(uv[std::size_t(v)], v, vh)) return false;
    try {
      for(std::size_t k = 0; k < vh.size(); ++k) m_cdt.insert_constraint(vh[k], vh[(k + 1) % vh.size()]);
    } catch(...) { // CDT::Intersection_of_constraints_exception
      return false;
    }
    return true;
  }

  /// Inserts the point `p` as vertex `v`; false when it repeats one.
  bool add_point(const Vec2& p, int v)
  {
    std::vector<CDT::Vertex_handle> vh;
    try {
      return add_point(p, v, vh);
    } catch(...) {
      return false;
    }
  }

  /// The faces at nesting depth `depth`, counter-clockwise in uv.
  std::vector<Face> faces_at_depth(int depth)
  {
    mark_depths();
    std::vector<Face> out;
    for(CDT::Finite_faces_iterator f = m_cdt.finite_faces_begin(); f != m_cdt.finite_faces_end(); ++f)
      if(f->info() == depth)
        out.push_back(Face{{ f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info() }});
    return out;
  }

private:
  bool add_point(const Vec2& p, int v, std::vector<CDT::Vertex_handle>& vh)
  {
    if(!std::isfinite(p[0]) || !std::isfinite(p[1])) return false;
    const std::size_t before = m_cdt.number_of_vertices();
    CDT::Vertex_handle h = m_cdt.insert(K::Point_2(p[0], p[1]));
    if(m_cdt.number_of_vertices() != before + 1) return false;
    h->info() = v;
    vh.push_back(h);
    return true;
  }

  // Depth by a walk from the unbounded face: within a depth, across
  // unconstrained edges; one deeper across a constraint.
  void mark_depths()
  {
    for(CDT::All_faces_iterator f = m_cdt.all_faces_begin(); f != m_cdt.all_faces_end(); ++f) f->info() = -1;
    std::deque<std::pair<CDT::Face_handle, int> > next(1, std::make_pair(m_cdt.infinite_face(), 0));
    while(!next.empty()) {
      const std::pair<CDT::Face_handle, int> seed = next.front();
      next.pop_front();
      if(seed.first->info() != -1) continue;
      std::vector<CDT::Face_handle> stack(1, seed.first);
      seed.first->info() = seed.second;
      while(!stack.empty()) {
        const CDT::Face_handle f = stack.back();
        stack.pop_back();
        for(int i = 0; i < 3; ++i) {
          const CDT::Face_handle g = f->neighbor(i);
          if(g->info() != -1) continue;
          if(f->is_constrained(i)) next.push_back(std::make_pair(g, seed.second + 1));
          else { g->info() = seed.second; stack.push_back(g); }
        }
      }
    }
  }

  CDT m_cdt;
};

/// Whether `fill` closes the directed loop edges `edges` (each loop edge
/// a → b must be an edge of a fill face with that direction) and uses no
/// directed edge twice: the fill then lies on the loop's open side, as the
/// caller's faces across it require.
inline bool fill_closes(const std::vector<Face>& fill, const std::vector<std::pair<int, int> >& edges)
{
  std::set<std::pair<int, int> > directed;
  for(const Face& t : fill)
    for(int k = 0; k < 3; ++k)
      if(!directed.insert(std::make_pair(t[std::size_t(k)], t[std::size_t((k + 1) % 3)])).second) return false;
  for(const std::pair<int, int>& e : edges)
    if(directed.count(e) == 0) return false;
  return true;
}

/// `faces` turned to the caller's orientation (`sign` < 0: clockwise in uv).
inline void orient_faces(std::vector<Face>& faces, double sign)
{
  if(sign < 0)
    for(Face& t : faces) std::swap(t[1], t[2]);
}

/// The triangulation of the hole polygon `loop` (its fill faces (loop[k],
/// loop[k+1], c) in `P` name its edges) with its virtual vertex `c` placed
/// at the centroid of the polygon's largest triangle: `loop.size()` faces,
/// as the fan it replaces. False when the polygon is not simple or the
/// triangulation does not close the loop.
inline bool triangulate_hole(const std::vector<Vec2>& uv, const std::vector<int>& loop, int c, double sign,
                             std::vector<Face>& fill, Vec2& at)
{
  Loop_triangulation T;
  if(!T.add_loop(uv, loop)) return false;
  const std::vector<Face> inside = T.faces_at_depth(1);
  if(inside.size() + 2 != loop.size()) return false;
  double largest = -1;
  for(const Face& t : inside) {
    const Vec2 &a = uv[std::size_t(t[0])], &b = uv[std::size_t(t[1])], &d = uv[std::size_t(t[2])];
    const double area = std::abs((b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]));
    if(area > largest) {
      largest = area;
      at = Vec2{{ (a[0] + b[0] + d[0]) / 3, (a[1] + b[1] + d[1]) / 3 }};
    }
  }
  if(!T.add_point(at, c)) return false;
  fill = T.faces_at_depth(1);
  if(fill.size() != loop.size()) return false;
  orient_faces(fill, sign);
  std::vector<std::pair<int, int> > edges;
  for(std::size_t k = 0; k < loop.size(); ++k) edges.emplace_back(loop[k], loop[(k + 1) % loop.size()]);
  return fill_closes(fill, edges);
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
