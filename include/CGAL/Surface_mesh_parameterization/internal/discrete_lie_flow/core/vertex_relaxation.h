// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the vertex-by-vertex relaxation sweeps of the plane and the sphere
// share: the faces around each vertex, the 2 × 2 Gauss–Newton model of one
// vertex's move, its line search and its exact check.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_VERTEX_RELAXATION_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_VERTEX_RELAXATION_H

#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/geometry.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/morton_order.h>

#include <CGAL/enum.h>

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// Faces around each vertex, with the corner the vertex occupies.
struct Vertex_faces
{
  std::vector<std::size_t> first;              ///< CSR offsets, size n + 1
  std::vector<std::pair<std::size_t, int> > of; ///< (face, corner)

  Vertex_faces(std::size_t n, const std::vector<Face>& faces) : first(n + 1, 0)
  {
    for(const Face& t : faces) for(int k = 0; k < 3; ++k) ++first[std::size_t(t[k]) + 1];
    for(std::size_t v = 0; v < n; ++v) first[v + 1] += first[v];
    of.resize(first[n]);
    std::vector<std::size_t> fill(first.begin(), first.end() - 1);
    for(std::size_t f = 0; f < faces.size(); ++f)
      for(int k = 0; k < 3; ++k) of[fill[std::size_t(faces[f][k])]++] = std::make_pair(f, k);
  }
};

/// The 2 × 2 Gauss–Newton model of one vertex's move in a relaxation sweep
/// (planar_relaxation.h, sphere_relaxation.h): gradient g and matrix
/// Σ w ∇u ∇uᵀ, accumulated face by face in the vertex's own frame.
struct Vertex_model
{
  double g0 = 0, g1 = 0, h00 = 0, h01 = 0, h11 = 0;

  /// A face with ∂E/∂u = dE, curvature w and ∂u/∂(vertex) = (x, y).
  void add(double dE, double w, double x, double y)
  {
    g0 += dE * x; g1 += dE * y;
    h00 += w * x * x; h01 += w * x * y; h11 += w * y * y;
  }

  /// The (slightly regularised) Newton step x and its slope gᵀx; false
  /// unless it is a descent direction.
  bool step(double& x0, double& x1, double& slope) const
  {
    const double reg = 1e-9 * (h00 + h11), a = h00 + reg, c = h11 + reg;
    const double det = a * c - h01 * h01;
    if(!(det > 0)) return false;
    x0 = -(c * g0 - h01 * g1) / det;
    x1 = -(a * g1 - h01 * g0) / det;
    slope = g0 * x0 + g1 * x1;
    return slope < 0;
  }
};

/// What a relaxation sweep did (planar_relaxation.h, sphere_relaxation.h).
struct Relaxation_outcome
{
  std::size_t moved = 0, refused_by_exact_check = 0;
  double energy = 0; ///< the plane: E after the sweep, as the sweep kept it up to date
};

/// The line search of one vertex's relaxation move, shared by the plane and
/// the sphere: `at(λ)` is the vertex's trial position, `energy(x)` the total
/// energy with the vertex at x (+∞ when one of its faces is not positive;
/// the caller keeps what it needs to commit the move), `certified(x)` the
/// exact orientation check of its faces. From `lambda`, at most 8 halvings
/// until the energy passes Armijo against `E` and the exact predicate
/// agrees; then true, with the position in `moved`.
template <class Point, class Position, class Energy, class Certified>
bool relaxation_line_search(double E, double lambda, double slope, const Position& at, const Energy& energy,
                            const Certified& certified, Point& moved, Relaxation_outcome& out)
{
  for(int halvings = 0; halvings < 8; ++halvings, lambda *= 0.5) {
    moved = at(lambda);
    if(!(energy(moved) <= E + 1e-4 * lambda * slope)) continue;
    if(!certified(moved)) { ++out.refused_by_exact_check; continue; }
    ++out.moved;
    return true;
  }
  return false;
}

/// Whether `orientation(x, r, s)` is positive for every face (x, r, s) of the
/// vertex at `around.of[begin, end)` moved to x (r, s: its other corners in
/// `p`, in the face's order): the exact check of a relaxation move.
template <class Point, class Orientation>
bool moved_vertex_is_positive(const Vertex_faces& around, std::size_t begin, std::size_t end,
                              const std::vector<Face>& faces, const std::vector<Point>& p, const Point& x,
                              const Orientation& orientation)
{
  for(std::size_t i = begin; i < end; ++i) {
    const Face& t = faces[around.of[i].first];
    const int k = around.of[i].second;
    if(orientation(x, p[std::size_t(t[(k + 1) % 3])], p[std::size_t(t[(k + 2) % 3])]) != CGAL::POSITIVE) return false;
  }
  return true;
}

/// A fixed split of the vertices for sweeps on several threads: `parts`
/// consecutive runs of the Morton order of the input points (spatially
/// compact regions), each with its interior (the vertices whose neighbours
/// all lie in the region) in that order, and the separator, the remaining
/// vertices, in that order too (consecutive moves then touch nearby memory:
/// visited in index order, the regions' sweeps ran 1.7 times slower). No
/// face has corners in two interiors: interiors move concurrently without
/// touching a shared face.
struct Sweep_partition
{
  std::vector<std::vector<std::size_t> > interior;
  std::vector<std::size_t> separator;

  Sweep_partition() = default;
  Sweep_partition(const std::vector<Vec3>& xyz, const std::vector<Face>& faces, std::size_t parts)
    : Sweep_partition(morton_order(xyz), faces, parts)
  {}

  /// From a vertex order computed once (a coarse level keeps its finer
  /// level's), on the vertices with `keep[v]` (all when null).
  Sweep_partition(const std::vector<std::size_t>& order, const std::vector<Face>& faces, std::size_t parts,
                  const std::vector<char>* keep = nullptr)
  {
    parts = (std::max)(std::size_t(1), parts);
    const std::size_t n = order.size();
    std::vector<std::size_t> region(n);
    for(std::size_t i = 0; i < n; ++i) region[order[i]] = i * parts / (std::max)(n, std::size_t(1));
    std::vector<char> cut(n, 0);
    for(const Face& t : faces)
      for(int k = 0; k < 3; ++k) {
        const std::size_t a = std::size_t(t[k]), b = std::size_t(t[(k + 1) % 3]);
        if(region[a] != region[b]) cut[a] = cut[b] = 1;
      }
    interior.assign(parts, std::vector<std::size_t>());
    for(std::size_t v : order) {
      if(keep && !(*keep)[v]) continue;
      if(cut[v]) separator.push_back(v);
      else interior[region[v]].push_back(v);
    }
  }
};

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
