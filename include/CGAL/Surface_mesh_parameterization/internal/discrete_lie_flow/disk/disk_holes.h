// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A genus-0 mesh with several border loops made a disk: each inner loop is
// filled by a fan of virtual faces around a virtual vertex, and the start is
// Tutte's embedding of the filled disk inside the outer loop. The certified
// flow then keeps the fill positive as well as the caller's faces, so the
// caller's map stays injective: the holes keep their room and nothing
// overlaps them.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_DISK_HOLES_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_DISK_HOLES_H

#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/disk/disk_problem.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/geometry.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/sparse_solver.h>

#include <Eigen/Sparse>

#include <algorithm>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// A fill face's target, relative to the caller's face across its loop edge:
/// at least this fraction of that face's, so that a thin or flat hole (a fan
/// of near-zero 3D area) still keeps triangles the flow can move.
constexpr double hole_fill_floor = 0.25;

/// Fills the inner loop `loop` of `P` (vertex indices, so that the caller's
/// face `across[k]` has the edge loop[k+1] → loop[k]) with the fan of faces
/// (loop[k], loop[k+1], c), c a new vertex at the loop's 3D centroid. A fan
/// face's target is its 3D area (at least `hole_fill_floor` times the area
/// of the face across) times the density of the face across: each hole
/// keeps about the room its rim would span in 3D.
inline void fill_hole(Disk_problem& P, const std::vector<int>& loop, const std::vector<std::size_t>& across)
{
  const int c = int(P.xyz.size());
  Vec3 centre{{ 0, 0, 0 }};
  for(int v : loop)
    for(int j = 0; j < 3; ++j) centre[std::size_t(j)] += P.xyz[std::size_t(v)][std::size_t(j)] / double(loop.size());
  P.xyz.push_back(centre);
  for(std::size_t k = 0; k < loop.size(); ++k) {
    const int a = loop[k], b = loop[(k + 1) % loop.size()];
    const Face& g = P.faces[across[k]];
    const double area_g = triangle_area_3(P.xyz[std::size_t(g[0])], P.xyz[std::size_t(g[1])], P.xyz[std::size_t(g[2])]);
    const double rho = P.target[across[k]] / area_g;
    const double area = triangle_area_3(P.xyz[std::size_t(a)], P.xyz[std::size_t(b)], centre);
    P.faces.push_back(Face{{ a, b, c }});
    P.target.push_back(rho * (std::max)(area, hole_fill_floor * area_g));
  }
  ++P.fill_vertices;
  P.fill_faces += loop.size();
  ++P.holes;
}

/// Tutte's embedding (uniform weights) of the disk `P` with its boundary
/// vertices kept where `uv` has them; `uv` (one entry per vertex of `P`)
/// receives the others. Bijective when the boundary polygon is convex (and
/// no edge joins two vertices of one straight side); the caller certifies it
/// with the exact predicate. False if the solve fails.
template <class EigenSolver>
bool filled_disk_tutte(const Disk_problem& P, std::vector<Vec2>& uv)
{
  const std::size_t n = P.xyz.size();
  std::vector<int> idx(n, 0);
  for(int b : P.boundary) idx[std::size_t(b)] = -1;
  int ni = 0;
  for(std::size_t v = 0; v < n; ++v) idx[v] = idx[v] == 0 ? ni++ : -1;
  if(ni == 0) return true;
  std::vector<std::pair<int, int> > edges;
  edges.reserve(3 * P.faces.size());
  for(const Face& t : P.faces)
    for(int k = 0; k < 3; ++k) edges.emplace_back((std::min)(t[k], t[(k + 1) % 3]), (std::max)(t[k], t[(k + 1) % 3]));
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  std::vector<Eigen::Triplet<double> > trip;
  trip.reserve(4 * edges.size());
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(ni, 2);
  for(const std::pair<int, int>& e : edges) {
    const int a = idx[std::size_t(e.first)], b = idx[std::size_t(e.second)];
    if(a >= 0) trip.emplace_back(a, a, 1.);
    if(b >= 0) trip.emplace_back(b, b, 1.);
    if(a >= 0 && b >= 0) { trip.emplace_back(a, b, -1.); trip.emplace_back(b, a, -1.); }
    else if(a >= 0) { rhs(a, 0) += uv[std::size_t(e.second)][0]; rhs(a, 1) += uv[std::size_t(e.second)][1]; }
    else if(b >= 0) { rhs(b, 0) += uv[std::size_t(e.first)][0]; rhs(b, 1) += uv[std::size_t(e.first)][1]; }
  }
  return solve_interior_2<EigenSolver>(ni, trip, rhs, idx, uv);
}

/// The caller's part of a list indexed by the faces of `P` (the fill's dropped).
template <class T>
std::vector<T> caller_part(const std::vector<T>& per_face, const Disk_problem& P)
{
  return std::vector<T>(per_face.begin(), per_face.begin() + std::ptrdiff_t(P.caller_faces()));
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
