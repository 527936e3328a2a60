// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the vertex-by-vertex relaxation sweeps of the plane and the sphere
// share: the faces around each vertex, the 2 × 2 Gauss–Newton model of one
// vertex's move, its line search and its exact check; and what the coarse
// levels of both share: a vertex's ring, independent half-edge collapses
// that keep the topology, the removed faces' targets handed to the ring.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_VERTEX_RELAXATION_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_VERTEX_RELAXATION_H

#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/geometry.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/morton_order.h>

#include <CGAL/enum.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <unordered_set>
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

/// The vertices one level removed from the level above, each with its ring
/// there: counter-clockwise, the collapse's target first. The star of a
/// removed vertex v in the level above is {(v, ring[i], ring[i+1])}.
struct Collapse_decimation
{
  std::vector<int> removed;
  std::vector<std::size_t> ring_first{ 0 }; ///< CSR offsets into `ring`
  std::vector<int> ring;
};

/// One coarse level: faces in the finest level's vertex numbering, and
/// their targets (the sum of the targets of the finer faces they replace).
struct Collapse_level
{
  std::vector<Face> faces;
  std::vector<double> target;
  Collapse_decimation from_above; ///< how this level was made from the finer one
};

/// The ring of interior vertex `v` (counter-clockwise, as its star's faces
/// run), or false when the star is not one closed fan of at most `most` faces.
inline bool vertex_ring(const Vertex_faces& around, const std::vector<Face>& faces, std::size_t v, std::size_t most,
                        std::vector<int>& ring)
{
  const std::size_t begin = around.first[v], end = around.first[v + 1], k = end - begin;
  ring.clear();
  if(k < 3 || k > most) return false;
  int a[32], b[32];
  for(std::size_t i = 0; i < k; ++i) {
    const Face& f = faces[around.of[begin + i].first];
    const int c = around.of[begin + i].second;
    a[i] = f[(c + 1) % 3];
    b[i] = f[(c + 2) % 3];
  }
  int cur = a[0];
  for(std::size_t step = 0; step < k; ++step) {
    ring.push_back(cur);
    std::size_t i = 0;
    while(i < k && a[i] != cur) ++i;
    if(i == k) return false;
    cur = b[i];
  }
  if(cur != a[0]) return false;
  std::vector<int> sorted(ring);
  std::sort(sorted.begin(), sorted.end());
  return std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end();
}

/// Whether the edge (w, x) is one of the level's faces' edges.
inline bool level_has_edge(const Vertex_faces& around, const std::vector<Face>& faces, int w, int x)
{
  for(std::size_t i = around.first[std::size_t(w)]; i < around.first[std::size_t(w) + 1]; ++i) {
    const Face& f = faces[around.of[i].first];
    if(f[0] == x || f[1] == x || f[2] == x) return true;
  }
  return false;
}

/// The faces of the level made by the collapses `v` → `into[v]` (−1: kept)
/// of `out.from_above`: the faces with the target as a corner go; the
/// others of the star keep their shape in the ring with v moved onto the
/// target, and share out the targets of the two that went.
inline void collapse_level_faces(const std::vector<Face>& faces, const std::vector<double>& target,
                                 const std::vector<int>& into, Collapse_level& out)
{
  const Collapse_decimation& D = out.from_above;
  std::vector<double> dropped(into.size(), 0);
  std::vector<int> owner;
  out.faces.clear();
  out.target.clear();
  for(std::size_t f = 0; f < faces.size(); ++f) {
    Face t = faces[f];
    int corner = -1;
    for(int c = 0; c < 3; ++c) if(into[std::size_t(t[c])] >= 0) corner = c;
    if(corner < 0) { out.faces.push_back(t); out.target.push_back(target[f]); owner.push_back(-1); continue; }
    const int v = t[corner], w = into[std::size_t(v)];
    if(t[0] == w || t[1] == w || t[2] == w) { dropped[std::size_t(v)] += target[f]; continue; }
    t[corner] = w;
    out.faces.push_back(t);
    out.target.push_back(target[f]);
    owner.push_back(v);
  }
  for(std::size_t r = 0; r < D.removed.size(); ++r) {
    const std::size_t v = std::size_t(D.removed[r]);
    dropped[v] /= double(D.ring_first[r + 1] - D.ring_first[r] - 2); // the faces left of its star
  }
  for(std::size_t f = 0; f < out.faces.size(); ++f)
    if(owner[f] >= 0) out.target[f] += dropped[std::size_t(owner[f])];
}

/// Makes the next coarser level of (`faces`, `target`) on `n` vertices:
/// removes an independent set of vertices without `fixed[v]` (a disk's
/// border), each by the collapse into a ring vertex (the nearest in `xyz`
/// that passes) that keeps the topology (no ring vertex joined twice to the
/// target: the link condition), joins no two fixed vertices and makes only
/// faces (w, a, b) with `accept(v, w, a, b)` in place of (v, a, b) (the
/// disk: positive in its start by the exact predicate). Returns the number
/// of vertices removed.
template <class Accept>
std::size_t coarsen_level(std::size_t n, const std::vector<Face>& faces, const std::vector<double>& target,
                          const std::vector<Vec3>& xyz, const std::vector<char>& fixed, const Accept& accept,
                          Collapse_level& out)
{
  // Rings of more than 10 give fans of long thin triangles; most vertices have 6.
  const std::size_t most = 10;
  const Vertex_faces around(n, faces);
  std::vector<char> state(n, 0); // 1: in a removed vertex's ring (kept), 2: removed
  std::vector<int> into(n, -1);
  std::unordered_set<std::uint64_t> added; // edges the accepted collapses made
  const auto key = [](int p, int q) {
    return (std::uint64_t(std::uint32_t((std::min)(p, q))) << 32) | std::uint32_t((std::max)(p, q));
  };
  Collapse_decimation& D = out.from_above;
  std::vector<int> ring;
  std::vector<std::pair<double, std::size_t> > order;
  for(std::size_t v = 0; v < n; ++v) {
    if(fixed[v] || state[v] != 0 || !vertex_ring(around, faces, v, most, ring)) continue;
    const std::size_t k = ring.size();
    order.clear();
    for(std::size_t j = 0; j < k; ++j) {
      const Vec3 e = sub(xyz[std::size_t(ring[j])], xyz[v]);
      order.emplace_back(dot(e, e), j);
    }
    std::sort(order.begin(), order.end());
    std::size_t chosen = k;
    for(const auto& candidate : order) {
      const std::size_t j = candidate.second;
      const int w = ring[j];
      bool ok = true;
      for(std::size_t i = 0; i < k && ok; ++i) {
        const std::size_t i1 = (i + 1) % k;
        if(i == j || i1 == j) continue;
        ok = accept(int(v), w, ring[i], ring[i1]);
        // Ring vertices other than w's two ring neighbours become joined to
        // w: once only, and not across the border (a chord between two
        // border vertices makes a triangle whose three corners the border
        // holds, whose area the flow can hardly reach).
        if(ok && i != (j + 1) % k)
          ok = !(fixed[std::size_t(w)] && fixed[std::size_t(ring[i])]) && !level_has_edge(around, faces, w, ring[i]) &&
               added.count(key(w, ring[i])) == 0;
      }
      if(ok) { chosen = j; break; }
    }
    if(chosen == k) continue;
    std::rotate(ring.begin(), ring.begin() + std::ptrdiff_t(chosen), ring.end());
    state[v] = 2;
    into[v] = ring[0];
    for(std::size_t i = 0; i < k; ++i) {
      state[std::size_t(ring[i])] = 1;
      if(i >= 2 && i + 1 < k) added.insert(key(ring[0], ring[i]));
    }
    D.removed.push_back(int(v));
    D.ring.insert(D.ring.end(), ring.begin(), ring.end());
    D.ring_first.push_back(D.ring.size());
  }
  collapse_level_faces(faces, target, into, out);
  return D.removed.size();
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
