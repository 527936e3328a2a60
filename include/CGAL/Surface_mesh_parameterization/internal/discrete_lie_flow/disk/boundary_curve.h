// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The fixed curve that boundary vertices slide on (circle, square with fixed
// corners, or a free polyline), parameterised by arc length counter-clockwise;
// a floating border has none (its vertices move as the interior's).

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_BOUNDARY_CURVE_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_BOUNDARY_CURVE_H

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_options.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/critical_step.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// A closed curve with an arc-length parameter s ∈ [0, length), and for each
/// boundary vertex its parameter and the open interval it may slide in.
class Boundary_curve
{
public:
  typedef Discrete_lie_flow_border Kind;

  /// Builds the curve through `pts` (boundary positions, counter-clockwise).
  /// `kind` AUTOMATIC detects a circle or an axis-aligned square.
  Boundary_curve(const std::vector<Vec2>& pts, Kind kind)
  {
    // A floating border is no curve: its vertices move freely (planar_dofs.h);
    // the polyline through them is kept for what asks the curve.
    const bool floating = kind == Kind::FLOATING;
    if(floating) kind = Kind::FREE;
    if(kind == Kind::AUTOMATIC)
      kind = fits_square(pts) ? Kind::SQUARE : (fits_circle(pts) ? Kind::CIRCLE : Kind::FREE);
    if(kind == Kind::CIRCLE && !fit_circle(pts, m_center, m_radius)) kind = Kind::FREE;
    m_kind = floating ? Kind::FLOATING : kind;
    const std::size_t n = pts.size();
    if(kind == Kind::CIRCLE) {
      m_length = 2 * M_PI * m_radius;
    } else if(kind == Kind::SQUARE) {
      double x0 = pts[0][0], y0 = pts[0][1], x1 = x0, y1 = y0;
      for(const Vec2& p : pts) {
        x0 = (std::min)(x0, p[0]); x1 = (std::max)(x1, p[0]);
        y0 = (std::min)(y0, p[1]); y1 = (std::max)(y1, p[1]);
      }
      m_origin = {{ x0, y0 }};
      m_side = 0.5 * ((x1 - x0) + (y1 - y0));
      m_length = 4 * m_side;
    } else {
      m_poly = pts;
      m_cumul.assign(n + 1, 0.);
      for(std::size_t i = 0; i < n; ++i)
        m_cumul[i + 1] = m_cumul[i] + dist(pts[i], pts[(i + 1) % n]);
      m_length = m_cumul[n];
    }
    // Parameters of the vertices; the free polyline has its corners there.
    m_s.resize(n);
    for(std::size_t i = 0; i < n; ++i)
      m_s[i] = (kind == Kind::FREE) ? m_cumul[i] : parameter_of(pts[i]);
    // Square corners are fixed; other vertices may slide strictly between
    // the corners that enclose them.
    m_fixed.assign(n, false);
    if(kind == Kind::SQUARE) {
      const double tol = 1e-9 * m_length;
      for(std::size_t i = 0; i < n; ++i) {
        const double q = m_s[i] / m_side;
        if(std::abs(q - std::round(q)) * m_side <= tol) m_fixed[i] = true;
      }
    }
  }

  Kind kind() const { return m_kind; }
  double length() const { return m_length; }
  bool is_fixed(std::size_t i) const { return m_fixed[i]; }
  double parameter(std::size_t i) const { return m_s[i]; }

  /// Position of vertex i after sliding by ds; false when the move leaves
  /// the piece of curve the vertex is confined to (square sides).
  bool slide(std::size_t i, double ds, Vec2& out) const
  {
    if(m_fixed[i]) { out = point(m_s[i]); return ds == 0; }
    const double s = m_s[i] + ds;
    if(m_kind == Kind::SQUARE && std::floor(s / m_side) != std::floor(m_s[i] / m_side)) return false;
    out = point(s);
    return true;
  }
  void commit(std::size_t i, double ds) { if(!m_fixed[i]) m_s[i] = wrap(m_s[i] + ds); }

  /// Unit tangent (direction of increasing s) at vertex i; at a polyline
  /// corner, the normalised mean of the two segment directions.
  Vec2 tangent(std::size_t i) const
  {
    const double s = m_s[i];
    if(m_kind == Kind::CIRCLE) {
      const double a = s / m_radius;
      return {{ -std::sin(a), std::cos(a) }};
    }
    if(m_kind == Kind::SQUARE) {
      static const Vec2 dirs[4] = {{{1, 0}}, {{0, 1}}, {{-1, 0}}, {{0, -1}}};
      return dirs[int(std::floor(s / m_side)) & 3];
    }
    const std::size_t n = m_poly.size();
    std::size_t k = segment_of(s);
    Vec2 t = unit(sub2(m_poly[(k + 1) % n], m_poly[k]));
    if(s - m_cumul[k] <= 1e-12 * m_length) { // at a corner
      const Vec2 tp = unit(sub2(m_poly[k], m_poly[(k + n - 1) % n]));
      t = unit({{ t[0] + tp[0], t[1] + tp[1] }});
    }
    return t;
  }

  Vec2 point(double s) const
  {
    s = wrap(s);
    if(m_kind == Kind::CIRCLE) {
      const double a = s / m_radius;
      return {{ m_center[0] + m_radius * std::cos(a), m_center[1] + m_radius * std::sin(a) }};
    }
    if(m_kind == Kind::SQUARE) {
      const int side = (std::min)(3, int(std::floor(s / m_side)));
      const double t = s - side * m_side, a = m_side;
      const double x0 = m_origin[0], y0 = m_origin[1];
      switch(side) {
      case 0: return {{ x0 + t, y0 }};
      case 1: return {{ x0 + a, y0 + t }};
      case 2: return {{ x0 + a - t, y0 + a }};
      default: return {{ x0, y0 + a - t }};
      }
    }
    const std::size_t n = m_poly.size();
    const std::size_t k = segment_of(s);
    const double len = m_cumul[k + 1] - m_cumul[k];
    const double t = len > 0 ? (s - m_cumul[k]) / len : 0;
    const Vec2& a = m_poly[k];
    const Vec2& b = m_poly[(k + 1) % n];
    return {{ a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]) }};
  }

  /// Least-squares circle through `pts` (Kåsa's algebraic fit, centred
  /// coordinates): exact for points on a circle, however unevenly spaced.
  static bool fit_circle(const std::vector<Vec2>& pts, Vec2& center, double& radius)
  {
    const Vec2 m = centroid(pts);
    double suu = 0, svv = 0, suv = 0, suuu = 0, svvv = 0, suvv = 0, svuu = 0;
    for(const Vec2& p : pts) {
      const double u = p[0] - m[0], v = p[1] - m[1];
      suu += u * u; svv += v * v; suv += u * v;
      suuu += u * u * u; svvv += v * v * v; suvv += u * v * v; svuu += v * u * u;
    }
    const double det = suu * svv - suv * suv;
    if(!(std::abs(det) > 0)) return false;
    const double bu = 0.5 * (suuu + suvv), bv = 0.5 * (svvv + svuu);
    const double uc = (bu * svv - bv * suv) / det, vc = (suu * bv - suv * bu) / det;
    center = {{ m[0] + uc, m[1] + vc }};
    double r = 0;
    for(const Vec2& p : pts) r += dist(p, center);
    radius = r / double(pts.size());
    return std::isfinite(radius) && radius > 0;
  }

  static bool fits_circle(const std::vector<Vec2>& pts)
  {
    Vec2 c;
    double r;
    if(pts.size() < 3 || !fit_circle(pts, c, r)) return false;
    double rmin = dist(pts[0], c), rmax = rmin;
    for(const Vec2& p : pts) { rmin = (std::min)(rmin, dist(p, c)); rmax = (std::max)(rmax, dist(p, c)); }
    return rmax > 0 && rmax - rmin <= 1e-7 * rmax;
  }

  static bool fits_square(const std::vector<Vec2>& pts)
  {
    if(pts.size() < 4) return false;
    double x0 = pts[0][0], y0 = pts[0][1], x1 = x0, y1 = y0;
    for(const Vec2& p : pts) {
      x0 = (std::min)(x0, p[0]); x1 = (std::max)(x1, p[0]);
      y0 = (std::min)(y0, p[1]); y1 = (std::max)(y1, p[1]);
    }
    const double w = x1 - x0, h = y1 - y0, tol = 1e-9 * (w + h);
    if(w <= 0 || std::abs(w - h) > tol) return false;
    int corners = 0;
    for(const Vec2& p : pts) {
      const bool onx = std::abs(p[0] - x0) <= tol || std::abs(p[0] - x1) <= tol;
      const bool ony = std::abs(p[1] - y0) <= tol || std::abs(p[1] - y1) <= tol;
      if(!onx && !ony) return false;
      if(onx && ony) ++corners;
    }
    return corners == 4;
  }

private:
  static Vec2 sub2(const Vec2& a, const Vec2& b) { return {{ a[0] - b[0], a[1] - b[1] }}; }
  static double dist(const Vec2& a, const Vec2& b) { return std::hypot(a[0] - b[0], a[1] - b[1]); }
  static Vec2 unit(const Vec2& v)
  {
    const double l = std::hypot(v[0], v[1]);
    return l > 0 ? Vec2{{ v[0] / l, v[1] / l }} : Vec2{{ 0, 0 }};
  }
  static Vec2 centroid(const std::vector<Vec2>& pts)
  {
    Vec2 c{{ 0, 0 }};
    for(const Vec2& p : pts) { c[0] += p[0]; c[1] += p[1]; }
    c[0] /= double(pts.size()); c[1] /= double(pts.size());
    return c;
  }
  double wrap(double s) const
  {
    s = std::fmod(s, m_length);
    return s < 0 ? s + m_length : s;
  }
  double parameter_of(const Vec2& p) const
  {
    if(m_kind == Kind::CIRCLE) return wrap(m_radius * std::atan2(p[1] - m_center[1], p[0] - m_center[0]));
    // square: the side p lies on (the nearest one)
    const double a = m_side, x = p[0] - m_origin[0], y = p[1] - m_origin[1];
    const double d[4] = { std::abs(y), std::abs(x - a), std::abs(y - a), std::abs(x) };
    const int side = int(std::min_element(d, d + 4) - d);
    switch(side) {
    case 0: return wrap((std::min)((std::max)(x, 0.), a));
    case 1: return a + (std::min)((std::max)(y, 0.), a);
    case 2: return 2 * a + (std::min)((std::max)(a - x, 0.), a);
    default: return wrap(3 * a + (std::min)((std::max)(a - y, 0.), a));
    }
  }
  std::size_t segment_of(double s) const
  {
    s = wrap(s);
    std::size_t k = std::size_t(std::upper_bound(m_cumul.begin(), m_cumul.end(), s) - m_cumul.begin());
    k = (k == 0) ? 0 : k - 1;
    return (std::min)(k, m_poly.size() - 1);
  }

  Kind m_kind;
  Vec2 m_center{{ 0, 0 }}, m_origin{{ 0, 0 }};
  double m_radius = 0, m_side = 0, m_length = 0;
  std::vector<Vec2> m_poly;
  std::vector<double> m_cumul;
  std::vector<double> m_s;
  std::vector<bool> m_fixed;
};

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
