// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A certified bijective initial map of a closed genus-0 mesh onto the unit
// sphere: puncture one face, map the remaining disk onto the plane with the
// punctured face's three vertices fixed (Tutte's barycentric embedding inside
// an equilateral triangle, bijective in exact arithmetic; or the cotangent-
// harmonic, discrete conformal, map inside a triangle similar to the face),
// scale the plane by the factor that minimises D_area after projection, and
// lift it by inverse stereographic projection (the punctured face becomes the
// cap around the north pole; scaling keeps a conformal map conformal). The
// result is accepted only when every face is positively oriented by CGAL's
// exact predicate on the stored doubles; otherwise other punctures are tried.
// A Tutte start compressed by many decades may then be reweighted: Tutte's
// map again with the edge weights scaled by the faces' area ratios, which
// keeps it bijective (any positive weights do) and certified the same way.
// Tutte's map may also use Floater's mean-value weights (directed, positive:
// still a bijection; an LU solve), which keep straight edges straight.
// A caller's own start is normalised and certified the same way.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_SPHERE_INITIAL_MAP_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_SPHERE_INITIAL_MAP_H

#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/certification.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/area_barrier_energy.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/area_elements.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/sparse_solver.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/sphere/sphere_problem.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/sphere/sphere_spherical_area.h>

#include <Eigen/Sparse>
#include <Eigen/SparseLU>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// The solver of the mean-value start's non-symmetric system.
typedef Eigen::SparseLU<Sparse_matrix, Eigen::COLAMDOrdering<int> > Sphere_lu_solver;

/// What the initial map did.
struct Sphere_initial_outcome
{
  bool certified = false;
  int puncture = -1;          ///< the punctured face
  double scale = 0;           ///< the plane scale s of the accepted map
  double d_area = 0;          ///< D_area of the accepted map
  std::size_t attempts = 0;   ///< punctures tried
  std::size_t reweightings = 0; ///< reweighted Tutte maps accepted (`reweighted_tutte_map()`)
  std::string message;        ///< why no map was certified
};

/// Punctures worth trying, best first: large faces (they become the polar
/// cap, whose area the projection controls) that are well shaped (a sliver
/// gives a thin boundary triangle). Score: area × shape quality 4√3 A / Σ ℓ².
inline std::vector<int> puncture_candidates(const Sphere_problem& P, std::size_t count)
{
  const std::size_t F = P.faces.size();
  std::vector<double> score(F);
  for(std::size_t f = 0; f < F; ++f) {
    const Face& t = P.faces[f];
    const Vec3 &a = P.xyz[std::size_t(t[0])], &b = P.xyz[std::size_t(t[1])], &c = P.xyz[std::size_t(t[2])];
    const double A = triangle_area_3(a, b, c);
    const double l2 = dot(sub(b, a), sub(b, a)) + dot(sub(c, b), sub(c, b)) + dot(sub(a, c), sub(a, c));
    score[f] = A * (4 * std::sqrt(3.) * A / l2);
  }
  std::vector<int> order(F);
  std::iota(order.begin(), order.end(), 0);
  count = (std::min)(count, F);
  std::partial_sort(order.begin(), order.begin() + std::ptrdiff_t(count), order.end(),
                    [&score](int x, int y) { return score[std::size_t(x)] > score[std::size_t(y)]; });
  order.resize(count);
  return order;
}

/// Where the puncture's corners go: the unit-circumradius equilateral
/// triangle (Tutte), or a triangle similar to the face, its centroid at the
/// origin (conformal). Counter-clockwise in the order hole[0], hole[2],
/// hole[1], which is how the disk's faces see their border.
inline std::array<Vec2, 3> puncture_corners(const Sphere_problem& P, const Face& hole, bool conformal)
{
  const double pi = 3.14159265358979323846;
  std::array<Vec2, 3> c; // c[k]: the corner of the k-th vertex of the order (hole[0], hole[2], hole[1])
  if(!conformal) {
    for(int k = 0; k < 3; ++k) c[std::size_t(k)] = {{ std::cos(pi / 2 + 2 * pi * k / 3), std::sin(pi / 2 + 2 * pi * k / 3) }};
    return c;
  }
  const Vec3 &a = P.xyz[std::size_t(hole[0])], &b = P.xyz[std::size_t(hole[2])], &d = P.xyz[std::size_t(hole[1])];
  const double ab = norm3(sub(b, a)), ad = norm3(sub(d, a));
  const double angle = std::atan2(norm3(cross(sub(b, a), sub(d, a))), dot(sub(b, a), sub(d, a)));
  c[0] = {{ 0, 0 }};
  c[1] = {{ ab, 0 }};
  c[2] = {{ ad * std::cos(angle), ad * std::sin(angle) }};
  const Vec2 g{{ (c[0][0] + c[1][0] + c[2][0]) / 3, (c[0][1] + c[1][1] + c[2][1]) / 3 }};
  const double r = std::sqrt((std::max)({ (c[0][0] - g[0]) * (c[0][0] - g[0]) + (c[0][1] - g[1]) * (c[0][1] - g[1]),
                                          (c[1][0] - g[0]) * (c[1][0] - g[0]) + (c[1][1] - g[1]) * (c[1][1] - g[1]),
                                          (c[2][0] - g[0]) * (c[2][0] - g[0]) + (c[2][1] - g[1]) * (c[2][1] - g[1]) }));
  for(Vec2& x : c) x = {{ (x[0] - g[0]) / r, (x[1] - g[1]) / r }};
  return c;
}

/// Half the cotangent of the angle at `a` of the 3D triangle (a, b, c).
inline double half_cotangent_3(const Vec3& a, const Vec3& b, const Vec3& c)
{
  const Vec3 u = sub(b, a), v = sub(c, a);
  return 0.5 * dot(u, v) / norm3(cross(u, v));
}

/// The key of the undirected edge {i, j}: the smaller index in the high half.
inline std::uint64_t undirected_edge_key(int i, int j)
{
  return (std::uint64_t(std::uint32_t((std::min)(i, j))) << 32) | std::uint32_t((std::max)(i, j));
}

/// Cotangent weights ½ (cot α + cot β) of the undirected edges of a closed
/// mesh (α, β the 3D angles opposite the edge), sorted by key, raised to at
/// least 1e-3 of their mean where an edge is far from Delaunay (α + β near
/// or above π): positive weights keep Tutte's guarantee (a bijection onto the
/// convex puncture in exact arithmetic), and Delaunay edges, most of a fine
/// mesh, keep their cotangent weights.
inline std::vector<std::pair<std::uint64_t, double> > conformal_edge_weights(const Sphere_problem& P)
{
  std::vector<std::pair<std::uint64_t, double> > w;
  w.reserve(3 * P.faces.size());
  for(const Face& t : P.faces)
    for(int k = 0; k < 3; ++k) {
      const int i = t[(k + 1) % 3], j = t[(k + 2) % 3];
      w.emplace_back(undirected_edge_key(i, j), half_cotangent_3(P.xyz[std::size_t(t[k])], P.xyz[std::size_t(i)], P.xyz[std::size_t(j)]));
    }
  std::sort(w.begin(), w.end());
  std::size_t out = 0;
  for(std::size_t a = 0; a < w.size(); ) {
    std::size_t b = a;
    double sum = 0;
    for(; b < w.size() && w[b].first == w[a].first; ++b) sum += w[b].second;
    w[out++] = std::make_pair(w[a].first, sum);
    a = b;
  }
  w.resize(out);
  double mean = 0;
  for(const auto& e : w) mean += std::fabs(e.second);
  mean /= double((std::max)(w.size(), std::size_t(1)));
  for(auto& e : w) e.second = (std::max)(e.second, 1e-3 * mean);
  return w;
}

/// The punctured face's corners fixed in `uv` (every other point at 0) and
/// the unknowns' numbering `idx` (−1 for the three fixed vertices); returns
/// the number of unknowns. Shared by the symmetric and the directed maps.
inline int puncture_unknowns(const Sphere_problem& P, int puncture, bool conformal, std::vector<Vec2>& uv,
                             std::vector<int>& idx)
{
  const std::size_t n = P.xyz.size();
  const Face& hole = P.faces[std::size_t(puncture)];
  idx.assign(n, 0);
  for(int k = 0; k < 3; ++k) idx[std::size_t(hole[k])] = -1;
  int ni = 0;
  for(std::size_t v = 0; v < n; ++v)
    if(idx[v] == 0) idx[v] = ni++; else idx[v] = -1;
  uv.assign(n, Vec2{{ 0, 0 }});
  const std::array<Vec2, 3> corners = puncture_corners(P, hole, conformal);
  const int order[3] = { hole[0], hole[2], hole[1] };
  for(int k = 0; k < 3; ++k) uv[std::size_t(order[k])] = corners[std::size_t(k)];
  return ni;
}

/// The mesh minus face `puncture` mapped onto the plane with the puncture's
/// corners fixed (`puncture_corners()`), the faces counter-clockwise: the
/// harmonic map of Tutte's uniform weights, or with `conformal` of
/// `conformal_edge_weights()` (the discrete conformal map), or of
/// `corner_weights` when not null (positive; entry 3f + k the weight of the
/// edge from corner k to corner k + 1 of face f, equal from both its faces).
/// False if the solve fails.
template <class EigenSolver>
bool punctured_planar_map(const Sphere_problem& P, int puncture, bool conformal, std::vector<Vec2>& uv,
                          const std::vector<double>* corner_weights = nullptr)
{
  std::vector<int> idx;
  const int ni = puncture_unknowns(P, puncture, conformal, uv, idx);
  if(ni == 0) return true;
  std::vector<std::pair<std::uint64_t, double> > cot;
  if(conformal && !corner_weights) cot = conformal_edge_weights(P);
  // Each edge of a closed mesh is seen from its two faces: half its weight from each.
  auto half_weight = [&cot, corner_weights](std::size_t f, int k, int i, int j) {
    if(corner_weights) return 0.5 * (*corner_weights)[3 * f + std::size_t(k)];
    if(cot.empty()) return 0.5;
    const std::uint64_t key = undirected_edge_key(i, j);
    return 0.5 * std::lower_bound(cot.begin(), cot.end(), std::make_pair(key, -std::numeric_limits<double>::infinity()))->second;
  };
  std::vector<Eigen::Triplet<double> > trip;
  trip.reserve(P.faces.size() * 6);
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(ni, 2);
  for(std::size_t f = 0; f < P.faces.size(); ++f)
    for(int k = 0; k < 3; ++k) {
      const Face& t = P.faces[f];
      const int i = t[k], j = t[(k + 1) % 3];
      const double w = half_weight(f, k, i, j);
      const int a = idx[std::size_t(i)], b = idx[std::size_t(j)];
      if(a >= 0) trip.emplace_back(a, a, w);
      if(b >= 0) trip.emplace_back(b, b, w);
      if(a >= 0 && b >= 0) { trip.emplace_back(a, b, -w); trip.emplace_back(b, a, -w); }
      else if(a >= 0) { rhs(a, 0) += w * uv[std::size_t(j)][0]; rhs(a, 1) += w * uv[std::size_t(j)][1]; }
      else if(b >= 0) { rhs(b, 0) += w * uv[std::size_t(i)][0]; rhs(b, 1) += w * uv[std::size_t(i)][1]; }
    }
  return solve_interior_2<EigenSolver>(ni, trip, rhs, idx, uv);
}

/// Floater's mean-value weights, directed: entry 6f + 2k + s is what face f
/// gives the weight of the edge from its corner k to corner k + 1 (s = 0) or
/// k + 2 (s = 1), tan(θ/2) / |x_j − x_i| with θ the face's 3D angle at corner
/// k. Summed over the two faces of an edge they are Floater's w_ij, positive
/// on any mesh with positive angles below π (Tutte's guarantee holds), and
/// they reproduce linear functions: a vertex on a straight 3D edge between
/// two neighbours (a needle fan's centre) stays near the segment between
/// their images instead of being pulled towards the fan's far corners.
inline std::vector<double> mean_value_corner_weights(const Sphere_problem& P)
{
  std::vector<double> w(6 * P.faces.size());
  for(std::size_t f = 0; f < P.faces.size(); ++f)
    for(int k = 0; k < 3; ++k) {
      const Face& t = P.faces[f];
      const Vec3& a = P.xyz[std::size_t(t[k])];
      const Vec3 u = sub(P.xyz[std::size_t(t[(k + 1) % 3])], a), v = sub(P.xyz[std::size_t(t[(k + 2) % 3])], a);
      const double lu = norm3(u), lv = norm3(v);
      // tan(θ/2) = sin θ / (1 + cos θ) = |u × v| / (|u||v| + u·v): no cancellation for small θ.
      const double half_tan = norm3(cross(u, v)) / (lu * lv + dot(u, v));
      w[6 * f + 2 * std::size_t(k)] = half_tan / lu;
      w[6 * f + 2 * std::size_t(k) + 1] = half_tan / lv;
    }
  return w;
}

/// The mesh minus face `puncture` mapped onto the plane as in
/// `punctured_planar_map()` (Tutte's triangle), with directed weights
/// (`mean_value_corner_weights()` layout, positive): each interior vertex is
/// the convex combination of its neighbours with its own row of weights. The
/// system is not symmetric, hence an LU solver. False if the solve fails.
template <class LUSolver>
bool punctured_planar_map_directed(const Sphere_problem& P, int puncture, const std::vector<double>& directed,
                                   std::vector<Vec2>& uv)
{
  std::vector<int> idx;
  const int ni = puncture_unknowns(P, puncture, false, uv, idx);
  if(ni == 0) return true;
  std::vector<Eigen::Triplet<double> > trip;
  trip.reserve(P.faces.size() * 12);
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(ni, 2);
  for(std::size_t f = 0; f < P.faces.size(); ++f)
    for(int k = 0; k < 3; ++k)
      for(int s = 0; s < 2; ++s) {
        const Face& t = P.faces[f];
        const int i = t[k], j = t[(k + 1 + s) % 3];
        const int a = idx[std::size_t(i)], b = idx[std::size_t(j)];
        if(a < 0) continue;
        const double w = directed[6 * f + 2 * std::size_t(k) + std::size_t(s)];
        trip.emplace_back(a, a, w);
        if(b >= 0) trip.emplace_back(a, b, -w);
        else { rhs(a, 0) += w * uv[std::size_t(j)][0]; rhs(a, 1) += w * uv[std::size_t(j)][1]; }
      }
  return solve_interior_2<LUSolver>(ni, trip, rhs, idx, uv);
}

/// Inverse stereographic projection of s·(z − centre), mirrored in y when
/// `mirror` (the projection reverses orientation as seen from outside).
inline void lift_to_sphere(const std::vector<Vec2>& uv, double s, const Vec2& centre, bool mirror, std::vector<Vec3>& p)
{
  p.resize(uv.size());
  for(std::size_t v = 0; v < uv.size(); ++v) {
    const double x = s * (uv[v][0] - centre[0]), y = s * (uv[v][1] - centre[1]);
    const double r2 = x * x + y * y;
    // |(2x, 2y, r² − 1)| = r² + 1 exactly; normalising again only removes rounding.
    p[v] = normalized(Vec3{{ 2 * x, mirror ? -2 * y : 2 * y, r2 - 1 }});
  }
}

/// Searches the scale s (log-grid, then golden section) that minimises
/// D_area of the lifted map; +∞ energy when some face is not positive in
/// floating point. Returns the best log s and its energy.
inline std::pair<double, double> best_lift_scale(const Sphere_problem& P, const Area_barrier_energy& energy,
                                                 const std::vector<Vec2>& uv, const Vec2& centre, bool mirror)
{
  std::vector<Vec3> p;
  std::vector<double> u;
  auto E = [&](double t) {
    lift_to_sphere(uv, std::exp(t), centre, mirror, p);
    cone_areas_sphere(p, P.faces, u);
    return energy.value(u);
  };
  double best_t = 0, best_E = std::numeric_limits<double>::infinity();
  for(double t = -10; t <= 40; t += 0.5) {
    const double e = E(t);
    if(e < best_E) { best_E = e; best_t = t; }
  }
  if(!std::isfinite(best_E)) return std::make_pair(best_t, best_E);
  // Golden section on [t − ½, t + ½] (E is unimodal in practice near its grid minimum).
  const double g = 0.5 * (std::sqrt(5.) - 1);
  double lo = best_t - 0.5, hi = best_t + 0.5;
  double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
  double e1 = E(x1), e2 = E(x2);
  for(int it = 0; it < 30; ++it) {
    if(e1 < e2) { hi = x2; x2 = x1; e2 = e1; x1 = hi - g * (hi - lo); e1 = E(x1); }
    else { lo = x1; x1 = x2; e1 = e2; x2 = lo + g * (hi - lo); e2 = E(x2); }
  }
  if(e1 < best_E) { best_E = e1; best_t = x1; }
  if(e2 < best_E) { best_E = e2; best_t = x2; }
  return std::make_pair(best_t, best_E);
}

/// best_lift_scale() in the orientation most faces have when `uv` is lifted
/// at the unit scale (the planar map may come out mirrored); `mirror` is set
/// to that orientation, `p` and `u` are scratch.
inline std::pair<double, double> best_oriented_lift(const Sphere_problem& P, const Area_barrier_energy& energy,
                                                    const std::vector<Vec2>& uv, bool& mirror,
                                                    std::vector<Vec3>& p, std::vector<double>& u)
{
  lift_to_sphere(uv, 2, Vec2{{ 0, 0 }}, false, p);
  signed_areas_sphere(p, P.faces, u);
  std::size_t negative = 0;
  for(double a : u) if(a < 0) ++negative;
  mirror = 2 * negative > u.size();
  return best_lift_scale(P, energy, uv, Vec2{{ 0, 0 }}, mirror);
}

/// The largest share of the sphere held by one face (its spherical area over 4π).
inline double largest_face_share(const std::vector<Vec3>& p, const std::vector<Face>& faces)
{
  std::vector<double> a;
  spherical_areas_sphere(p, faces, a);
  double m = 0;
  for(double x : a) m = (std::max)(m, x);
  return m / (4 * 3.14159265358979323846);
}

/// When and how a compressed Tutte start is reweighted (`reweighted_tutte_map()`).
struct Sphere_reweighting
{
  /// Reweight while the flat D_area is above this: each decade of start
  /// D_area costs the opening about six steps, and a start below it opens
  /// in a few.
  double above = 1e3;
  /// ... and only on meshes of at least this many faces. On coarse meshes the
  /// polish's plateau sits near the goals and moves with the start: dino
  /// (7,828 faces) converges from Tutte's start (mean |log r| 0.0200) but
  /// stops on a plateau at 0.029 from the reweighted one; and their openings
  /// cost little.
  std::size_t min_faces = 10000;
  /// A round multiplies each edge's weight by (r_f r_g)^(exponent/2), r the
  /// area ratios of its two faces (cone areas, normalised totals); a round
  /// not kept halves the exponent for the next, down to `least_exponent`.
  double exponent = 1;
  double least_exponent = 0.25;
  /// A round is kept only if it divides D_area by at least this and no face
  /// then holds a larger share of the sphere than before: lowering D_area by
  /// handing a few faces next to the puncture a large part of the sphere
  /// (D_area weighs them by their small targets) makes a start that the
  /// opening stalls on.
  double least_gain = 10;
  /// Rounds tried at most, kept or not (each a Tutte solve and a scale search).
  std::size_t max_rounds = 4;
};

/// Lowers the compression of a certified Tutte start (`sphere`, punctured at
/// `puncture`, flat D_area `d_area`, plane scale `scale`): Tutte's map again
/// with each edge's weight scaled by the area ratios of its two faces, so
/// that compressed regions (small ratios, weaker springs) spread and
/// stretched ones contract. Positive weights keep the planar map a bijection
/// in exact arithmetic; each round's map is lifted at its best scale and
/// kept only if certified by the exact predicate and better as set out in
/// `Sphere_reweighting`; a round not kept is retried from the last kept
/// weights with half the exponent. Returns the rounds kept; `sphere`,
/// `d_area` and `scale` describe the last. With `directed` (a mean-value
/// start, `mean_value_corner_weights()`), each directed weight is scaled by
/// its edge's factor instead of the uniform ones.
template <class EigenSolver>
std::size_t reweighted_tutte_map(const Sphere_problem& P, int puncture, const Area_barrier_energy& energy,
                                 std::vector<Vec3>& sphere, double& d_area, double& scale,
                                 const Sphere_reweighting& settings = Sphere_reweighting(),
                                 const std::vector<double>* directed = nullptr)
{
  if(!(d_area > settings.above) || P.faces.size() < settings.min_faces) return 0;
  const std::size_t F = P.faces.size();
  // The undirected edges (sorted keys), the edge of each face corner (from
  // corner k to k + 1) and the two faces of each edge; weights start at 1.
  std::vector<std::uint64_t> keys;
  keys.reserve(3 * F);
  for(const Face& t : P.faces)
    for(int k = 0; k < 3; ++k) keys.push_back(undirected_edge_key(t[k], t[(k + 1) % 3]));
  std::vector<std::size_t> corner_edge(3 * F);
  std::vector<std::uint64_t> edges(keys);
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  std::vector<std::array<int, 2> > faces_of(edges.size(), std::array<int, 2>{{ -1, -1 }});
  for(std::size_t c = 0; c < 3 * F; ++c) {
    const std::size_t e = std::size_t(std::lower_bound(edges.begin(), edges.end(), keys[c]) - edges.begin());
    corner_edge[c] = e;
    faces_of[e][faces_of[e][0] < 0 ? 0 : 1] = int(c / 3);
  }
  std::vector<double> w(edges.size(), 1.), trial, corner_weights(directed ? 6 * F : 3 * F);
  double T = 0;
  for(double t : P.target) T += t;
  double share = largest_face_share(sphere, P.faces);
  std::size_t kept = 0;
  std::vector<double> u, log_ratio(F);
  std::vector<Vec2> uv;
  std::vector<Vec3> p;
  // One round with the given exponent from the last kept weights; true if kept.
  auto round = [&](double exponent) {
    cone_areas_sphere(sphere, P.faces, u);
    double U = 0;
    for(double a : u) U += a;
    for(std::size_t f = 0; f < F; ++f) log_ratio[f] = std::log((u[f] / U) / (P.target[f] / T));
    trial = w;
    double largest = 0;
    for(std::size_t e = 0; e < trial.size(); ++e) {
      trial[e] *= std::exp(0.5 * exponent * (log_ratio[std::size_t(faces_of[e][0])] + log_ratio[std::size_t(faces_of[e][1])]));
      largest = (std::max)(largest, trial[e]);
    }
    bool normal = std::isnormal(largest);
    for(std::size_t e = 0; normal && e < trial.size(); ++e) normal = std::isnormal(trial[e] /= largest);
    if(!normal) return false; // the weights' range left double precision
    if(directed) {
      // Corner k's edges: to k + 1 is corner k's edge, to k + 2 is corner k + 2's.
      for(std::size_t c = 0; c < 3 * F; ++c) {
        const std::size_t f = c / 3, k = c % 3;
        corner_weights[2 * c] = (*directed)[2 * c] * trial[corner_edge[c]];
        corner_weights[2 * c + 1] = (*directed)[2 * c + 1] * trial[corner_edge[3 * f + (k + 2) % 3]];
      }
      if(!punctured_planar_map_directed<Sphere_lu_solver>(P, puncture, corner_weights, uv)) return false;
    } else {
      for(std::size_t c = 0; c < 3 * F; ++c) corner_weights[c] = trial[corner_edge[c]];
      if(!punctured_planar_map<EigenSolver>(P, puncture, false, uv, &corner_weights)) return false;
    }
    bool mirror = false;
    const std::pair<double, double> best = best_oriented_lift(P, energy, uv, mirror, p, u);
    if(!std::isfinite(best.second)) return false;
    lift_to_sphere(uv, std::exp(best.first), Vec2{{ 0, 0 }}, mirror, p);
    if(!count_orientations_sphere(p, P.faces).all_positive()) return false;
    const double D = flat_d_area(p, P.faces, P.target);
    const double sh = largest_face_share(p, P.faces);
    if(!(D * settings.least_gain <= d_area) || sh > share) return false;
    sphere.swap(p);
    w.swap(trial);
    d_area = D;
    share = sh;
    scale = std::exp(best.first);
    return true;
  };
  double exponent = settings.exponent;
  for(std::size_t r = 0; r < settings.max_rounds && exponent >= settings.least_exponent && d_area > settings.above; ++r) {
    if(round(exponent)) ++kept;
    else exponent *= 0.5;
  }
  return kept;
}

/// Extremal faces: those with the largest and smallest centroid coordinate
/// along each axis and the one farthest from the centre of mass. On a shape
/// with protrusions they sit at protrusion tips, whose puncture keeps that
/// protrusion out of the compressed core of the Tutte map.
inline std::vector<int> extremal_faces(const Sphere_problem& P)
{
  const std::size_t F = P.faces.size();
  std::vector<Vec3> c(F);
  Vec3 m{{ 0, 0, 0 }};
  double A = 0;
  for(std::size_t f = 0; f < F; ++f) {
    const Face& t = P.faces[f];
    for(int j = 0; j < 3; ++j)
      c[f][std::size_t(j)] = (P.xyz[std::size_t(t[0])][std::size_t(j)] + P.xyz[std::size_t(t[1])][std::size_t(j)] +
                              P.xyz[std::size_t(t[2])][std::size_t(j)]) / 3;
    for(int j = 0; j < 3; ++j) m[std::size_t(j)] += P.target[f] * c[f][std::size_t(j)];
    A += P.target[f];
  }
  for(double& x : m) x /= A;
  std::vector<int> out;
  for(int j = 0; j < 3; ++j) {
    std::size_t lo = 0, hi = 0;
    for(std::size_t f = 1; f < F; ++f) {
      if(c[f][std::size_t(j)] < c[lo][std::size_t(j)]) lo = f;
      if(c[f][std::size_t(j)] > c[hi][std::size_t(j)]) hi = f;
    }
    out.push_back(int(lo));
    out.push_back(int(hi));
  }
  std::size_t far = 0;
  for(std::size_t f = 1; f < F; ++f)
    if(dot(sub(c[f], m), sub(c[f], m)) > dot(sub(c[far], m), sub(c[far], m))) far = f;
  out.push_back(int(far));
  return out;
}

/// The certified initial map (Tutte's, or with `conformal` the cotangent-harmonic one). Candidates: the `well_shaped` best-scored
/// punctures, then (when `extremal`) the faces at the shape's extremes. Each
/// is mapped and lifted at its best scale; the first certified one is kept,
/// or with `keep_best` the certified one of least energy. (Measured: the
/// start's energy is a poor guide — keeping the best of ten candidates cost
/// 5–7 s on bunny00 and its flow needed more iterations, 206 against 33 from
/// the first candidate; the others are a fallback for when it fails.)
/// `sphere` receives unit vectors only when one is certified.
/// With `reweight` (Tutte's start only), a start compressed beyond
/// `Sphere_reweighting::above` is then reweighted (`reweighted_tutte_map()`).
template <class EigenSolver>
Sphere_initial_outcome certified_sphere_initial_map(const Sphere_problem& P, std::vector<Vec3>& sphere,
                                                    bool conformal = false, std::size_t well_shaped = 3,
                                                    bool extremal = true, bool keep_best = false,
                                                    bool reweight = false, bool mean_value = false)
{
  Sphere_initial_outcome out;
  const Area_barrier_energy energy(P.target);
  std::vector<int> candidates = puncture_candidates(P, well_shaped);
  if(extremal)
    for(int f : extremal_faces(P))
      if(std::find(candidates.begin(), candidates.end(), f) == candidates.end()) candidates.push_back(f);
  std::ostringstream why;
  std::vector<Vec2> uv;
  std::vector<Vec3> p;
  std::vector<double> u;
  double best_E = std::numeric_limits<double>::infinity();
  mean_value = mean_value && !conformal;
  const std::vector<double> directed = mean_value ? mean_value_corner_weights(P) : std::vector<double>();
  for(int f : candidates) {
    ++out.attempts;
    if(mean_value ? !punctured_planar_map_directed<Sphere_lu_solver>(P, f, directed, uv)
                  : !punctured_planar_map<EigenSolver>(P, f, conformal, uv)) {
      why << " puncture " << f << ": the " << (conformal ? "cotangent" : mean_value ? "mean-value" : "Tutte") << " solve failed;";
      continue;
    }
    bool mirror = false;
    const std::pair<double, double> best = best_oriented_lift(P, energy, uv, mirror, p, u);
    if(!std::isfinite(best.second)) { why << " puncture " << f << ": no scale keeps every face positive in floating point;"; continue; }
    if(!(best.second < best_E)) continue;
    lift_to_sphere(uv, std::exp(best.first), Vec2{{ 0, 0 }}, mirror, p);
    const Orientation_count oc = count_orientations_sphere(p, P.faces);
    if(!oc.all_positive()) {
      why << " puncture " << f << ": " << oc.inverted << " inverted and " << oc.degenerate
          << " degenerate faces by the exact predicate (first: face " << oc.first_bad << ");";
      continue;
    }
    best_E = best.second;
    sphere.swap(p);
    out.certified = true;
    out.puncture = f;
    out.scale = std::exp(best.first);
    if(!keep_best) break;
  }
  if(out.certified) {
    out.d_area = flat_d_area(sphere, P.faces, P.target);
    if(reweight && !conformal)
      out.reweightings = reweighted_tutte_map<EigenSolver>(P, out.puncture, energy, sphere, out.d_area, out.scale,
                                                           Sphere_reweighting(), mean_value ? &directed : nullptr);
  }
  else out.message = std::string("no ") + (conformal ? "conformal " : "") + "initial spherical map could be certified after " +
                     std::to_string(out.attempts) + " punctures:" + why.str();
  return out;
}

/// The caller's start: `given` normalised into `sphere` and certified.
/// Returns an empty string on success, else what is wrong (which vertex, or
/// how many faces fold and the first).
inline std::string certified_given_sphere_map(const Sphere_problem& P, const std::vector<Vec3>& given,
                                              std::vector<Vec3>& sphere)
{
  if(given.size() != P.xyz.size())
    return "the given initial map has " + std::to_string(given.size()) + " points for " + std::to_string(P.xyz.size()) +
           " vertices";
  std::vector<Vec3> p(given.size());
  for(std::size_t v = 0; v < given.size(); ++v) {
    const double r = norm3(given[v]);
    if(!std::isfinite(r) || !(r > 0))
      return "the given initial map's point of vertex " + std::to_string(v) + " is " +
             (std::isfinite(r) ? "at the centre" : "not finite");
    p[v] = {{ given[v][0] / r, given[v][1] / r, given[v][2] / r }};
  }
  const Orientation_count oc = count_orientations_sphere(p, P.faces);
  if(!oc.all_positive()) {
    std::ostringstream why;
    why << "the given initial map has " << oc.inverted << " inverted and " << oc.degenerate
        << " degenerate faces on the unit sphere by the exact predicate (first: face " << oc.first_bad << ")";
    return why.str();
  }
  sphere.swap(p);
  return std::string();
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
