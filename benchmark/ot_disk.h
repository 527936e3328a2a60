// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The optimal-transport peer of doc/paper_experiments.md: a semi-discrete
// optimal transport map from point masses in the unit disk to the uniform
// measure of the disk, in the style of the OMT references of the paper
// (Zhao, Su, Gu et al.). The point i with mass ν_i gets the power cell
//
//   W_i(h) = { x in the disk : <x, p_i> + h_i >= <x, p_j> + h_j for all j },
//
// and the Brenier potential's heights h solve |W_i(h)| = ν_i. They minimise
// the convex energy E(h) = Σ ν_i h_i − ∫_disk max_i(<x, p_i> + h_i) dx, whose
// gradient is ν − |W(h)| and whose Hessian is the weighted graph Laplacian of
// the power diagram, ∂|W_i|/∂h_j = −|e_ij| / |p_i − p_j| (e_ij the common
// edge of the two cells inside the disk). The power diagram is the dual of
// CGAL's Regular_triangulation_2 with weights w_i = 2 h_i + |p_i|² (power
// distance |x − p_i|² − w_i = |x|² − 2(<x, p_i> + h_i)); cells are clipped to
// the disk exactly (segments and circular arcs). Newton's method is damped as
// in Kitagawa, Mérigot and Thibert (2019): a step is halved until every cell
// keeps at least half the smallest of the targets and the start's cell areas,
// and the gradient norm falls by the factor 1 − α/2.

#ifndef DLF_BENCHMARK_OT_DISK_H
#define DLF_BENCHMARK_OT_DISK_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Regular_triangulation_2.h>
#include <CGAL/Regular_triangulation_face_base_2.h>
#include <CGAL/Regular_triangulation_vertex_base_2.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <array>
#include <chrono>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace dlf_benchmark {
namespace ot {

typedef std::array<double, 2> P;

/// A convex polygon, counter-clockwise; edge k (from v[k] to v[k+1]) lies on
/// the bisector with the cell of `label[k]` (−1: the bounding box).
struct Polygon
{
  std::vector<P> v;
  std::vector<int> label;
};

/// Keeps the part of `poly` where n·x ≤ c; the new edge gets `label`.
inline void clip(Polygon& poly, const P& n, double c, int label)
{
  Polygon out;
  const std::size_t m = poly.v.size();
  for(std::size_t k = 0; k < m; ++k) {
    const P& a = poly.v[k];
    const P& b = poly.v[(k + 1) % m];
    const double sa = n[0] * a[0] + n[1] * a[1] - c, sb = n[0] * b[0] + n[1] * b[1] - c;
    const bool ina = sa <= 0, inb = sb <= 0;
    const auto cut = [&]() {
      const double t = sa / (sa - sb);
      return P{{ a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]) }};
    };
    if(ina) { out.v.push_back(a); out.label.push_back(poly.label[k]); }
    if(ina && !inb) { out.v.push_back(cut()); out.label.push_back(label); }
    if(!ina && inb) { out.v.push_back(cut()); out.label.push_back(poly.label[k]); }
  }
  poly = std::move(out);
}

/// The part of a cell inside the unit disk: area, first moments, ∫|x|², and
/// the length inside the disk of each labelled edge.
struct Cell_measure
{
  double area = 0, mx = 0, my = 0, second = 0;
  std::vector<std::pair<int, double> > edges;
};

inline Cell_measure disk_measure(const Polygon& poly)
{
  Cell_measure out;
  struct Piece { P s, e; };
  std::vector<Piece> pieces;
  const std::size_t m = poly.v.size();
  for(std::size_t k = 0; k < m; ++k) {
    const P& a = poly.v[k];
    const P& b = poly.v[(k + 1) % m];
    const P d{{ b[0] - a[0], b[1] - a[1] }};
    const double A = d[0] * d[0] + d[1] * d[1], B = 2 * (a[0] * d[0] + a[1] * d[1]), C = a[0] * a[0] + a[1] * a[1] - 1;
    const double disc = B * B - 4 * A * C;
    if(A == 0 || disc <= 0) continue;
    const double r = std::sqrt(disc);
    // Roots without cancellation.
    const double q = -0.5 * (B + (B >= 0 ? r : -r));
    double t0 = q / A, t1 = C / q;
    if(q == 0) t0 = t1 = 0;
    if(t0 > t1) std::swap(t0, t1);
    const double lo = (std::max)(t0, 0.), hi = (std::min)(t1, 1.);
    if(!(lo < hi)) continue;
    const P s{{ a[0] + lo * d[0], a[1] + lo * d[1] }}, e{{ a[0] + hi * d[0], a[1] + hi * d[1] }};
    pieces.push_back({ s, e });
    if(poly.label[k] >= 0) out.edges.emplace_back(poly.label[k], (hi - lo) * std::sqrt(A));
  }
  if(pieces.empty()) {
    // No boundary inside the disk: the disk is inside the cell or outside it.
    bool contains_origin = m >= 3;
    for(std::size_t k = 0; k < m && contains_origin; ++k) {
      const P& a = poly.v[k];
      const P& b = poly.v[(k + 1) % m];
      contains_origin = (b[0] - a[0]) * (-a[1]) - (b[1] - a[1]) * (-a[0]) >= 0;
    }
    if(contains_origin) { out.area = M_PI; out.second = M_PI / 2; }
    return out;
  }
  // Fan from the origin: triangles (0, s, e) for the segments, sectors for
  // the arcs of the circle between one piece's end and the next one's start.
  const auto sector = [&](const P& from, const P& to, bool whole_turn_if_equal) {
    const double t1 = std::atan2(from[1], from[0]), t2 = std::atan2(to[1], to[0]);
    double dt = t2 - t1;
    if(dt < 0 || (whole_turn_if_equal && dt <= 0)) dt += 2 * M_PI;
    out.area += dt / 2;
    out.mx += (std::sin(t1 + dt) - std::sin(t1)) / 3;
    out.my += (std::cos(t1) - std::cos(t1 + dt)) / 3;
    out.second += dt / 4;
  };
  for(std::size_t k = 0; k < pieces.size(); ++k) {
    const P &s = pieces[k].s, &e = pieces[k].e;
    const double cr = s[0] * e[1] - s[1] * e[0];
    out.area += cr / 2;
    out.mx += cr / 6 * (s[0] + e[0]);
    out.my += cr / 6 * (s[1] + e[1]);
    out.second += cr / 12 * (s[0] * s[0] + s[1] * s[1] + e[0] * e[0] + e[1] * e[1] + s[0] * e[0] + s[1] * e[1]);
    const P& next = pieces[(k + 1) % pieces.size()].s;
    if(pieces.size() == 1) sector(e, next, true);
    else if(std::hypot(next[0] - e[0], next[1] - e[1]) > 1e-13) sector(e, next, false);
  }
  return out;
}

/// The power cells of `points` for the heights `h`, measured in the disk.
struct Evaluation
{
  std::vector<Cell_measure> cells;
  bool all_present = true; ///< no point hidden by the regular triangulation
  double min_area = 0;
};

inline Evaluation evaluate(const std::vector<P>& points, const std::vector<double>& h)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  typedef CGAL::Regular_triangulation_vertex_base_2<K> Vbase;
  typedef CGAL::Triangulation_vertex_base_with_info_2<int, K, Vbase> Vb;
  typedef CGAL::Regular_triangulation_face_base_2<K> Fb;
  typedef CGAL::Triangulation_data_structure_2<Vb, Fb> Tds;
  typedef CGAL::Regular_triangulation_2<K, Tds> Rt;
  const std::size_t n = points.size();
  std::vector<std::pair<K::Weighted_point_2, int> > wp;
  wp.reserve(n);
  for(std::size_t i = 0; i < n; ++i) {
    const P& p = points[i];
    wp.emplace_back(K::Weighted_point_2(K::Point_2(p[0], p[1]), 2 * h[i] + p[0] * p[0] + p[1] * p[1]), int(i));
  }
  Rt rt;
  rt.insert(wp.begin(), wp.end());
  Evaluation ev;
  ev.cells.assign(n, Cell_measure());
  std::vector<char> present(n, 0);
  for(auto v = rt.finite_vertices_begin(); v != rt.finite_vertices_end(); ++v) {
    const int i = v->info();
    present[std::size_t(i)] = 1;
    Polygon cell;
    cell.v = { P{{ -2, -2 }}, P{{ 2, -2 }}, P{{ 2, 2 }}, P{{ -2, 2 }} };
    cell.label = { -1, -1, -1, -1 };
    auto c = rt.incident_vertices(v), done = c;
    if(c != nullptr) do {
      if(rt.is_infinite(c)) continue;
      const int j = c->info();
      const P &pi = points[std::size_t(i)], &pj = points[std::size_t(j)];
      // <x, p_i> + h_i >= <x, p_j> + h_j  <=>  <x, p_j − p_i> <= h_i − h_j.
      clip(cell, P{{ pj[0] - pi[0], pj[1] - pi[1] }}, h[std::size_t(i)] - h[std::size_t(j)], j);
    } while(++c != done && !cell.v.empty());
    ev.cells[std::size_t(i)] = disk_measure(cell);
  }
  ev.min_area = std::numeric_limits<double>::infinity();
  for(std::size_t i = 0; i < n; ++i) {
    if(!present[i]) ev.all_present = false;
    ev.min_area = (std::min)(ev.min_area, ev.cells[i].area);
  }
  return ev;
}

struct Result
{
  bool converged = false;
  std::string message;
  int newton_iterations = 0;
  int halvings = 0;            ///< step halvings over the whole run
  double gradient_relative = 0; ///< ‖|W(h)| − ν‖₂ / ‖ν‖₂ at the end
  double w2 = 0;               ///< the semi-discrete W2 distance, (Σ_i ∫_{W_i} |x − p_i|² dx / π)^½
  std::vector<double> h;
  std::vector<double> cell_area;
  std::vector<P> centroid;     ///< of each cell: where the map sends point i
  std::vector<double> gradient_history;
};

inline double norm2(const std::vector<double>& g)
{
  double s = 0;
  for(double x : g) s += x * x;
  return std::sqrt(s);
}

/// The gradient ν − |W(h)| of the convex energy (the Newton system below
/// solves for its zero).
inline std::vector<double> residual(const Evaluation& ev, const std::vector<double>& nu)
{
  std::vector<double> g(nu.size());
  for(std::size_t i = 0; i < nu.size(); ++i) g[i] = ev.cells[i].area - nu[i];
  return g;
}

/// Solves |W_i(h)| = ν_i for points in the closed unit disk with masses
/// summing to π, to ‖|W(h)| − ν‖₂ ≤ tolerance · ‖ν‖₂.
inline Result solve(const std::vector<P>& points, const std::vector<double>& nu, double tolerance = 1e-8,
                    int max_iterations = 100)
{
  Result R;
  const std::size_t n = points.size();
  // Start from the Voronoi diagram (power weights 0): h_i = −|p_i|² / 2.
  R.h.resize(n);
  for(std::size_t i = 0; i < n; ++i) R.h[i] = -0.5 * (points[i][0] * points[i][0] + points[i][1] * points[i][1]);
  if(n < 2) { R.message = "fewer than two points"; return R; }
  double nu_min = nu[0], nu_sum = 0;
  for(double x : nu) { nu_min = (std::min)(nu_min, x); nu_sum += x; }
  if(!(nu_min > 0) || std::abs(nu_sum - M_PI) > 1e-9 * M_PI) { R.message = "masses must be positive and sum to pi"; return R; }
  Evaluation ev = evaluate(points, R.h);
  if(!ev.all_present || !(ev.min_area > 0)) { R.message = "a point has an empty Voronoi cell in the disk (repeated point?)"; return R; }
  const double keep = 0.5 * (std::min)(nu_min, ev.min_area);
  const double nu_norm = norm2(nu);
  std::vector<double> g = residual(ev, nu);
  double gn = norm2(g);
  for(;;) {
    R.gradient_history.push_back(gn / nu_norm);
    if(gn <= tolerance * nu_norm) { R.converged = true; break; }
    if(R.newton_iterations >= max_iterations) { R.message = "Newton iteration cap"; break; }
    // Hessian of the areas, with h_0 pinned (the areas see h up to a constant).
    std::vector<Eigen::Triplet<double> > trip;
    for(std::size_t i = 1; i < n; ++i) {
      double diag = 0;
      for(const auto& e : ev.cells[i].edges) {
        const P &pi = points[i], &pj = points[std::size_t(e.first)];
        const double w = e.second / std::hypot(pj[0] - pi[0], pj[1] - pi[1]);
        diag += w;
        if(e.first > 0) trip.emplace_back(int(i) - 1, e.first - 1, -w);
      }
      trip.emplace_back(int(i) - 1, int(i) - 1, diag);
    }
    Eigen::SparseMatrix<double> H(int(n) - 1, int(n) - 1);
    H.setFromTriplets(trip.begin(), trip.end());
    Eigen::SparseMatrix<double> Hs = 0.5 * (H + Eigen::SparseMatrix<double>(H.transpose()));
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double> > ldlt(Hs);
    if(ldlt.info() != Eigen::Success) { R.message = "the Hessian of the power diagram is singular"; break; }
    Eigen::VectorXd rhs(int(n) - 1);
    for(std::size_t i = 1; i < n; ++i) rhs[int(i) - 1] = -g[i];
    const Eigen::VectorXd step = ldlt.solve(rhs);
    double alpha = 1;
    bool accepted = false;
    while(alpha > 1e-12) {
      std::vector<double> trial = R.h;
      for(std::size_t i = 1; i < n; ++i) trial[i] += alpha * step[int(i) - 1];
      Evaluation et = evaluate(points, trial);
      if(et.all_present && et.min_area >= keep) {
        const std::vector<double> gt = residual(et, nu);
        const double gtn = norm2(gt);
        if(gtn <= (1 - alpha / 2) * gn) {
          R.h = std::move(trial);
          ev = std::move(et);
          g = gt;
          gn = gtn;
          accepted = true;
          break;
        }
      }
      alpha /= 2;
      ++R.halvings;
    }
    ++R.newton_iterations;
    if(!accepted) { R.message = "no damped Newton step decreases the gradient (rounding floor)"; break; }
  }
  R.gradient_relative = gn / nu_norm;
  R.cell_area.resize(n);
  R.centroid.resize(n);
  double cost = 0;
  for(std::size_t i = 0; i < n; ++i) {
    const Cell_measure& c = ev.cells[i];
    R.cell_area[i] = c.area;
    R.centroid[i] = c.area > 0 ? P{{ c.mx / c.area, c.my / c.area }} : points[i];
    const P& p = points[i];
    cost += c.second - 2 * (p[0] * c.mx + p[1] * c.my) + (p[0] * p[0] + p[1] * p[1]) * c.area;
  }
  R.w2 = std::sqrt((std::max)(0., cost) / M_PI);
  if(R.converged) R.message = "converged";
  return R;
}

} // namespace ot
} // namespace dlf_benchmark

#endif
