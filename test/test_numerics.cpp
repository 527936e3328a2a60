// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The internal pieces of the Discrete Lie Flow, tested on their own with
// light includes (no CGAL mesh types): critical steps (quadratic and cubic,
// against brute force), exact certification (a case where rounding alone
// accepts a folded triangle), the boundary curve, Delaunay flips, the
// distortion metrics, the gradient of the barrier energy (finite differences)
// and the sign of the paper's Poisson step.

#include <gtest/gtest.h>

#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/disk/planar_certified_flow.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/disk/planar_gauss_newton.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/disk/planar_paper_flow.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/flow/coarse_to_fine_levels.h>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

// The tests compile in unity batches (DLF_UNITY_BUILD): each file keeps its
// names in a namespace of its own.
namespace dlf_test_numerics {

namespace D = CGAL::Surface_mesh_parameterization::internal::dlf;
namespace SMP = CGAL::Surface_mesh_parameterization;

namespace {

using D::Vec2;
using D::Vec3;
using D::Face;
typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_2 EP;
const double inf = std::numeric_limits<double>::infinity();

// ---------------------------------------------------------------------------
// Brute force: the first λ in (0, L] where a sign predicate stops being
// positive, by a uniform scan and bisection. +∞ if none on the scan.
// ---------------------------------------------------------------------------

template <class Positive>
double first_nonpositive(Positive positive, double L, int samples = 4000)
{
  double lo = 0;
  for(int k = 1; k <= samples; ++k) {
    const double x = L * k / samples;
    if(!positive(x)) {
      double hi = x;
      for(int it = 0; it < 200 && hi - lo > 4 * std::numeric_limits<double>::epsilon() * hi; ++it) {
        const double mid = 0.5 * (lo + hi);
        if(positive(mid)) lo = mid; else hi = mid;
      }
      return hi;
    }
    lo = x;
  }
  return inf;
}

long double poly(const std::vector<long double>& c, long double x) // c[0] x^n + ... + c[n]
{
  long double r = 0;
  for(long double a : c) r = r * x + a;
  return r;
}

std::vector<long double> expand(const std::vector<long double>& roots, long double lead = 1) // lead·Π(x − r)
{
  std::vector<long double> c(1, lead);
  for(long double r : roots) {
    std::vector<long double> n(c.size() + 1, 0.L);
    for(std::size_t i = 0; i < c.size(); ++i) { n[i] += c[i]; n[i + 1] -= c[i] * r; }
    c = n;
  }
  return c;
}

// ---------------------------------------------------------------------------
// Quadratic critical roots
// ---------------------------------------------------------------------------

TEST(Critical_step, QuadraticLinearAndNearlyLinear)
{
  EXPECT_EQ(D::smallest_positive_root(0, -2, 1), 0.5);
  EXPECT_EQ(D::smallest_positive_root(0, 2, 1), inf);
  EXPECT_EQ(D::smallest_positive_root(0, 0, 1), inf);
  // a ≈ 0: the root near 1 must not be lost to cancellation (the textbook
  // formula (−b + sqrt(b² − 4ac)) / 2a gives 0 or garbage here).
  for(double a : { 1e-30, -1e-30, 1e-20, -1e-20, 1e-17, -1e-17, 1e-12 }) {
    const double r = D::smallest_positive_root(a, -1, 1);
    const long double exact = 2.L / (1 + std::sqrt(1 - 4.L * a)); // the root near 1
    EXPECT_NEAR(r, double(exact), 1e-15) << "a = " << a;
  }
  // a ≈ 0, the far root is the positive one: −1e-17 λ² + λ + 1 has roots ≈ −1 and ≈ 1e17.
  EXPECT_NEAR(D::smallest_positive_root(-1e-17, 1, 1), 1e17, 1e17 * 1e-12);
  EXPECT_EQ(D::smallest_positive_root(1e-17, 1, 1), inf); // roots ≈ −1 and ≈ −1e17
}

TEST(Critical_step, QuadraticDoubleRoots)
{
  EXPECT_EQ(D::smallest_positive_root(1, -4, 4), 2.);      // (λ − 2)²
  EXPECT_EQ(D::smallest_positive_root(4, -4, 1), 0.5);     // (2λ − 1)²
  EXPECT_EQ(D::smallest_positive_root(1, 2, 1), inf);      // (λ + 1)²
  // Near-double: (λ − 1)(λ − 1 − ε). The first root is found to ~sqrt(eps),
  // and never beyond the true first root by more than that.
  for(double eps : { 1e-4, 1e-6, 1e-8 }) {
    const double r = D::smallest_positive_root(1, -(2 + eps), 1 + eps);
    EXPECT_NEAR(r, 1., 3e-8) << "eps = " << eps;
  }
}

TEST(Critical_step, QuadraticNoPositiveRoot)
{
  EXPECT_EQ(D::smallest_positive_root(1, 3, 2), inf);  // −1, −2
  EXPECT_EQ(D::smallest_positive_root(1, 0, 1), inf);  // ±i
  EXPECT_EQ(D::smallest_positive_root(1, 1, 1), inf);  // complex
  EXPECT_EQ(D::smallest_positive_root(1, -1, 1), inf); // complex with positive real part
  EXPECT_EQ(D::smallest_positive_root(-1, 0, 4), 2.);  // concave: ±2
  EXPECT_EQ(D::smallest_positive_root(1, -5, 6), 2.);  // 2, 3
}

TEST(Critical_step, QuadraticRootAtZero)
{
  // A root at exactly λ = 0 is not positive (the triangle is already flat).
  EXPECT_EQ(D::smallest_positive_root(1, -1, 0), 1.);  // 0, 1
  EXPECT_EQ(D::smallest_positive_root(1, 1, 0), inf);  // 0, −1
  EXPECT_EQ(D::smallest_positive_root(0, 1, 0), inf);
  EXPECT_EQ(D::smallest_positive_root(1, 0, 0), inf);  // double root at 0
}

TEST(Critical_step, PlanarTriangleExamples)
{
  const Vec2 p0{{ 0, 0 }}, p1{{ 1, 0 }}, p2{{ 0, 1 }}, z{{ 0, 0 }};
  // The apex moves straight down: flat at λ = 1.
  EXPECT_EQ(D::critical_step_2(p0, p1, p2, z, z, Vec2{{ 0, -1 }}), 1.);
  // The apex moves along the base: never flat.
  EXPECT_EQ(D::critical_step_2(p0, p1, p2, z, z, Vec2{{ 1, 0 }}), inf);
  // A uniform translation and a rotation never flatten a triangle.
  EXPECT_EQ(D::critical_step_2(p0, p1, p2, Vec2{{ 3, 1 }}, Vec2{{ 3, 1 }}, Vec2{{ 3, 1 }}), inf);
  // A uniform contraction towards the origin: p + λ(−p) is flat at λ = 1 (a double root).
  EXPECT_EQ(D::critical_step_2(p0, p1, p2, z, Vec2{{ -1, 0 }}, Vec2{{ 0, -1 }}), 1.);
}

TEST(Critical_step, PlanarRandomAgainstBruteForce)
{
  std::mt19937_64 gen(12345);
  std::uniform_real_distribution<double> U(-1, 1), E(-6, 6);
  int compared = 0, none = 0;
  for(int trial = 0; trial < 3000; ++trial) {
    const double s = std::pow(10., E(gen)), t = s * std::pow(10., 0.5 * E(gen) / 6); // position and velocity scales
    Vec2 p[3], d[3];
    for(int k = 0; k < 3; ++k) { p[k] = {{ s * U(gen), s * U(gen) }}; d[k] = {{ t * U(gen), t * U(gen) }}; }
    if(D::exact_orientation_2(p[0], p[1], p[2]) == CGAL::NEGATIVE) std::swap(p[1], p[2]), std::swap(d[1], d[2]);
    if(D::exact_orientation_2(p[0], p[1], p[2]) != CGAL::POSITIVE) continue;
    const double r = D::critical_step_2(p[0], p[1], p[2], d[0], d[1], d[2]);
    // Brute force: the exact sign of the moved triangle (coordinates in long double).
    auto positive = [&](double x) {
      long double q[3][2];
      for(int k = 0; k < 3; ++k) for(int j = 0; j < 2; ++j) q[k][j] = p[k][j] + (long double)x * d[k][j];
      const long double a2 = (q[1][0] - q[0][0]) * (q[2][1] - q[0][1]) - (q[1][1] - q[0][1]) * (q[2][0] - q[0][0]);
      return a2 > 0;
    };
    const double L = 50 * s / t;
    const double b = first_nonpositive(positive, L);
    // Skip near-tangent roots, where the brute-force scan can step over a dip.
    const std::array<double, 3> q = D::doubled_area_quadratic(p[0], p[1], p[2], d[0], d[1], d[2]);
    if(std::isfinite(b)) {
      const double slope = std::fabs(2 * q[0] * b + q[1]), size = std::fabs(q[0]) * b + std::fabs(q[1]);
      if(slope < 1e-3 * size) continue;
      EXPECT_NEAR(r, b, 1e-9 * b) << "trial " << trial;
      ++compared;
    } else {
      // No sign change before L: the root, if any, lies beyond L, or is a tangency.
      if(r <= L) {
        const double slope = std::fabs(2 * q[0] * r + q[1]), size = std::fabs(q[0]) * r + std::fabs(q[1]);
        EXPECT_LT(slope, 1e-3 * size) << "trial " << trial << ": a root at " << r << " the scan does not see";
      }
      ++none;
    }
  }
  EXPECT_GT(compared, 1000);
  EXPECT_GT(none, 100);
}

// ---------------------------------------------------------------------------
// Cubic critical roots (the sphere)
// ---------------------------------------------------------------------------

double cubic_root(const std::vector<long double>& c)
{
  return D::smallest_positive_root(double(c[0]), double(c[1]), double(c[2]), double(c[3]));
}

TEST(Critical_step, CubicExamples)
{
  EXPECT_NEAR(cubic_root(expand({ 1, 2, 3 })), 1., 1e-14);
  EXPECT_NEAR(cubic_root(expand({ 3, 2, 1 }, -2)), 1., 1e-14);           // a < 0
  EXPECT_NEAR(cubic_root(expand({ -1, 4, 7 })), 4., 4e-14);
  EXPECT_EQ(cubic_root(expand({ -1, -2, -3 })), inf);                    // no positive root
  EXPECT_NEAR(D::smallest_positive_root(1, -5, 1, -5), 5., 5e-14);     // (λ − 5)(λ² + 1)
  EXPECT_EQ(D::smallest_positive_root(1, 5, 1, 5), inf);                 // (λ + 5)(λ² + 1)
  EXPECT_NEAR(cubic_root(expand({ 0, 1, 2 })), 1., 1e-14);               // a root at 0 is not positive
  // a = 0: the quadratic (λ − 1)(λ − 2).
  EXPECT_EQ(D::smallest_positive_root(0, 1, -3, 2), 1.);
  EXPECT_EQ(D::smallest_positive_root(0, 0, -2, 1), 0.5);
  // |a| tiny against the rest: ≈ the quadratic's root.
  EXPECT_NEAR(D::smallest_positive_root(1e-18, 1, -5, 6), 2., 1e-12);
  EXPECT_NEAR(D::smallest_positive_root(-1e-18, 1, -5, 6), 2., 1e-12);
}

TEST(Critical_step, CubicMultipleAndNearMultipleRoots)
{
  EXPECT_NEAR(D::smallest_positive_root(1, 0, -3, 2), 1., 1e-12);   // (λ − 1)²(λ + 2)
  EXPECT_NEAR(D::smallest_positive_root(1, -3, 3, -1), 1., 1e-5);   // (λ − 1)³: cube-root conditioning
  EXPECT_NEAR(cubic_root(expand({ 2, 2, 5 })), 2., 1e-7);            // double root first
  for(long double eps : { 1e-3L, 1e-5L, 1e-7L }) {
    const std::vector<long double> c = expand({ 1, 1 + eps, -2 });
    const double r = cubic_root(c);
    EXPECT_NEAR(r, 1., 1e-7) << "eps = " << double(eps);
    EXPECT_LE(r, 1 + double(eps)) << "eps = " << double(eps); // never beyond the pair
  }
}

TEST(Critical_step, CubicRandomAgainstBruteForce)
{
  std::mt19937_64 gen(777);
  std::uniform_real_distribution<double> U(-1, 1), P(0.01, 1);
  int compared = 0;
  for(int trial = 0; trial < 3000; ++trial) {
    const std::vector<long double> c = { U(gen), U(gen), U(gen), P(gen) }; // positive at 0
    const double r = cubic_root(c);
    auto positive = [&](double x) { return poly(c, x) > 0; };
    const double b = first_nonpositive(positive, 20.);
    if(std::isfinite(b)) {
      const long double slope = std::fabs(3 * c[0] * b * b + 2 * c[1] * b + c[2]);
      if(slope < 1e-3L) continue; // near-tangent
      EXPECT_NEAR(r, b, 1e-9 * b) << "trial " << trial;
      ++compared;
    } else if(r <= 20.) {
      const long double slope = std::fabs(3 * c[0] * r * r + 2 * c[1] * r + c[2]);
      EXPECT_LT(double(slope), 1e-3) << "trial " << trial << ": a root at " << r << " the scan does not see";
    }
  }
  EXPECT_GT(compared, 1000);
}

Vec3 unit3(const Vec3& v) { const double l = std::sqrt(D::dot(v, v)); return {{ v[0] / l, v[1] / l, v[2] / l }}; }
long double det3(const long double a[3], const long double b[3], const long double c[3])
{
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
}

TEST(Critical_step, SphereCubicMatchesDeterminantAndBruteForce)
{
  std::mt19937_64 gen(99);
  std::uniform_real_distribution<double> U(-1, 1);
  int compared = 0;
  for(int trial = 0; trial < 2000; ++trial) {
    const Vec3 c = unit3({{ U(gen), U(gen), U(gen) }});
    const double size = std::pow(10., -3 * (U(gen) + 1)); // triangles from 1 down to 1e-6
    Vec3 p[3], t[3];
    for(int k = 0; k < 3; ++k) {
      p[k] = unit3({{ c[0] + size * U(gen), c[1] + size * U(gen), c[2] + size * U(gen) }});
      const Vec3 g{{ size * U(gen), size * U(gen), size * U(gen) }};
      const double gp = D::dot(g, p[k]);
      t[k] = {{ g[0] - gp * p[k][0], g[1] - gp * p[k][1], g[2] - gp * p[k][2] }}; // tangent
    }
    if(D::exact_orientation_sphere(p[0], p[1], p[2]) == CGAL::NEGATIVE) std::swap(p[1], p[2]), std::swap(t[1], t[2]);
    if(D::exact_orientation_sphere(p[0], p[1], p[2]) != CGAL::POSITIVE) continue;
    const std::array<double, 4> k = D::orientation_cubic(p[0], p[1], p[2], t[0], t[1], t[2]);
    auto det_at = [&](long double x) { // det[q0, q1 − q0, q2 − q0], q = p + x t, in long double
      long double q[3][3];
      for(int j = 0; j < 3; ++j) {
        q[0][j] = p[0][j] + x * t[0][j];
        for(int i = 1; i < 3; ++i) q[i][j] = ((long double)p[i][j] - p[0][j]) + x * ((long double)t[i][j] - t[0][j]);
      }
      return det3(q[0], q[1], q[2]);
    };
    for(double x : { 0.25, 1., 3. }) {
      const long double exact = det_at(x);
      const long double scale = std::fabs(det_at(0)) + std::pow(size, 3) * (1 + x * x * x);
      const long double mine = ((k[0] * (long double)x + k[1]) * x + k[2]) * x + k[3];
      EXPECT_LE(std::fabs(mine - exact), 1e-9L * scale) << "trial " << trial << " at " << x;
    }
    const double r = D::critical_step_sphere(p[0], p[1], p[2], t[0], t[1], t[2]);
    const double b = first_nonpositive([&](double x) { return det_at(x) > 0; }, 20.);
    if(std::isfinite(b)) {
      const long double h = 1e-6L * b, slope = std::fabs(det_at(b + h) - det_at(b - h)) / (2 * h);
      const long double scale = std::fabs(det_at(0)) / b;
      if(slope < 1e-3L * scale) continue;
      EXPECT_NEAR(r, b, 1e-8 * b) << "trial " << trial;
      ++compared;
    }
  }
  EXPECT_GT(compared, 300);
}

// ---------------------------------------------------------------------------
// Exact certification
// ---------------------------------------------------------------------------

// A near-collinear triangle (1e-17 relative) whose doubled area, computed in
// doubles the way the flow computes areas, is positive while the exact
// predicate says the triangle is inverted: rounding alone would accept it.
TEST(Certification, RoundingAcceptsAFoldTheExactPredicateRefuses)
{
  bool found = false;
  Vec2 a, b{{ 12, 12 }}, c{{ 24, 24 }};
  double x = 0.5;
  for(int i = 0; i < 256 && !found; ++i, x = std::nextafter(x, 1.)) {
    double y = 0.5;
    for(int j = 0; j < 256 && !found; ++j, y = std::nextafter(y, 1.)) {
      a = {{ x, y }};
      if(D::signed_area_2(a, b, c) > 0 && D::exact_orientation_2(a, b, c) == CGAL::NEGATIVE) found = true;
    }
  }
  ASSERT_TRUE(found) << "no wrong-sign case in the search grid";
  // The points are collinear up to ~1e-15 relative (a few hundred ulps of 0.5).
  EXPECT_LT(std::fabs(a[0] - a[1]), 1e-13);
  EXPECT_LT(std::fabs(D::signed_area_2(a, b, c)), 1e-13 * 24 * 24);
  // Doubles say positive, in every form the flow uses...
  EXPECT_GT(D::signed_area_2(a, b, c), 0);
  std::vector<double> u;
  const std::vector<Vec2> pts = { a, b, c };
  const std::vector<Face> faces = { Face{{ 0, 1, 2 }} };
  D::signed_areas_2(pts, faces, u);
  EXPECT_GT(u[0], 0);
  EXPECT_TRUE(std::isfinite(D::d_area_of(u, std::vector<double>(1, 1.)))); // the energy accepts it
  // ... the exact predicate (CGAL's, on the same doubles) does not.
  EXPECT_EQ(CGAL::orientation(EP(a[0], a[1]), EP(b[0], b[1]), EP(c[0], c[1])), CGAL::NEGATIVE);
  const D::Orientation_count oc = D::count_orientations_2(pts, faces);
  EXPECT_EQ(oc.inverted, 1u);
  EXPECT_FALSE(oc.all_positive());
  EXPECT_EQ(oc.first_bad, 0);
}

TEST(Certification, CountsInvertedAndDegenerateFaces)
{
  const std::vector<Vec2> uv = { {{ 0, 0 }}, {{ 1, 0 }}, {{ 0, 1 }}, {{ 1, 1 }}, {{ 2, 2 }} };
  const std::vector<Face> faces = { Face{{ 0, 1, 2 }}, Face{{ 1, 3, 2 }}, Face{{ 0, 2, 1 }}, Face{{ 0, 3, 4 }}, Face{{ 2, 3, 1 }} };
  const D::Orientation_count oc = D::count_orientations_2(uv, faces);
  EXPECT_EQ(oc.inverted, 2u);   // faces 2 and 4
  EXPECT_EQ(oc.degenerate, 1u); // face 3: collinear
  EXPECT_EQ(oc.first_bad, 2);
  EXPECT_EQ(D::count_orientations_2(uv, faces, true).first_bad, 2);
  // Sphere: seen from the centre.
  const Vec3 p{{ 1, 0, 0 }}, q{{ 0, 1, 0 }}, r{{ 0, 0, 1 }};
  EXPECT_EQ(D::exact_orientation_sphere(p, q, r), CGAL::POSITIVE);
  EXPECT_EQ(D::exact_orientation_sphere(p, r, q), CGAL::NEGATIVE);
  EXPECT_EQ(D::exact_orientation_sphere(p, q, Vec3{{ -1, 0, 0 }}), CGAL::ZERO); // a great circle through p, q, −p
}

// ---------------------------------------------------------------------------
// Boundary curves
// ---------------------------------------------------------------------------

std::vector<Vec2> circle_points(const std::vector<double>& angles)
{
  std::vector<Vec2> p;
  for(double a : angles) p.push_back({{ 0.5 + 0.5 * std::cos(a), 0.5 + 0.5 * std::sin(a) }});
  return p;
}

TEST(Boundary_curve, CircleKeepsVerticesOnTheCircle)
{
  std::vector<double> angles;
  for(int k = 0; k < 40; ++k) angles.push_back(2 * M_PI * k / 40);
  const std::vector<Vec2> pts = circle_points(angles);
  D::Boundary_curve c(pts, SMP::Discrete_lie_flow_border::AUTOMATIC);
  EXPECT_EQ(c.kind(), SMP::Discrete_lie_flow_border::CIRCLE);
  for(std::size_t i = 0; i < pts.size(); ++i) {
    Vec2 q;
    ASSERT_TRUE(c.slide(i, 0.013, q));
    EXPECT_NEAR(std::hypot(q[0] - 0.5, q[1] - 0.5), 0.5, 1e-15);
    const Vec2 t = c.tangent(i);
    EXPECT_NEAR(t[0] * (pts[i][0] - 0.5) + t[1] * (pts[i][1] - 0.5), 0, 1e-15); // tangent ⟂ radius
    EXPECT_GT(t[0] * -(pts[i][1] - 0.5) + t[1] * (pts[i][0] - 0.5), 0);        // counter-clockwise
  }
}

// Vertices spaced unevenly on a circle (CGAL's arc-length circle border) are
// not centred on their centroid: the circle must still be detected and kept.
TEST(Boundary_curve, UnevenlySpacedCircleIsDetectedAndReproduced)
{
  const std::vector<Vec2> pts = circle_points({ 0., 0.3, 2.0, 4.0, 5.5 });
  D::Boundary_curve c(pts, SMP::Discrete_lie_flow_border::AUTOMATIC);
  EXPECT_EQ(c.kind(), SMP::Discrete_lie_flow_border::CIRCLE) << "an unevenly spaced circle is not detected";
  D::Boundary_curve forced(pts, SMP::Discrete_lie_flow_border::CIRCLE);
  for(std::size_t i = 0; i < pts.size(); ++i) {
    Vec2 q;
    ASSERT_TRUE(forced.slide(i, 0., q));
    EXPECT_NEAR(q[0], pts[i][0], 1e-14) << "vertex " << i << " is moved off its place on the circle";
    EXPECT_NEAR(q[1], pts[i][1], 1e-14) << "vertex " << i << " is moved off its place on the circle";
  }
}

TEST(Boundary_curve, SquareCornersFixedAndSidesKept)
{
  // 12 points on the unit square, corners included, counter-clockwise.
  std::vector<Vec2> pts;
  for(int k = 0; k < 3; ++k) pts.push_back({{ k / 3., 0 }});
  for(int k = 0; k < 3; ++k) pts.push_back({{ 1, k / 3. }});
  for(int k = 0; k < 3; ++k) pts.push_back({{ 1 - k / 3., 1 }});
  for(int k = 0; k < 3; ++k) pts.push_back({{ 0, 1 - k / 3. }});
  D::Boundary_curve c(pts, SMP::Discrete_lie_flow_border::AUTOMATIC);
  ASSERT_EQ(c.kind(), SMP::Discrete_lie_flow_border::SQUARE);
  for(std::size_t i = 0; i < pts.size(); ++i) {
    EXPECT_EQ(c.is_fixed(i), i % 3 == 0) << i;
    Vec2 q;
    if(i % 3 == 0) { EXPECT_FALSE(c.slide(i, 0.1, q)); continue; }
    ASSERT_TRUE(c.slide(i, 0.1, q));
    const int side = int(i / 3);
    if(side == 0) EXPECT_EQ(q[1], 0.); else if(side == 1) EXPECT_EQ(q[0], 1.);
    else if(side == 2) EXPECT_EQ(q[1], 1.); else EXPECT_EQ(q[0], 0.);
    EXPECT_FALSE(c.slide(i, 0.7, q)) << "vertex " << i << " slid past a corner";
    EXPECT_FALSE(c.slide(i, -0.7, q)) << "vertex " << i << " slid past a corner";
  }
}

// A square border with only its four corners also fits a circle: it must be
// taken as a square (corners fixed).
TEST(Boundary_curve, FourCornerSquareIsASquare)
{
  const std::vector<Vec2> pts = { {{ 0, 0 }}, {{ 1, 0 }}, {{ 1, 1 }}, {{ 0, 1 }} };
  D::Boundary_curve c(pts, SMP::Discrete_lie_flow_border::AUTOMATIC);
  EXPECT_EQ(c.kind(), SMP::Discrete_lie_flow_border::SQUARE);
}

TEST(Boundary_curve, FreePolylineKeepsVerticesOnIt)
{
  const std::vector<Vec2> pts = { {{ 0, 0 }}, {{ 2, 0 }}, {{ 2, 1 }}, {{ 1, 0.5 }}, {{ 0, 1 }} }; // non-convex
  D::Boundary_curve c(pts, SMP::Discrete_lie_flow_border::AUTOMATIC);
  ASSERT_EQ(c.kind(), SMP::Discrete_lie_flow_border::FREE);
  for(std::size_t i = 0; i < pts.size(); ++i)
    for(double ds : { -0.3, 0.0, 0.25, 0.6 }) {
      Vec2 q;
      ASSERT_TRUE(c.slide(i, ds, q));
      double best = inf; // distance to the polyline
      for(std::size_t k = 0; k < pts.size(); ++k) {
        const Vec2 &a = pts[k], &b = pts[(k + 1) % pts.size()];
        const double vx = b[0] - a[0], vy = b[1] - a[1];
        const double t = std::max(0., std::min(1., ((q[0] - a[0]) * vx + (q[1] - a[1]) * vy) / (vx * vx + vy * vy)));
        best = std::min(best, std::hypot(q[0] - a[0] - t * vx, q[1] - a[1] - t * vy));
      }
      EXPECT_LE(best, 1e-15) << "vertex " << i << " slid by " << ds << " left the polyline";
      if(ds == 0) { EXPECT_EQ(q[0], pts[i][0]); EXPECT_EQ(q[1], pts[i][1]); }
    }
}

// ---------------------------------------------------------------------------
// Delaunay flips
// ---------------------------------------------------------------------------

TEST(Edge_flips, LawsonFlipsReachTheDelaunayTriangulation)
{
  std::mt19937_64 gen(5);
  std::uniform_real_distribution<double> J(-0.2, 0.2);
  const int m = 12; // (m+1)² points, interior ones jittered, border straight
  std::vector<Vec2> uv;
  for(int j = 0; j <= m; ++j)
    for(int i = 0; i <= m; ++i) {
      const bool border = i == 0 || j == 0 || i == m || j == m;
      uv.push_back({{ i + (border ? 0 : J(gen)), j + (border ? 0 : J(gen)) }});
    }
  std::vector<Face> faces;
  auto id = [m](int i, int j) { return j * (m + 1) + i; };
  for(int j = 0; j < m; ++j)
    for(int i = 0; i < m; ++i) { // alternate diagonals, many of them non-Delaunay
      if((i + j) % 2) { faces.push_back({{ id(i, j), id(i + 1, j), id(i + 1, j + 1) }}); faces.push_back({{ id(i, j), id(i + 1, j + 1), id(i, j + 1) }}); }
      else { faces.push_back({{ id(i, j), id(i + 1, j), id(i, j + 1) }}); faces.push_back({{ id(i + 1, j), id(i + 1, j + 1), id(i, j + 1) }}); }
    }
  ASSERT_TRUE(D::count_orientations_2(uv, faces).all_positive());
  D::Flip_triangulation tri(faces);
  std::set<int> changed;
  const std::size_t flips = tri.make_delaunay(uv, [&](int f) { changed.insert(f); }, 100000);
  EXPECT_GT(flips, 0u);
  EXPECT_FALSE(changed.empty());
  // Positive, same count, every directed edge once, interior edges paired.
  EXPECT_EQ(tri.faces.size(), faces.size());
  EXPECT_TRUE(D::count_orientations_2(uv, tri.faces).all_positive());
  std::map<std::pair<int, int>, int> opp; // directed edge -> opposite corner
  for(const Face& f : tri.faces)
    for(int k = 0; k < 3; ++k) {
      const auto e = std::make_pair(f[(k + 1) % 3], f[(k + 2) % 3]);
      EXPECT_EQ(opp.count(e), 0u);
      opp[e] = f[k];
    }
  // Locally Delaunay everywhere (exact), hence Delaunay (the domain is convex).
  std::size_t interior = 0, bad = 0;
  for(const auto& e : opp) {
    const auto it = opp.find(std::make_pair(e.first.second, e.first.first));
    if(it == opp.end() || e.first.first > e.first.second) continue;
    ++interior;
    const Vec2 &a = uv[e.second], &b = uv[e.first.first], &c = uv[e.first.second], &d = uv[it->second];
    if(CGAL::side_of_oriented_circle(EP(a[0], a[1]), EP(b[0], b[1]), EP(c[0], c[1]), EP(d[0], d[1])) == CGAL::ON_POSITIVE_SIDE) ++bad;
  }
  EXPECT_EQ(interior, std::size_t(3 * m * m - 2 * m));
  EXPECT_EQ(bad, 0u);
  // The twins agree with the faces.
  for(std::size_t h = 0; h < tri.twin.size(); ++h) {
    const int o = tri.twin[h];
    if(o < 0) continue;
    const Face &f = tri.faces[h / 3], &g = tri.faces[std::size_t(o) / 3];
    EXPECT_EQ(f[(h % 3 + 1) % 3], g[(o % 3 + 2) % 3]);
    EXPECT_EQ(f[(h % 3 + 2) % 3], g[(o % 3 + 1) % 3]);
  }
}

// ---------------------------------------------------------------------------
// Distortion metrics
// ---------------------------------------------------------------------------

TEST(Distortion, IsometryStretchAndInversion)
{
  // A flat grid mapped onto itself.
  const int m = 4;
  std::vector<Vec2> uv;
  std::vector<Vec3> xyz;
  std::vector<Face> faces;
  for(int j = 0; j <= m; ++j) for(int i = 0; i <= m; ++i) { uv.push_back({{ double(i), double(j) }}); xyz.push_back({{ double(i), double(j), 0 }}); }
  for(int j = 0; j < m; ++j) for(int i = 0; i < m; ++i) {
    const int a = j * (m + 1) + i;
    faces.push_back({{ a, a + 1, a + m + 2 }});
    faces.push_back({{ a, a + m + 2, a + m + 1 }});
  }
  const double F = double(faces.size());
  D::Distortion_metrics d = D::planar_distortion(xyz, uv, faces);
  EXPECT_NEAR(d.d_area, 2, 1e-14);
  EXPECT_NEAR(d.arap, 0, 1e-14);
  EXPECT_NEAR(d.symmetric_dirichlet, 4 * F, 1e-12);
  EXPECT_NEAR(d.log_area_max_abs, 0, 1e-14);
  EXPECT_EQ(d.inverted_faces, 0u);
  EXPECT_EQ(d.degenerate_faces, 0u);
  EXPECT_NEAR(d.min_angle_degrees, 45, 1e-12);
  // Uniform scaling of the domain changes nothing.
  std::vector<Vec2> big = uv;
  for(Vec2& p : big) { p[0] *= 3; p[1] *= 3; }
  EXPECT_NEAR(D::planar_distortion(xyz, big, faces).arap, 0, 1e-13);
  // An anisotropic stretch (2, 1): after the uniform area scaling σ = (√2, 1/√2).
  std::vector<Vec2> st = uv;
  for(Vec2& p : st) p[0] *= 2;
  d = D::planar_distortion(xyz, st, faces);
  EXPECT_NEAR(d.d_area, 2, 1e-13);
  EXPECT_NEAR(d.arap, std::pow(std::sqrt(2.) - 1, 2) + std::pow(1 / std::sqrt(2.) - 1, 2), 1e-13);
  EXPECT_NEAR(d.symmetric_dirichlet, 5 * F, 1e-11);
  // Area distortion: one half of the domain shrunk (x ↦ x/2 left of the middle).
  std::vector<Vec2> sq = uv;
  for(Vec2& p : sq) if(p[0] < m / 2.) p[0] = p[0] / 2; else p[0] = p[0] - m / 4.;
  d = D::planar_distortion(xyz, sq, faces);
  // Left half: area ratio 1/2, right half: 1, before scaling; scaled by 4/3: r = 2/3 and 4/3.
  EXPECT_NEAR(d.d_area, 0.5 * (2. / 3 + 1.5) + 0.5 * (4. / 3 + 0.75), 1e-13);
  // One inverted face.
  std::vector<Vec2> fold = uv;
  fold[std::size_t(1 * (m + 1) + 1)] = {{ 2.5, 2.5 }}; // vertex (1,1) pushed across (2,2)
  d = D::planar_distortion(xyz, fold, faces);
  EXPECT_EQ(d.inverted_faces, std::size_t(D::count_orientations_2(fold, faces).inverted));
  EXPECT_GT(d.inverted_faces, 0u);
}

// ---------------------------------------------------------------------------
// A real mesh (nefertiti.off) with a Tutte map onto the unit circle
// ---------------------------------------------------------------------------

struct Tutte_disk
{
  D::Disk_problem P;
  std::vector<Vec2> uv;
};

bool read_off(const std::string& path, std::vector<Vec3>& xyz, std::vector<Face>& faces)
{
  std::ifstream in(path);
  if(!in) return false;
  std::stringstream clean;
  std::string line;
  while(std::getline(in, line)) { const std::size_t c = line.find('#'); clean << line.substr(0, c) << '\n'; }
  std::string head;
  clean >> head;
  if(head != "OFF") return false;
  std::size_t nv, nf, ne;
  clean >> nv >> nf >> ne;
  xyz.resize(nv);
  for(Vec3& p : xyz) clean >> p[0] >> p[1] >> p[2];
  for(std::size_t f = 0; f < nf; ++f) {
    int k; Face t;
    clean >> k >> t[0] >> t[1] >> t[2];
    if(k != 3) return false;
    faces.push_back(t);
  }
  return bool(clean);
}

/// Uniform-weight Tutte embedding, border evenly on the unit circle, faces
/// oriented positively, border loop counter-clockwise.
bool tutte_disk(const std::string& name, Tutte_disk& T)
{
  D::Disk_problem& P = T.P;
  if(!read_off(std::string(DLF_DATA_DIR) + "/meshes/" + name + ".off", P.xyz, P.faces)) return false;
  const std::size_t n = P.xyz.size();
  std::map<std::pair<int, int>, int> directed;
  for(const Face& f : P.faces) for(int k = 0; k < 3; ++k) directed[std::make_pair(f[k], f[(k + 1) % 3])] = 1;
  std::map<int, int> next; // border: b -> a for directed edges a->b without twin
  for(const auto& e : directed)
    if(!directed.count(std::make_pair(e.first.second, e.first.first))) next[e.first.second] = e.first.first;
  if(next.empty()) return false;
  std::vector<int> loop(1, next.begin()->first);
  while(next.at(loop.back()) != loop.front()) loop.push_back(next.at(loop.back()));
  if(loop.size() != next.size()) return false;
  T.uv.assign(n, Vec2{{ 0, 0 }});
  std::vector<int> bpos(n, -1);
  for(std::size_t k = 0; k < loop.size(); ++k) {
    bpos[std::size_t(loop[k])] = int(k);
    const double a = 2 * M_PI * double(k) / double(loop.size());
    T.uv[std::size_t(loop[k])] = {{ std::cos(a), std::sin(a) }};
  }
  std::vector<std::set<int> > nb(n);
  for(const Face& f : P.faces) for(int k = 0; k < 3; ++k) { nb[f[k]].insert(f[(k + 1) % 3]); nb[f[k]].insert(f[(k + 2) % 3]); }
  std::vector<Eigen::Triplet<double> > trip;
  Eigen::VectorXd bx = Eigen::VectorXd::Zero(Eigen::Index(n)), by = bx;
  for(std::size_t i = 0; i < n; ++i) {
    if(bpos[i] >= 0) { trip.emplace_back(int(i), int(i), 1.); bx[Eigen::Index(i)] = T.uv[i][0]; by[Eigen::Index(i)] = T.uv[i][1]; continue; }
    trip.emplace_back(int(i), int(i), double(nb[i].size()));
    for(int j : nb[i]) trip.emplace_back(int(i), j, -1.);
  }
  D::Sparse_matrix A{ Eigen::Index(n), Eigen::Index(n) };
  A.setFromTriplets(trip.begin(), trip.end());
  Eigen::SparseLU<D::Sparse_matrix> lu(A);
  if(lu.info() != Eigen::Success) return false;
  const Eigen::VectorXd x = lu.solve(bx), y = lu.solve(by);
  for(std::size_t i = 0; i < n; ++i) T.uv[i] = {{ x[Eigen::Index(i)], y[Eigen::Index(i)] }};
  D::Orientation_count oc = D::count_orientations_2(T.uv, P.faces);
  if(oc.inverted * 2 > P.faces.size()) { for(Face& f : P.faces) std::swap(f[1], f[2]); oc = D::count_orientations_2(T.uv, P.faces); }
  if(!oc.all_positive()) return false;
  double twice = 0;
  for(std::size_t k = 0; k < loop.size(); ++k) {
    const Vec2 &a = T.uv[std::size_t(loop[k])], &b = T.uv[std::size_t(loop[(k + 1) % loop.size()])];
    twice += a[0] * b[1] - a[1] * b[0];
  }
  if(twice < 0) std::reverse(loop.begin(), loop.end());
  P.boundary = loop;
  P.target.resize(P.faces.size());
  for(std::size_t f = 0; f < P.faces.size(); ++f)
    P.target[f] = D::triangle_area_3(P.xyz[P.faces[f][0]], P.xyz[P.faces[f][1]], P.xyz[P.faces[f][2]]);
  return true;
}

long double d_area_mine(const std::vector<double>& u, const std::vector<double>& A)
{
  long double U = 0, T = 0, e = 0;
  for(std::size_t f = 0; f < u.size(); ++f) { U += u[f]; T += A[f]; }
  for(std::size_t f = 0; f < u.size(); ++f) { const long double w = A[f] / T, r = (u[f] / U) / w; e += w * (r + 1 / r); }
  return e;
}

/// Checks ∂energy/∂position (an energy of the signed areas) against central
/// finite differences at every vertex of `T`: within 1e-6 of its largest entry.
template <class Energy>
void expect_gradient_matches_finite_differences(const Tutte_disk& T, const Energy& energy)
{
  const D::Disk_problem& P = T.P;
  std::vector<double> u, dE, ux;
  std::vector<Vec2> g;
  D::signed_areas_2(T.uv, P.faces, u);
  energy.derivatives(u, dE);
  D::planar_position_gradient(T.uv, P.faces, dE, g);
  double gmax = 0;
  for(const Vec2& v : g) gmax = std::max(gmax, std::max(std::fabs(v[0]), std::fabs(v[1])));
  double mean_edge = 0;
  for(const Face& f : P.faces) mean_edge += std::hypot(T.uv[f[1]][0] - T.uv[f[0]][0], T.uv[f[1]][1] - T.uv[f[0]][1]);
  mean_edge /= double(P.faces.size());
  const double h = 1e-5 * mean_edge;
  double worst = 0;
  std::vector<Vec2> x = T.uv;
  for(std::size_t v = 0; v < x.size(); ++v)
    for(int c = 0; c < 2; ++c) {
      const double keep = x[v][c];
      x[v][c] = keep + h; D::signed_areas_2(x, P.faces, ux); const double ep = energy.value(ux);
      x[v][c] = keep - h; D::signed_areas_2(x, P.faces, ux); const double em = energy.value(ux);
      x[v][c] = keep;
      worst = std::max(worst, std::fabs((ep - em) / (2 * h) - g[v][c]));
    }
  ASSERT_GT(gmax, 0);
  EXPECT_LE(worst, 1e-6 * gmax) << "max |finite difference − gradient| = " << worst << ", max |gradient| = " << gmax;
}

TEST(Barrier_energy, GradientMatchesFiniteDifferencesOnNefertiti)
{
  Tutte_disk T;
  ASSERT_TRUE(tutte_disk("nefertiti", T));
  const D::Area_barrier_energy energy(T.P.target);
  std::vector<double> u;
  D::signed_areas_2(T.uv, T.P.faces, u);
  const double E = energy.value(u);
  // The energy is D_area.
  EXPECT_NEAR(E, double(d_area_mine(u, T.P.target)), 1e-12 * E);
  EXPECT_NEAR(E, D::d_area_of(u, T.P.target), 1e-12 * E);
  EXPECT_GT(E, 2.05); // far from the optimum, so the gradient is not small
  expect_gradient_matches_finite_differences(T, energy);
}

// The opening's energy: Σ w_t (log r_t)², recomputed here in long double,
// and its gradient against finite differences.
TEST(Log_ratio_energy, ValueAndGradientOnNefertiti)
{
  Tutte_disk T;
  ASSERT_TRUE(tutte_disk("nefertiti", T));
  const D::Area_barrier_energy barrier(T.P.target);
  const D::Log_ratio_energy energy(barrier);
  std::vector<double> u;
  D::signed_areas_2(T.uv, T.P.faces, u);
  long double U = 0, A = 0, L = 0;
  for(std::size_t f = 0; f < u.size(); ++f) { U += u[f]; A += T.P.target[f]; }
  for(std::size_t f = 0; f < u.size(); ++f) {
    const long double w = T.P.target[f] / A, l = std::log((u[f] / U) / w);
    L += w * l * l;
  }
  EXPECT_GT(double(L), 0.01);
  EXPECT_NEAR(energy.value(u), double(L), 1e-12 * double(L));
  // Invariant under a uniform scale of the domain; a face turned over is +∞.
  std::vector<double> scaled = u;
  for(double& a : scaled) a *= 7.5;
  EXPECT_NEAR(energy.value(scaled), double(L), 1e-12 * double(L));
  scaled[3] = -scaled[3];
  EXPECT_EQ(energy.value(scaled), std::numeric_limits<double>::infinity());
  expect_gradient_matches_finite_differences(T, energy);
}

// The certified flow with and without the log-ratio opening: both converge,
// certified, E never rising. (What the opening saves, 8 → 5 iterations on
// mushroom.off, is a speed figure: doc/certified_mode.md.)
TEST(Log_ratio_energy, CertifiedFlowWithAndWithoutTheOpening)
{
  Tutte_disk T;
  ASSERT_TRUE(tutte_disk("mushroom", T));
  std::size_t iterations[2] = { 0, 0 };
  for(int with = 0; with < 2; ++with) {
    std::vector<Vec2> uv = T.uv, loop;
    for(int v : T.P.boundary) loop.push_back(uv[std::size_t(v)]);
    D::Boundary_curve curve(loop, SMP::Discrete_lie_flow_border::CIRCLE);
    SMP::Discrete_lie_flow_options opt;
    opt.record_history = true;
    D::Planar_flow_settings settings;
    if(!with) settings.log_opening_above = 0;
    Eigen::SimplicialLDLT<D::Sparse_matrix, Eigen::Lower> solver;
    const D::Flow_outcome out = D::certified_disk_flow(T.P, uv, curve, opt, solver, settings);
    EXPECT_EQ(out.stop_reason, SMP::Discrete_lie_flow_stop_reason::CONVERGED) << "log opening " << with;
    EXPECT_TRUE(D::count_orientations_2(uv, T.P.faces, true).all_positive());
    double prev = out.initial_d_area;
    for(const auto& h : out.history) { EXPECT_LE(h.d_area, prev); prev = h.d_area; }
    iterations[with] = out.iterations;
  }
  // The opening may not cost iterations (8 → 5 here when measured).
  EXPECT_LE(iterations[1], iterations[0]) << "with the log opening: " << iterations[1] << ", without: " << iterations[0];
}

// The sign of the paper's Poisson step, from the internals: L h = A_Ω − A_M
// with the cotangent stiffness of the domain, vertex gradients averaged by
// area, one small step along ∇h lowers Σ (A_Ω − A_M)²; the opposite sign raises it.
double lumped_residual(const D::Disk_problem& P, const std::vector<Face>& faces, const std::vector<Vec2>& uv)
{
  const std::size_t n = uv.size();
  std::vector<long double> ao(n, 0.L), am(n, 0.L);
  long double so = 0, sm = 0;
  for(const Face& f : faces) {
    const long double u = std::fabs((long double)D::signed_area_2(uv[f[0]], uv[f[1]], uv[f[2]]));
    const long double a = D::triangle_area_3(P.xyz[f[0]], P.xyz[f[1]], P.xyz[f[2]]);
    for(int k = 0; k < 3; ++k) { ao[f[k]] += u / 3; am[f[k]] += a / 3; }
    so += u; sm += a;
  }
  long double r = 0;
  for(std::size_t i = 0; i < n; ++i) { const long double d = ao[i] - am[i] * so / sm; r += d * d; }
  return double(r);
}

TEST(Paper_step, PoissonStepLowersTheAreaMismatch_Internals)
{
  Tutte_disk T;
  ASSERT_TRUE(tutte_disk("nefertiti", T));
  const D::Disk_problem& P = T.P;
  const std::size_t n = T.uv.size();
  std::vector<double> u, AO, AM;
  D::signed_areas_2(T.uv, P.faces, u);
  D::lump_on_vertices(n, P.faces, u, AO);
  D::lump_on_vertices(n, P.faces, P.target, AM);
  double so = 0, sm = 0;
  for(std::size_t i = 0; i < n; ++i) { so += AO[i]; sm += AM[i]; }
  Eigen::VectorXd rhs(Eigen::Index(n - 1));
  for(std::size_t i = 1; i < n; ++i) rhs[Eigen::Index(i - 1)] = AO[i] - AM[i] * so / sm;
  const D::Sparse_matrix L = D::cotangent_stiffness(T.uv, P.faces);
  // L is symmetric, with the constants in its kernel and a positive diagonal.
  const Eigen::VectorXd ones = Eigen::VectorXd::Ones(Eigen::Index(n));
  EXPECT_LE((L * ones).cwiseAbs().maxCoeff(), 1e-12 * L.diagonal().maxCoeff());
  EXPECT_GT(L.diagonal().minCoeff(), 0);
  EXPECT_LE((D::Sparse_matrix(L.transpose()) - L).norm(), 1e-14 * L.norm());
  Eigen::SimplicialLDLT<D::Sparse_matrix> solver(L.bottomRightCorner(Eigen::Index(n - 1), Eigen::Index(n - 1)));
  ASSERT_EQ(solver.info(), Eigen::Success);
  const Eigen::VectorXd hr = solver.solve(rhs);
  std::vector<double> h(n, 0.);
  for(std::size_t i = 1; i < n; ++i) h[i] = hr[Eigen::Index(i - 1)];
  std::vector<Vec2> grad(n, Vec2{{ 0, 0 }});
  std::vector<double> w(n, 0.);
  for(std::size_t t = 0; t < P.faces.size(); ++t) {
    const Face& f = P.faces[t];
    const Vec2 gt = D::p1_gradient(T.uv[f[0]], T.uv[f[1]], T.uv[f[2]], h[f[0]], h[f[1]], h[f[2]]);
    for(int k = 0; k < 3; ++k) { grad[f[k]][0] += u[t] * gt[0]; grad[f[k]][1] += u[t] * gt[1]; w[f[k]] += u[t]; }
  }
  std::vector<bool> border(n, false);
  for(int v : P.boundary) border[std::size_t(v)] = true;
  const double r0 = lumped_residual(P, P.faces, T.uv);
  auto moved = [&](double lambda) {
    std::vector<Vec2> x = T.uv;
    for(std::size_t v = 0; v < n; ++v)
      if(!border[v]) { x[v][0] += lambda * grad[v][0] / w[v]; x[v][1] += lambda * grad[v][1] / w[v]; }
    return x;
  };
  for(double lambda : { 1e-3, 1e-2 }) {
    const std::vector<Vec2> plus = moved(lambda), minus = moved(-lambda);
    ASSERT_TRUE(D::count_orientations_2(plus, P.faces).all_positive());
    EXPECT_LT(lumped_residual(P, P.faces, plus), r0) << "λ = " << lambda << ": the step along ∇h does not lower the mismatch";
    EXPECT_GT(lumped_residual(P, P.faces, minus), r0) << "λ = " << lambda << ": the step along −∇h lowers it too (test is blind)";
  }
}

// The same through the paper flow itself: one fixed small step, no flips.
TEST(Paper_step, PoissonStepLowersTheAreaMismatch_PaperFlow)
{
  for(double step : { 1e-3, 1e-2 }) {
    Tutte_disk T;
    ASSERT_TRUE(tutte_disk("nefertiti", T));
    const double r0 = lumped_residual(T.P, T.P.faces, T.uv);
    std::vector<Vec2> uv = T.uv, loop;
    for(int v : T.P.boundary) loop.push_back(uv[std::size_t(v)]);
    D::Boundary_curve curve(loop, SMP::Discrete_lie_flow_border::CIRCLE);
    SMP::Discrete_lie_flow_options opt;
    opt.mode = SMP::Discrete_lie_flow_mode::PAPER;
    opt.max_iterations = 1;
    opt.fixed_step = step;
    opt.paper.delaunay_flips = false;
    opt.record_history = true;
    Eigen::SimplicialLDLT<D::Sparse_matrix, Eigen::Lower> solver;
    std::vector<Face> flowing;
    const D::Flow_outcome out = D::paper_disk_flow(T.P, uv, curve, opt, solver, flowing);
    ASSERT_EQ(out.iterations, 1u) << "step " << step;
    ASSERT_EQ(out.history.size(), 1u);
    EXPECT_EQ(out.history[0].step, step);
    bool changed = false;
    for(std::size_t i = 0; i < uv.size(); ++i) changed = changed || uv[i] != T.uv[i];
    ASSERT_TRUE(changed) << "step " << step << ": the flow returned the initial map (the step raised d_area)";
    EXPECT_TRUE(D::count_orientations_2(uv, T.P.faces).all_positive());
    const double r1 = lumped_residual(T.P, T.P.faces, uv);
    EXPECT_LT(r1, r0) << "step " << step;
    // To first order the mismatch drops by about 2λ·r0 (the full linearised
    // correction is λ = 1): not faster than that, and not 10× slower.
    EXPECT_LT(r1, r0 * (1 - 0.2 * step)) << "step " << step;
    EXPECT_GT(r1, r0 * (1 - 4 * step)) << "step " << step;
  }
}

} // namespace

// The paper mode's collapse guard: a face already below its target that the
// velocities drive to collapse (here an interior vertex driven onto an edge)
// keeps its area to first order, by the smallest change of its vertices'
// velocities; a face above its target may shrink and keeps its velocities.
TEST(Paper_guard, ProjectsTheCollapseOfSmallFaces)
{
  std::vector<Vec2> uv = { Vec2{{ 0, 0 }}, Vec2{{ 1, 0 }}, Vec2{{ 0.5, 0.01 }}, Vec2{{ 0.5, -1 }} };
  const std::vector<Face> faces = { Face{{ 0, 1, 2 }}, Face{{ 0, 3, 1 }} };
  const std::vector<double> target = { 0.5, 1.0 }; // face 0 is too small, face 1 too large
  std::vector<double> u;
  D::signed_areas_2(uv, faces, u);
  ASSERT_GT(u[0], 0);
  ASSERT_GT(u[1], 0);
  D::Boundary_curve curve(std::vector<Vec2>{ uv[0], uv[3], uv[1], uv[2] }, SMP::Discrete_lie_flow_border::FREE);
  const D::Planar_dofs dofs(uv.size(), std::vector<int>(), curve);
  ASSERT_EQ(dofs.size, 8);
  std::vector<Vec2> basis(8);
  for(int a = 0; a < 8; ++a) basis[std::size_t(a)] = (a % 2 == 0) ? Vec2{{ 1, 0 }} : Vec2{{ 0, 1 }};
  Eigen::VectorXd d = Eigen::VectorXd::Zero(8);
  d[4] = 0.3; d[5] = -1;  // vertex 2 towards the edge (0, 1): face 0 collapses at λ = 0.01
  d[7] = 0.5;             // vertex 3 up: face 1 shrinks (collapses at λ = 2)
  std::vector<Vec2> vel;
  D::planar_velocity(uv.size(), dofs, basis, d, vel);
  auto rate = [&](const Face& f) {
    const std::array<double, 3> q = D::doubled_area_quadratic(uv[f[0]], uv[f[1]], uv[f[2]], vel[f[0]], vel[f[1]], vel[f[2]]);
    return q[1];
  };
  ASSERT_LT(rate(faces[0]), 0);
  ASSERT_NEAR(D::critical_step_2(uv[0], uv[1], uv[2], vel[0], vel[1], vel[2]), 0.01, 1e-12);
  const Eigen::VectorXd d0 = d;
  D::guard_collapses(uv, faces, u, target, dofs, basis, D::Paper_flow_settings(), d, vel);
  // Face 0 keeps its area to first order, with the smallest change: the
  // correction is along the gradient of its area.
  EXPECT_NEAR(rate(faces[0]), 0, 1e-12);
  EXPECT_GT(D::critical_step_2(uv[0], uv[1], uv[2], vel[0], vel[1], vel[2]), 1);
  const double g[8] = { -0.01, -0.5, 0.01, -0.5, 0, 1, 0, 0 };
  const Eigen::VectorXd change = d - d0;
  for(int a = 0; a < 8; ++a) EXPECT_NEAR(change[a], g[a] / 1.5002, 1e-12) << "dof " << a;
  // Face 1 is above its target: vertex 3 keeps its velocity.
  EXPECT_EQ(d[6], 0.);
  EXPECT_EQ(d[7], 0.5);
  // The paper's velocities when the guard is off.
  Eigen::VectorXd d1 = d0;
  D::guard_collapses(uv, faces, u, target, dofs, basis, D::Paper_flow_settings::plain(), d1, vel);
  EXPECT_TRUE(d1 == d0);
}

// The paper's step as written (no guard, no line search) on a fixed
// connectivity stalls on a strongly curved disk: a vertex is driven onto an
// edge. The flow must detect it and return its best iterate, valid and not
// worse than the start.
TEST(Paper_stall, PlainStepFixedConnectivityMushroom)
{
  Tutte_disk T;
  ASSERT_TRUE(tutte_disk("mushroom", T));
  std::vector<Vec2> uv = T.uv, loop;
  for(int v : T.P.boundary) loop.push_back(uv[std::size_t(v)]);
  D::Boundary_curve curve(loop, SMP::Discrete_lie_flow_border::CIRCLE);
  SMP::Discrete_lie_flow_options opt;
  opt.mode = SMP::Discrete_lie_flow_mode::PAPER;
  opt.paper.delaunay_flips = false;
  opt.record_history = true;
  Eigen::SimplicialLDLT<D::Sparse_matrix, Eigen::Lower> solver;
  std::vector<Face> flowing;
  const D::Flow_outcome out = D::paper_disk_flow(T.P, uv, curve, opt, solver, flowing, D::Paper_flow_settings::plain());
  EXPECT_TRUE(out.stop_reason == SMP::Discrete_lie_flow_stop_reason::STALLED ||
              out.stop_reason == SMP::Discrete_lie_flow_stop_reason::PLATEAU)
    << "stop reason " << SMP::discrete_lie_flow_stop_reason_name(out.stop_reason) << " after " << out.iterations << " iterations";
  EXPECT_LT(out.iterations, opt.max_iterations);
  EXPECT_GT(out.final_d_area, 2 + opt.tolerance) << "the paper's step no longer stalls here: the test is blind";
  EXPECT_TRUE(flowing == T.P.faces);
  EXPECT_TRUE(D::count_orientations_2(uv, T.P.faces, true).all_positive());
  std::vector<double> u0, u;
  D::signed_areas_2(T.uv, T.P.faces, u0);
  D::signed_areas_2(uv, T.P.faces, u);
  EXPECT_LE(out.final_d_area, D::d_area_of(u0, T.P.target));
  EXPECT_NEAR(D::d_area_of(u, T.P.target), out.final_d_area, 1e-12 * out.final_d_area);
  for(const auto& h : out.history) EXPECT_GE(h.d_area, out.final_d_area * (1 - 1e-12));
}

// The planar Gauss–Newton matrix against its definition: with ε = 0,
// xᵀ H x = Σ_t w_t (∂u_t/∂s)², u_t a face's signed area and s the move
// Σ_a x_a basis_a of the dofs, differentiated numerically. Vertices with two
// dofs, one (a border tangent) and none (held) all occur.
// An n × n grid of the unit square, its interior vertices jittered by up to
// a fifth of a cell (every triangle stays positive); vertex j (n + 1) + i.
struct Jittered_grid
{
  int n;
  std::vector<Vec2> uv;
  std::vector<Face> faces;

  Jittered_grid(int n, std::mt19937& rng) : n(n)
  {
    std::uniform_real_distribution<double> U(-1, 1);
    for(int j = 0; j <= n; ++j)
      for(int i = 0; i <= n; ++i) {
        const bool b = i == 0 || j == 0 || i == n || j == n;
        uv.push_back({{ (i + (b ? 0 : 0.2 * U(rng))) / n, (j + (b ? 0 : 0.2 * U(rng))) / n }});
      }
    for(int j = 0; j < n; ++j)
      for(int i = 0; i < n; ++i) {
        const int a = j * (n + 1) + i;
        faces.push_back(Face{{ a, a + 1, a + n + 2 }});
        faces.push_back(Face{{ a, a + n + 2, a + n + 1 }});
      }
  }
  bool border(std::size_t v) const { return on_side(int(v) % (n + 1)) || on_side(int(v) / (n + 1)); }
  bool corner(std::size_t v) const { return on_side(int(v) % (n + 1)) && on_side(int(v) / (n + 1)); }

private:
  bool on_side(int k) const { return k == 0 || k == n; }
};

TEST(Planar_gauss_newton, MatrixIsItsDefinition)
{
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> U(-1, 1);
  const Jittered_grid grid(5, rng);
  const std::vector<Vec2>& uv = grid.uv;
  const std::vector<Face>& faces = grid.faces;
  std::vector<int> first(uv.size()), count(uv.size());
  std::vector<Vec2> basis;
  for(std::size_t v = 0; v < uv.size(); ++v) {
    first[v] = int(basis.size());
    count[v] = grid.corner(v) ? 0 : grid.border(v) ? 1 : 2;
    if(count[v] == 1) {
      const double t = U(rng);
      basis.push_back({{ std::cos(t), std::sin(t) }});
    } else if(count[v] == 2) {
      basis.push_back({{ 1, 0 }});
      basis.push_back({{ 0, 1 }});
    }
  }
  std::vector<double> w(faces.size());
  for(double& x : w) x = 1 + U(rng) * U(rng);
  D::Planar_gauss_newton_system system(first, count, int(basis.size()));
  const D::Sparse_matrix A = system.assemble(uv, faces, basis, w, 0);
  ASSERT_EQ(A.rows(), Eigen::Index(basis.size()));
  for(int trial = 0; trial < 3; ++trial) {
    Eigen::VectorXd x(A.rows());
    for(Eigen::Index k = 0; k < x.size(); ++k) x[k] = U(rng);
    const double e = 1e-6;
    std::vector<Vec2> plus = uv, minus = uv;
    for(std::size_t v = 0; v < uv.size(); ++v)
      for(int k = 0; k < count[v]; ++k) {
        const Vec2& b = basis[std::size_t(first[v] + k)];
        const double xv = x[Eigen::Index(first[v] + k)];
        for(int c = 0; c < 2; ++c) { plus[v][c] += e * xv * b[c]; minus[v][c] -= e * xv * b[c]; }
      }
    std::vector<double> up, um;
    D::signed_areas_2(plus, faces, up);
    D::signed_areas_2(minus, faces, um);
    double expected = 0;
    for(std::size_t t = 0; t < faces.size(); ++t) {
      const double du = (up[t] - um[t]) / (2 * e);
      expected += w[t] * du * du;
    }
    EXPECT_GT(expected, 0.);
    EXPECT_NEAR(x.dot(A * x), expected, 1e-6 * expected);
  }
}

// The Sobolev direction against its definition, assembled densely here:
// d = −M⁻¹ Bᵀg over the dofs (interior: x and y; a sliding border vertex:
// its tangent; a corner: none), M = [A C; Cᵀ CᵀA⁻¹C + S̃] from the cotangent
// stiffness K = L ⊗ I₂ (A = B_Iᵀ K B_I, C = B_Iᵀ K B_B) with the border's
// Schur complement replaced by S̃ = diag(L_vv).
TEST(Sobolev_direction, IsMinusTheInverseMetricAppliedToTheGradient)
{
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> U(-1, 1);
  const Jittered_grid grid(4, rng);
  const std::vector<Vec2>& uv = grid.uv;
  const std::vector<Face>& faces = grid.faces;
  const std::size_t nv = uv.size();
  std::vector<int> boundary_of(nv, -1);
  std::vector<Vec2> tangent(nv, Vec2{{ 0, 0 }}), g(nv);
  int nb = 0;
  for(std::size_t v = 0; v < nv; ++v) {
    if(grid.border(v)) {
      boundary_of[v] = nb++;
      const double t = 3 * U(rng);
      if(!grid.corner(v)) tangent[v] = {{ std::cos(t), std::sin(t) }};
    }
    g[v] = {{ U(rng), U(rng) }};
  }
  // The cotangent Laplacian from the angles.
  Eigen::MatrixXd L = Eigen::MatrixXd::Zero(Eigen::Index(nv), Eigen::Index(nv));
  for(const Face& t : faces)
    for(int k = 0; k < 3; ++k) {
      const Vec2& a = uv[std::size_t(t[k])];
      const Vec2& b = uv[std::size_t(t[(k + 1) % 3])];
      const Vec2& c = uv[std::size_t(t[(k + 2) % 3])];
      const double angle = std::abs(std::atan2((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]),
                                               (b[0] - a[0]) * (c[0] - a[0]) + (b[1] - a[1]) * (c[1] - a[1])));
      const double w = 0.5 / std::tan(angle);
      const Eigen::Index i = t[(k + 1) % 3], j = t[(k + 2) % 3];
      L(i, j) -= w; L(j, i) -= w; L(i, i) += w; L(j, j) += w;
    }
  // The dofs' basis B (2 nv × m), interior dofs first.
  std::vector<std::pair<std::size_t, Vec2> > dofs;
  for(std::size_t v = 0; v < nv; ++v)
    if(boundary_of[v] < 0) { dofs.push_back({ v, Vec2{{ 1, 0 }} }); dofs.push_back({ v, Vec2{{ 0, 1 }} }); }
  const Eigen::Index mi = Eigen::Index(dofs.size());
  for(std::size_t v = 0; v < nv; ++v)
    if(boundary_of[v] >= 0 && (tangent[v][0] != 0 || tangent[v][1] != 0)) dofs.push_back({ v, tangent[v] });
  const Eigen::Index m = Eigen::Index(dofs.size());
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(2 * Eigen::Index(nv), m);
  Eigen::VectorXd G(2 * Eigen::Index(nv));
  for(Eigen::Index k = 0; k < m; ++k)
    for(int c = 0; c < 2; ++c) B(2 * Eigen::Index(dofs[std::size_t(k)].first) + c, k) = dofs[std::size_t(k)].second[c];
  for(std::size_t v = 0; v < nv; ++v) { G[2 * Eigen::Index(v)] = g[v][0]; G[2 * Eigen::Index(v) + 1] = g[v][1]; }
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(2 * Eigen::Index(nv), 2 * Eigen::Index(nv));
  for(Eigen::Index i = 0; i < Eigen::Index(nv); ++i)
    for(Eigen::Index j = 0; j < Eigen::Index(nv); ++j) { K(2 * i, 2 * j) = L(i, j); K(2 * i + 1, 2 * j + 1) = L(i, j); }
  const Eigen::MatrixXd BKB = B.transpose() * K * B;
  const Eigen::MatrixXd A = BKB.topLeftCorner(mi, mi), C = BKB.topRightCorner(mi, m - mi);
  Eigen::MatrixXd M = BKB;
  M.bottomRightCorner(m - mi, m - mi) = C.transpose() * A.ldlt().solve(C);
  for(Eigen::Index k = mi; k < m; ++k) M(k, k) += L(Eigen::Index(dofs[std::size_t(k)].first), Eigen::Index(dofs[std::size_t(k)].first));
  const Eigen::VectorXd expected = B * M.ldlt().solve(-(B.transpose() * G));

  Eigen::SimplicialLDLT<D::Sparse_matrix, Eigen::Lower> solver;
  D::Split_sobolev_direction<Eigen::SimplicialLDLT<D::Sparse_matrix, Eigen::Lower> > sobolev(boundary_of, solver);
  sobolev.assemble(uv, faces);
  ASSERT_TRUE(sobolev.factorize());
  std::vector<Vec2> d;
  ASSERT_TRUE(sobolev.solve(g, tangent, d));
  ASSERT_EQ(d.size(), nv);
  double slope = 0, border_slope = 0;
  for(std::size_t v = 0; v < nv; ++v) {
    for(int c = 0; c < 2; ++c)
      EXPECT_NEAR(d[v][c], expected[2 * Eigen::Index(v) + c], 1e-9 * expected.cwiseAbs().maxCoeff()) << "vertex " << v;
    slope += d[v][0] * g[v][0] + d[v][1] * g[v][1];
    if(boundary_of[v] >= 0) border_slope += d[v][0] * g[v][0] + d[v][1] * g[v][1];
  }
  EXPECT_LT(slope, 0.) << "not a descent direction";
  EXPECT_NE(border_slope, 0.) << "the border vertices did not move";
}

// One relaxation sweep of the planar energy: the energy it reports (its
// running sums) is the energy of the map it leaves, recomputed from the
// areas here, lower than at the start, every face positive.
TEST(Planar_relaxation, SweepKeepsItsEnergyAndLowersIt)
{
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> U(-1, 1);
  const Jittered_grid grid(6, rng);
  std::vector<Vec2> uv = grid.uv;
  const std::vector<Face>& faces = grid.faces;
  std::vector<double> target(faces.size());
  for(double& a : target) a = 1 + 0.8 * U(rng); // far from the grid's areas: every vertex has a move
  const D::Area_barrier_energy energy(target);
  const D::Vertex_faces around(uv.size(), faces);
  std::vector<char> movable(uv.size(), 0);
  std::size_t interior = 0;
  for(std::size_t v = 0; v < uv.size(); ++v) {
    movable[v] = !grid.border(v);
    interior += std::size_t(movable[v]);
  }
  std::vector<double> u;
  D::signed_areas_2(uv, faces, u);
  double E = energy.value(u);
  for(int sweep = 0; sweep < 3; ++sweep) {
    const std::vector<Vec2> before = uv;
    const D::Relaxation_outcome out = D::relax_planar_vertices(faces, around, energy, 0.9, movable, uv, u);
    EXPECT_GT(out.moved, sweep == 0 ? interior / 2 : 0) << "sweep " << sweep;
    for(std::size_t v = 0; v < uv.size(); ++v)
      if(!movable[v]) EXPECT_TRUE(uv[v] == before[v]) << "a border vertex moved: " << v;
    std::vector<double> fresh;
    D::signed_areas_2(uv, faces, fresh);
    for(std::size_t t = 0; t < faces.size(); ++t) {
      ASSERT_GT(fresh[t], 0.) << "face " << t;
      EXPECT_EQ(u[t], fresh[t]) << "face " << t << ": the areas kept are not the map's";
    }
    const double E_fresh = energy.value(fresh);
    EXPECT_NEAR(out.energy, E_fresh, 1e-10 * E_fresh) << "sweep " << sweep;
    EXPECT_LT(E_fresh, E) << "sweep " << sweep;
    E = E_fresh;
  }
}

// The kernel of a ring polygon (where a vertex put back into its ring sees
// every ring edge from the inside) against the corners found here from the
// edges' lines: every pairwise intersection inside all the half-planes.
TEST(Kernel_centroid, MatchesTheHalfPlanesCorners)
{
  const auto corners_centroid = [](const std::vector<Vec2>& ring, Vec2& c) {
    const std::size_t k = ring.size();
    std::vector<Vec2> corners;
    for(std::size_t i = 0; i < k; ++i)
      for(std::size_t j = i + 1; j < k; ++j) {
        const Vec2 &a = ring[i], &b = ring[(i + 1) % k], &p = ring[j], &q = ring[(j + 1) % k];
        const double den = (b[0] - a[0]) * (q[1] - p[1]) - (b[1] - a[1]) * (q[0] - p[0]);
        if(std::abs(den) < 1e-14) continue;
        const double t = ((p[0] - a[0]) * (q[1] - p[1]) - (p[1] - a[1]) * (q[0] - p[0])) / den;
        const Vec2 x{{ a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]) }};
        bool inside = true;
        for(std::size_t e = 0; e < k && inside; ++e) {
          const Vec2 &e0 = ring[e], &e1 = ring[(e + 1) % k];
          inside = (e1[0] - e0[0]) * (x[1] - e0[1]) - (e1[1] - e0[1]) * (x[0] - e0[0]) > -1e-12;
        }
        bool seen = false;
        for(const Vec2& y : corners) seen = seen || (std::abs(y[0] - x[0]) < 1e-12 && std::abs(y[1] - x[1]) < 1e-12);
        if(inside && !seen) corners.push_back(x);
      }
    if(corners.size() < 3) return false;
    c = Vec2{{ 0, 0 }};
    for(const Vec2& y : corners) { c[0] += y[0] / double(corners.size()); c[1] += y[1] / double(corners.size()); }
    return true;
  };
  // A convex hexagon (its kernel is itself), an arrow head with a reflex
  // corner, a star with five reflex corners, and a spiral-like hook whose
  // kernel is empty.
  std::vector<std::vector<Vec2> > rings;
  {
    std::vector<Vec2> hexagon, star;
    for(int i = 0; i < 6; ++i) hexagon.push_back({{ std::cos(i * 1.0471975511965976), 1.3 * std::sin(i * 1.0471975511965976) }});
    for(int i = 0; i < 10; ++i) {
      const double r = i % 2 == 0 ? 1 : 0.45, a = i * 0.6283185307179586 + 0.1;
      star.push_back({{ r * std::cos(a), r * std::sin(a) }});
    }
    rings.push_back(hexagon);
    rings.push_back({ {{ 0, 0 }}, {{ 2, 1 }}, {{ 0, 2 }}, {{ 0.8, 1 }} });
    rings.push_back(star);
  }
  for(std::size_t r = 0; r < rings.size(); ++r) {
    Vec2 expected, got;
    ASSERT_TRUE(corners_centroid(rings[r], expected)) << "ring " << r;
    ASSERT_TRUE(D::kernel_centroid(rings[r], got)) << "ring " << r;
    EXPECT_NEAR(got[0], expected[0], 1e-12) << "ring " << r;
    EXPECT_NEAR(got[1], expected[1], 1e-12) << "ring " << r;
  }
  const std::vector<Vec2> hook{ {{ 0, 0 }}, {{ 3, 0 }}, {{ 3, 3 }}, {{ 0, 3 }}, {{ 0, 2 }}, {{ 2, 2 }}, {{ 2, 1 }}, {{ 0, 1 }} };
  Vec2 c, unused;
  EXPECT_FALSE(corners_centroid(hook, unused));
  EXPECT_FALSE(D::kernel_centroid(hook, c)) << "the hook has no kernel";
}

} // namespace dlf_test_numerics
