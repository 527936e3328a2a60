// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A start for the certified flow on the circle: Tutte's map (uniform weights)
// with the border vertices spaced by area instead of by length.
//
// Spacing by length gives a border arc the room its 3D length asks for, not
// the area behind it. Where a disk is long and thin, or cut open along a
// seam (the two sides of a leg's seam are long border arcs with little area
// between them, a seam's junction encloses faces between border vertices
// only), the Tutte map crushes faces by factors of e⁵ and more; the area of
// a pocket closed by border vertices grows with the cube of their spacing,
// and the flow then spends hundreds of iterations, each held at a fraction of
// a critical root of ~1e-3, widening it. Here every border vertex owns the
// faces nearest to it (geodesically, along edges); the arc of each vertex is
// then scaled by (target share / domain share)^½ of what it owns, a few
// times, each time re-solving Tutte's map with the factorisation of the
// first (the matrix does not change). Tutte's map of a convex border is an
// embedding; each candidate is still checked with the exact predicate.
//
// The same factor gives the default start (Tutte's map with the border on
// the circle by arc length) when the library computes it itself.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_BORDER_SPACING_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_BORDER_SPACING_H

#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/area_barrier_energy.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/area_elements.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/disk/boundary_curve.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/certification.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/default_solver.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/disk/disk_problem.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/sparse_solver.h>

#include <CGAL/number_type_config.h>

#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// For every vertex, the position in the boundary loop of the border vertex
/// nearest to it along the edges of the 3D mesh (multi-source Dijkstra).
inline std::vector<int> nearest_border_vertex(const Disk_problem& P)
{
  const std::size_t n = P.xyz.size();
  std::vector<std::vector<std::pair<int, double> > > adj(n);
  for(const Face& f : P.faces)
    for(int k = 0; k < 3; ++k) {
      const int a = f[k], b = f[(k + 1) % 3];
      const Vec3 &p = P.xyz[std::size_t(a)], &q = P.xyz[std::size_t(b)];
      const double l = std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
      adj[std::size_t(a)].emplace_back(b, l); // each interior edge twice (once per face): harmless
      adj[std::size_t(b)].emplace_back(a, l);
    }
  std::vector<double> dist(n, std::numeric_limits<double>::infinity());
  std::vector<int> owner(n, -1);
  typedef std::pair<double, int> Item;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item> > q;
  for(std::size_t k = 0; k < P.boundary.size(); ++k) {
    dist[std::size_t(P.boundary[k])] = 0;
    owner[std::size_t(P.boundary[k])] = int(k);
    q.emplace(0., P.boundary[k]);
  }
  while(!q.empty()) {
    const Item it = q.top();
    q.pop();
    if(it.first > dist[std::size_t(it.second)]) continue;
    for(const auto& e : adj[std::size_t(it.second)]) {
      const double d = it.first + e.second;
      if(d < dist[std::size_t(e.first)]) {
        dist[std::size_t(e.first)] = d;
        owner[std::size_t(e.first)] = owner[std::size_t(it.second)];
        q.emplace(d, e.first);
      }
    }
  }
  return owner;
}

/// Tutte's matrix over the interior vertices of `P` (the number of
/// neighbours on the diagonal, −1 for each interior neighbour). `interior`
/// numbers the interior vertices (−1 on the border), `neighbours` lists each
/// vertex's neighbours without repeats; returns the number of interior vertices.
inline int tutte_interior_matrix(const Disk_problem& P, std::size_t n, std::vector<int>& interior,
                                 std::vector<std::vector<int> >& neighbours, Sparse_matrix& A)
{
  interior.assign(n, -1);
  int ni = 0;
  std::vector<char> on_border(n, 0);
  for(int b : P.boundary) on_border[std::size_t(b)] = 1;
  for(std::size_t v = 0; v < n; ++v)
    if(!on_border[v]) interior[v] = ni++;
  neighbours.assign(n, std::vector<int>());
  for(const Face& f : P.faces)
    for(int k = 0; k < 3; ++k) {
      const int a = f[k], b = f[(k + 1) % 3];
      neighbours[std::size_t(a)].push_back(b);
      neighbours[std::size_t(b)].push_back(a);
    }
  std::vector<Eigen::Triplet<double> > triplets;
  for(std::size_t v = 0; v < n; ++v) {
    std::vector<int>& nv = neighbours[v];
    std::sort(nv.begin(), nv.end());
    nv.erase(std::unique(nv.begin(), nv.end()), nv.end());
    if(interior[v] < 0) continue;
    triplets.emplace_back(interior[v], interior[v], double(nv.size()));
    for(int w : nv)
      if(interior[std::size_t(w)] >= 0) triplets.emplace_back(interior[v], interior[std::size_t(w)], -1.);
  }
  A.resize(ni, ni);
  A.setFromTriplets(triplets.begin(), triplets.end());
  return ni;
}

/// Each border vertex's share of the total target: a third of each face
/// per corner, given to the corner's `owner` (above).
inline std::vector<double> border_target_shares(const Disk_problem& P, const std::vector<int>& owner)
{
  std::vector<double> share(P.boundary.size(), 0.);
  double total = 0;
  for(std::size_t t = 0; t < P.faces.size(); ++t) {
    for(int k = 0; k < 3; ++k) share[std::size_t(owner[std::size_t(P.faces[t][k])])] += P.target[t] / 3;
    total += P.target[t];
  }
  for(double& s : share) s /= total;
  return share;
}

/// Tutte's system of the interior vertices of a problem (uniform weights),
/// factorised once by the flow's solver: the start's map and every respaced
/// border below are solved with that one factor, and its symbolic analysis
/// (the pattern of the flow's interior stiffness) serves the flow
/// (Pattern_reusing_solver::adopt_analysis()).
template <class EigenSolver>
class Tutte_interior_system
{
public:
  /// Assembles and factorises the system of `P`'s `n` vertices with `solver`.
  /// Only the factor and the border coupling are kept (the system lives as
  /// long as the flow), and `P`, which must outlive the system when the
  /// factor may be released (release_factor()).
  Tutte_interior_system(const Disk_problem& P, std::size_t n, EigenSolver& solver) : m_solver(solver), m_P(&P), m_n(n)
  {
    Sparse_matrix A;
    std::vector<std::vector<int> > neighbours;
    m_unknowns = tutte_interior_matrix(P, n, m_interior, neighbours, A);
    A.makeCompressed();
    // The analysis first (AMD ran slower with the adjacency freed before it),
    // then the adjacency goes before the numeric factorization, the
    // process's largest allocation.
    if(m_unknowns > 0) m_solver.analyze(A);
    // rhs = B uv: each interior vertex sums its border neighbours.
    std::vector<Eigen::Triplet<double> > coupling;
    for(std::size_t v = 0; v < n; ++v)
      if(m_interior[v] >= 0)
        for(int w : neighbours[v])
          if(m_interior[std::size_t(w)] < 0) coupling.emplace_back(m_interior[v], w, 1.);
    std::vector<std::vector<int> >().swap(neighbours);
    m_B.resize(m_unknowns, Eigen::Index(n));
    m_B.setFromTriplets(coupling.begin(), coupling.end());
    m_factorized = m_unknowns > 0 && m_solver.factorize(A);
  }

  /// The number of interior vertices.
  int unknowns() const { return m_unknowns; }

  /// Whether the system has unknowns and its factorization succeeded.
  bool factorized() const { return m_factorized; }

  /// Frees the factor's numeric values (release_numeric_factor()), which the
  /// flow's solver refills at its next factorization: for a factor that is
  /// not needed for a while. The analysis stays; a later solve() first
  /// factorizes the same matrix again (the same factor, bit for bit).
  void release_factor()
  {
    if(!m_factorized || m_released) return;
    release_numeric_factor(m_solver.solver());
    m_released = true;
  }

  /// Writes into `uv` Tutte's map of the interior inside the border
  /// positions that `uv` holds; false when a solve fails or gives a
  /// non-finite value (then `uv`'s interior is unchanged).
  bool solve(std::vector<Vec2>& uv)
  {
    if(m_unknowns == 0) return true;
    if(!m_factorized) return false;
    if(m_released) {
      std::vector<std::vector<int> > neighbours;
      std::vector<int> interior;
      Sparse_matrix A;
      tutte_interior_matrix(*m_P, m_n, interior, neighbours, A);
      neighbours.clear();
      neighbours.shrink_to_fit();
      A.makeCompressed();
      m_released = false;
      if(!m_solver.factorize(A)) return m_factorized = false;
    }
    Eigen::MatrixXd border = Eigen::MatrixXd::Zero(m_B.cols(), 2), x;
    for(std::size_t v = 0; v < uv.size(); ++v)
      if(m_interior[v] < 0) border.row(Eigen::Index(v)) << uv[v][0], uv[v][1];
    if(!m_solver.solve(Eigen::MatrixXd(m_B * border), x)) return false;
    for(std::size_t v = 0; v < m_interior.size(); ++v)
      if(m_interior[v] >= 0) uv[v] = {{ x(m_interior[v], 0), x(m_interior[v], 1) }};
    return true;
  }

  /// The solver wrapper that holds the factor and the analysis.
  Pattern_reusing_solver<EigenSolver>& solver() { return m_solver; }

private:
  Pattern_reusing_solver<EigenSolver> m_solver;
  const Disk_problem* m_P;
  std::size_t m_n;
  std::vector<int> m_interior;
  Sparse_matrix m_B; // interior × all vertices: 1 for each border neighbour
  int m_unknowns = 0;
  bool m_factorized = false, m_released = false;
};

/// The border loop of `P` on the circle of centre (½, ½) and radius ½,
/// spaced by the 3D length of its edges, written into `uv`: the positions
/// CGAL's `Circular_border_arc_length_parameterizer_3` gives when walking
/// the border halfedges from the one whose target is `P.boundary[0]` (the
/// same arithmetic in the same order). False when the border has length 0.
inline bool circle_border_by_arc_length(const Disk_problem& P, std::vector<Vec2>& uv)
{
  const std::size_t nb = P.boundary.size();
  // Halfedge k of the loop runs from P.boundary[k − 1] to P.boundary[k].
  auto length = [&P, nb](std::size_t k) {
    const Vec3& s = P.xyz[std::size_t(P.boundary[(k + nb - 1) % nb])];
    const Vec3& t = P.xyz[std::size_t(P.boundary[k])];
    const double x = t[0] - s[0], y = t[1] - s[1], z = t[2] - s[2];
    return std::sqrt(x * x + y * y + z * z);
  };
  double total = 0;
  for(std::size_t k = 0; k < nb; ++k) total += length(k);
  if(!(total > 0)) return false;
  const double scale = 2 * CGAL_PI / total;
  double s = 0;
  for(std::size_t k = 0; k < nb; ++k) {
    const double angle = s * scale;
    uv[std::size_t(P.boundary[(k + nb - 1) % nb])] = {{ 0.5 + 0.5 * std::cos(-angle), 0.5 + 0.5 * std::sin(-angle) }};
    s += length(k);
  }
  return true;
}

/// Tutte's map of `P` with its border on the circle of `curve`, spaced by
/// area (above). Replaces `uv` when one of the candidates is an embedding
/// (exact predicate) whose barrier energy E is below `gain` times `uv`'s;
/// returns whether it did. `uv` must be positively oriented with the
/// boundary loop counter-clockwise on `curve`, which is then rebuilt for the
/// new positions. `tutte` is the problem's factorised Tutte system.
template <class EigenSolver>
bool respace_border_by_area(const Disk_problem& P, std::vector<Vec2>& uv, Boundary_curve& curve,
                            double gain, Tutte_interior_system<EigenSolver>& tutte, std::size_t rounds = 8)
{
  const std::size_t nb = P.boundary.size();
  if(curve.kind() != Discrete_lie_flow_border::CIRCLE || nb < 3) return false;
  if(tutte.unknowns() == 0 || !tutte.factorized()) return false;

  // What each border vertex owns: a third of each face per corner.
  const std::vector<int> owner = nearest_border_vertex(P);
  const std::vector<double> target_share = border_target_shares(P, owner);

  const Area_barrier_energy energy(P.target);
  std::vector<double> u;
  signed_areas_2(uv, P.faces, u);
  double best_E = gain * energy.value(u);
  std::vector<Vec2> best, candidate = uv;
  const double L = curve.length(), s0 = curve.parameter(0);
  // Arc owned by each border vertex, first in proportion to its target share.
  std::vector<double> weight = target_share;
  double E_previous = std::numeric_limits<double>::infinity();
  for(std::size_t round = 0; round < rounds; ++round) {
    // Border vertex k at the middle of its arc: s_k = s0 + Σ_{j<k} weight_j + (weight_k − weight_0) / 2.
    double sum = 0;
    for(double w : weight) sum += w;
    double s = 0;
    for(std::size_t k = 0; k < nb; ++k) {
      if(k > 0) s += 0.5 * (weight[k - 1] + weight[k]) / sum * L;
      candidate[std::size_t(P.boundary[k])] = curve.point(s0 + s);
    }
    if(!tutte.solve(candidate)) break;
    signed_areas_2(candidate, P.faces, u);
    const double E = energy.value(u);
    if(E < best_E && count_orientations_2(candidate, P.faces, true).all_positive()) {
      best_E = E;
      best = candidate;
    }
    // The rounds are a fixed-point iteration whose E falls to its least and
    // then rises (on the data set's disks, CGAL's seams and the cut
    // surfaces of benchmark/cut_surfaces.sh alike): past the first rise a
    // round only costs a solve.
    if(!std::isfinite(E) || E > E_previous) break;
    E_previous = E;
    // Scale each arc by the square root of its vertex's target over domain share.
    std::vector<double> domain_share(nb, 0.);
    double U = 0;
    for(std::size_t t = 0; t < P.faces.size(); ++t) {
      for(int k = 0; k < 3; ++k) domain_share[std::size_t(owner[std::size_t(P.faces[t][k])])] += u[t] / 3;
      U += u[t];
    }
    for(std::size_t k = 0; k < nb; ++k) weight[k] *= std::sqrt(target_share[k] / (domain_share[k] / U));
  }
  if(best.empty()) return false;
  uv.swap(best);
  std::vector<Vec2> loop(nb);
  for(std::size_t k = 0; k < nb; ++k) loop[k] = uv[std::size_t(P.boundary[k])];
  curve = Boundary_curve(loop, Discrete_lie_flow_border::CIRCLE);
  return true;
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
