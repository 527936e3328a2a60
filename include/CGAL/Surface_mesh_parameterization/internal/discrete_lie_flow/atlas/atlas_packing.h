// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Packing the charts into the unit square, every chart keeping its share of
// the surface (one common scale). Two ways: cells of a squarified treemap
// of the unit square, one per chart's bounding box, each chart stretched by
// an area-preserving affine map (u, v) → (a·u, v/a) to its cell's shape
// (the default: square charts then fill the square); or shelves of the
// boxes as they are, by decreasing height, the largest scale that fits
// found by bisection. The check afterwards is exact on the stored doubles:
// every point in [0, 1]², the charts' boxes pairwise disjoint (so no two
// charts overlap).

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_ATLAS_PACKING_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_ATLAS_PACKING_H

#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/geometry.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

struct Box2
{
  double lo[2] = { 0, 0 }, hi[2] = { 0, 0 };
  double width() const { return hi[0] - lo[0]; }
  double height() const { return hi[1] - lo[1]; }
};

inline Box2 bounding_box(const std::vector<Vec2>& uv)
{
  Box2 b;
  if(uv.empty()) return b;
  b.lo[0] = b.hi[0] = uv[0][0];
  b.lo[1] = b.hi[1] = uv[0][1];
  for(const Vec2& p : uv)
    for(int i = 0; i < 2; ++i) { b.lo[i] = (std::min)(b.lo[i], p[i]); b.hi[i] = (std::max)(b.hi[i], p[i]); }
  return b;
}

/// Shelf packing of rectangles `w × h` (plus `gutter` around each) at scale
/// `s` into the unit square: the lower-left corners, or false if they do not fit.
inline bool shelf_pack(const std::vector<double>& w, const std::vector<double>& h, const std::vector<std::size_t>& order,
                       double s, double gutter, std::vector<Vec2>& corner)
{
  corner.assign(w.size(), Vec2{{ 0, 0 }});
  double x = 0, y = 0, shelf = 0;
  for(std::size_t i : order) {
    const double bw = s * w[i] + gutter, bh = s * h[i] + gutter;
    if(bw > 1 || bh > 1) return false;
    if(x + bw > 1) { y += shelf; x = 0; shelf = 0; }
    if(y + bh > 1) return false;
    corner[i] = {{ x, y }};
    x += bw;
    shelf = (std::max)(shelf, bh);
  }
  return true;
}

/// Places the charts (each `uv[c]` already at its share: area = its surface
/// area, in any units) into the unit square: turns, scales and translates
/// them in place. Returns the common scale applied (0 if nothing fits).
inline double pack_charts(std::vector<std::vector<Vec2> >& uv, double gutter)
{
  const std::size_t n = uv.size();
  std::vector<double> w(n), h(n);
  for(std::size_t c = 0; c < n; ++c) {
    Box2 b = bounding_box(uv[c]);
    if(b.height() > b.width()) { // a quarter turn, exact in doubles: (u, v) → (−v, u)
      for(Vec2& p : uv[c]) p = {{ -p[1], p[0] }};
      b = bounding_box(uv[c]);
    }
    for(Vec2& p : uv[c]) p = {{ p[0] - b.lo[0], p[1] - b.lo[1] }};
    w[c] = b.width();
    h[c] = b.height();
  }
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return h[a] > h[b]; });
  // Bisection on the scale; `lo` always fits.
  double total = 0, biggest = 0;
  for(std::size_t c = 0; c < n; ++c) { total += w[c] * h[c]; biggest = (std::max)(biggest, (std::max)(w[c], h[c])); }
  if(!(total > 0) || !(gutter < 1)) return 0;
  double hi = (std::min)(1 / std::sqrt(total), 1 / biggest), lo = 0;
  std::vector<Vec2> corner, best;
  for(int it = 0; it < 60; ++it) {
    const double mid = 0.5 * (lo + hi);
    if(shelf_pack(w, h, order, mid, gutter, corner)) { lo = mid; best = corner; }
    else hi = mid;
  }
  if(!(lo > 0)) return 0;
  // Each chart sits half a gutter inside its slot; a margin for rounding
  // keeps the scaled chart inside the slot.
  const double s = lo * (1 - 1e-12);
  for(std::size_t c = 0; c < n; ++c)
    for(Vec2& p : uv[c]) p = {{ best[c][0] + 0.5 * gutter + s * p[0], best[c][1] + 0.5 * gutter + s * p[1] }};
  return s;
}

/// The cells of a squarified treemap (Bruls, Huizing, van Wijk 2000) of the
/// unit square with areas proportional to `area` (positive): one box per item.
inline std::vector<Box2> squarified_cells(const std::vector<double>& area)
{
  const std::size_t n = area.size();
  std::vector<Box2> cell(n);
  double total = 0;
  for(double a : area) total += a;
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return area[a] > area[b]; });
  double x = 0, y = 0, w = 1, h = 1;
  auto worst = [](double sum, double lo, double hi, double side) { // the worst aspect ratio of a row
    const double s2 = sum * sum, l2 = side * side;
    return (std::max)(l2 * hi / s2, s2 / (l2 * lo));
  };
  std::size_t i = 0;
  while(i < n) {
    const double side = (std::min)(w, h);
    std::size_t j = i;
    double sum = 0, lo = 0, hi = 0;
    for(; j < n; ++j) {
      const double a = area[order[j]] / total;
      if(j > i && worst(sum + a, (std::min)(lo, a), (std::max)(hi, a), side) > worst(sum, lo, hi, side)) break;
      sum += a;
      lo = j == i ? a : (std::min)(lo, a);
      hi = j == i ? a : (std::max)(hi, a);
    }
    if(j == n) sum = w * h; // the last row takes what is left (rounding)
    const double t = sum / side;
    double along = 0;
    for(std::size_t k = i; k < j; ++k) {
      const double a = area[order[k]] / total;
      const double len = k + 1 == j ? side - along : side * a / sum;
      Box2& b = cell[order[k]];
      if(w >= h) { b.lo[0] = x; b.hi[0] = x + t; b.lo[1] = y + along; b.hi[1] = y + along + len; }
      else { b.lo[0] = x + along; b.hi[0] = x + along + len; b.lo[1] = y; b.hi[1] = y + t; }
      along += len;
    }
    if(w >= h) { x += t; w -= t; } else { y += t; h -= t; }
    i = j;
  }
  return cell;
}

/// Places the charts (each `uv[c]` at its share: area = its surface area,
/// in any units) in the cells of `squarified_cells()` of their bounding
/// boxes, each a gutter inside its cell, stretched by (a, 1/a) to the
/// cell's shape, all scaled by one factor. Returns that factor (0 if the
/// gutter leaves no room) and, in `stretch`, the largest max(a, 1/a).
inline double fill_charts(std::vector<std::vector<Vec2> >& uv, double gutter, double& stretch)
{
  const std::size_t n = uv.size();
  std::vector<Box2> box(n);
  std::vector<double> area(n);
  for(std::size_t c = 0; c < n; ++c) {
    box[c] = bounding_box(uv[c]);
    area[c] = box[c].width() * box[c].height();
    if(!(area[c] > 0)) return 0;
  }
  // One scale for all: the chart's box takes `s` times its area, inside
  // its cell less the gutter (and a relative margin for rounding). The
  // cells are sized for the box and its gutter: (√(s·area) + gutter)², `s`
  // from the previous round.
  const double margin = 1e-12;
  double total = 0;
  for(double a : area) total += a;
  double s = 1 / total;
  std::vector<Box2> cell;
  std::vector<double> W(n), H(n), want(n);
  for(int round = 0; round < 4; ++round) {
    for(std::size_t c = 0; c < n; ++c) want[c] = std::pow(std::sqrt(s * area[c]) + gutter, 2);
    cell = squarified_cells(want);
    double next = std::numeric_limits<double>::infinity();
    for(std::size_t c = 0; c < n; ++c) {
      W[c] = (cell[c].width() - gutter) * (1 - margin);
      H[c] = (cell[c].height() - gutter) * (1 - margin);
      next = (W[c] > 0 && H[c] > 0) ? (std::min)(next, W[c] * H[c] / area[c]) : 0.;
      if(!(next > 0)) break;
    }
    if(!(next > 0)) return 0;
    s = next;
  }
  stretch = 1;
  for(std::size_t c = 0; c < n; ++c) {
    const double k = std::sqrt(s * area[c] / (W[c] * H[c])); // ≤ 1: the box's share of the cell, per side
    const double sx = k * W[c] / box[c].width(), sy = k * H[c] / box[c].height();
    const double x0 = cell[c].lo[0] + 0.5 * gutter + 0.5 * (W[c] - k * W[c]);
    const double y0 = cell[c].lo[1] + 0.5 * gutter + 0.5 * (H[c] - k * H[c]);
    for(Vec2& p : uv[c]) p = {{ x0 + sx * (p[0] - box[c].lo[0]), y0 + sy * (p[1] - box[c].lo[1]) }};
    const double a = std::sqrt(sx / sy);
    stretch = (std::max)(stretch, (std::max)(a, 1 / a));
  }
  return s;
}

/// Pairs of charts whose bounding boxes overlap (interiors meet), and points
/// outside [0, 1]², by comparisons of the stored doubles (exact).
inline std::size_t overlapping_chart_pairs(const std::vector<std::vector<Vec2> >& uv, std::size_t& outside)
{
  std::vector<Box2> box;
  outside = 0;
  for(const std::vector<Vec2>& c : uv) {
    box.push_back(bounding_box(c));
    for(const Vec2& p : c)
      if(!(p[0] >= 0 && p[0] <= 1 && p[1] >= 0 && p[1] <= 1)) ++outside;
  }
  std::vector<std::size_t> order(box.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return box[a].lo[0] < box[b].lo[0]; });
  std::size_t pairs = 0;
  for(std::size_t i = 0; i < order.size(); ++i)
    for(std::size_t j = i + 1; j < order.size() && box[order[j]].lo[0] < box[order[i]].hi[0]; ++j) {
      const Box2 &a = box[order[i]], &b = box[order[j]];
      if(a.lo[1] < b.hi[1] && b.lo[1] < a.hi[1]) ++pairs;
    }
  return pairs;
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
