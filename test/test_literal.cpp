// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The literal mode (Algorithm 1 as printed) and the errata of the paper
// (doc/paper_errata.md): Eq. 4's coefficients against brute force, and the
// first step of Algorithm 1 computed here independently (angles, a dense
// solve, per-face gradients, roots by the quadratic formula) against the
// library's.

#include <gtest/gtest.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/critical_step.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/default_solver.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/disk/disk_flow.h>

#include <Eigen/Dense>

#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

// The tests compile in unity batches (DLF_UNITY_BUILD): each file keeps its
// names in a namespace of its own.
namespace dlf_test_literal {

namespace {

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace D = CGAL::Surface_mesh_parameterization::internal::dlf;
using D::Face;
using D::Vec2;
using D::Vec3;

/// Twice the signed area of (p0 + λ d0, p1 + λ d1, p2 + λ d2), straight from the points.
double doubled_area_at(const std::array<Vec2, 3>& p, const std::array<Vec2, 3>& d, double l)
{
  Vec2 q[3];
  for(int k = 0; k < 3; ++k) q[k] = Vec2{{ p[k][0] + l * d[k][0], p[k][1] + l * d[k][1] }};
  return (q[1][0] - q[0][0]) * (q[2][1] - q[0][1]) - (q[1][1] - q[0][1]) * (q[2][0] - q[0][0]);
}

/// The exact quadratic through three samples (λ = −1, 0, 1): (a, b, c).
std::array<double, 3> brute_force_quadratic(const std::array<Vec2, 3>& p, const std::array<Vec2, 3>& d)
{
  const double m = doubled_area_at(p, d, -1), z = doubled_area_at(p, d, 0), u = doubled_area_at(p, d, 1);
  return {{ (u + m) / 2 - z, (u - m) / 2, z }};
}

/// Smallest positive root of a λ² + b λ + c by the schoolbook formula (+∞ if none).
double schoolbook_root(double a, double b, double c)
{
  double best = std::numeric_limits<double>::infinity();
  if(std::abs(a) < 1e-14 * (std::abs(b) + std::abs(c))) {
    if(b != 0 && -c / b > 0) best = -c / b;
    return best;
  }
  const double disc = b * b - 4 * a * c;
  if(disc < 0) return best;
  for(const double s : { -1., 1. }) {
    const double r = (-b + s * std::sqrt(disc)) / (2 * a);
    if(r > 0 && r < best) best = r;
  }
  return best;
}

// Eq. 4 as printed (the line through v1, v2 at v3; x_k, y_k the corners,
// h_k = (h¹_k, h²_k) their velocities) is not the signed area: the errata's
// coefficients are, and the library's are those.
TEST(Errata, Eq4CoefficientsAgainstBruteForce)
{
  std::mt19937 rng(20190604);
  std::uniform_real_distribution<double> U(-1, 1);
  int printed_wrong = 0;
  for(int trial = 0; trial < 200; ++trial) {
    std::array<Vec2, 3> p, d;
    for(int k = 0; k < 3; ++k) { p[k] = Vec2{{ U(rng), U(rng) }}; d[k] = Vec2{{ U(rng), U(rng) }}; }
    if(doubled_area_at(p, d, 0) < 0) std::swap(p[1], p[2]), std::swap(d[1], d[2]);
    const double x1 = p[0][0], y1 = p[0][1], x2 = p[1][0], y2 = p[1][1], x3 = p[2][0], y3 = p[2][1];
    const double h11 = d[0][0], h12 = d[0][1], h21 = d[1][0], h22 = d[1][1], h31 = d[2][0], h32 = d[2][1];
    const std::array<double, 3> bf = brute_force_quadratic(p, d);
    // The errata's Λ, S, Q (doc/paper_errata.md, "Eq. 4"): the paper's
    // left-hand side is −2·area, so Λ = −a, S = −b, Q = −c.
    const double L = (h21 - h11) * (h32 - h12) - (h22 - h12) * (h31 - h11);
    const double S = (x2 - x1) * (h32 - h12) + (h21 - h11) * (y3 - y1) - (y2 - y1) * (h31 - h11) - (h22 - h12) * (x3 - x1);
    const double Q = (x2 - x1) * (y3 - y1) - (y2 - y1) * (x3 - x1);
    const double scale = 1 + std::abs(bf[0]) + std::abs(bf[1]) + std::abs(bf[2]);
    EXPECT_NEAR(L, bf[0], 1e-12 * scale);
    EXPECT_NEAR(S, bf[1], 1e-12 * scale);
    EXPECT_NEAR(Q, bf[2], 1e-12 * scale);
    // The library's coefficients.
    const std::array<double, 3> lib = D::doubled_area_quadratic(p[0], p[1], p[2], d[0], d[1], d[2]);
    for(int k = 0; k < 3; ++k) EXPECT_NEAR(lib[k], bf[k], 1e-12 * scale) << "coefficient " << k;
    // Its root: the area vanishes there and is positive before.
    const double r = D::critical_step_2(p[0], p[1], p[2], d[0], d[1], d[2]);
    const double r_school = schoolbook_root(bf[0], bf[1], bf[2]);
    if(std::isfinite(r_school)) {
      EXPECT_NEAR(r, r_school, 1e-9 * (1 + r_school));
      for(int k = 1; k < 10; ++k) EXPECT_GT(doubled_area_at(p, d, r * k / 10.), 0);
    } else {
      EXPECT_FALSE(std::isfinite(r));
    }
    // Eq. 4 as printed, with the sign of the paper's equation (−2·area).
    const double Lp = x2 * h12 - x1 * h22 + h31 * (h22 - h12) - h32 * (h21 - h11);
    const double Sp = h31 * (y2 - y1) + x3 * (h22 - h12) - h32 * (x2 - x1) - y3 * (h21 - h11) + y2 * (h21 - h11);
    const double Qp = x2 * y1 - x1 * y2 - y3 * (x2 - x1);
    if(std::abs(Lp + bf[0]) > 1e-6 * scale || std::abs(Sp + bf[1]) > 1e-6 * scale || std::abs(Qp + bf[2]) > 1e-6 * scale)
      ++printed_wrong;
  }
  // The print is wrong for generic data (it misses x₃(y₂ − y₁) in Q alone).
  EXPECT_EQ(printed_wrong, 200);
}

/// Seven points of [−1, 1]² (corners 0–3, interior 4–6) and their Delaunay
/// triangulation, lifted to z = 0.6 x² + 0.4 x y so the targets differ.
void small_square(D::Disk_problem& P, std::vector<Vec2>& uv)
{
  uv = { {{ -1, -1 }}, {{ 1, -1 }}, {{ 1, 1 }}, {{ -1, 1 }}, {{ -0.35, -0.2 }}, {{ 0.4, -0.3 }}, {{ 0.1, 0.45 }} };
  P.faces = { {{ 4, 3, 0 }}, {{ 1, 5, 0 }}, {{ 5, 4, 0 }}, {{ 2, 5, 1 }}, {{ 3, 6, 2 }}, {{ 6, 3, 4 }}, {{ 6, 5, 2 }}, {{ 5, 6, 4 }} };
  P.boundary = { 0, 1, 2, 3 };
  for(const Vec2& q : uv) P.xyz.push_back(Vec3{{ q[0], q[1], 0.6 * q[0] * q[0] + 0.4 * q[0] * q[1] }});
  for(const Face& f : P.faces) P.target.push_back(D::triangle_area_3(P.xyz[f[0]], P.xyz[f[1]], P.xyz[f[2]]));
}

// Algorithm 1's first step with μ and targets as printed (μ = 0.8, h_M
// lumped on the input triangles, the square's corners fixed), computed here
// from scratch, against the library's literal mode after one iteration.
TEST(Literal, FirstStepByHand)
{
  D::Disk_problem P;
  std::vector<Vec2> uv;
  small_square(P, uv);
  const std::size_t n = uv.size();
  // Precondition: the triangulation is Delaunay, so step 2 flips nothing.
  typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_2 Pt;
  for(const Face& f : P.faces)
    for(std::size_t v = 0; v < n; ++v) {
      if(int(v) == f[0] || int(v) == f[1] || int(v) == f[2]) continue;
      ASSERT_EQ(CGAL::side_of_oriented_circle(Pt(uv[f[0]][0], uv[f[0]][1]), Pt(uv[f[1]][0], uv[f[1]][1]),
                                              Pt(uv[f[2]][0], uv[f[2]][1]), Pt(uv[v][0], uv[v][1])),
                CGAL::ON_NEGATIVE_SIDE);
    }

  // Step 1 and 3: vertex area elements, h_Ω scaled to ∫h_M... both to the domain's area.
  std::vector<double> hM(n, 0.), hO(n, 0.), area(P.faces.size());
  double SO = 0, SM = 0;
  for(std::size_t t = 0; t < P.faces.size(); ++t) {
    const Face& f = P.faces[t];
    area[t] = 0.5 * ((uv[f[1]][0] - uv[f[0]][0]) * (uv[f[2]][1] - uv[f[0]][1]) -
                     (uv[f[1]][1] - uv[f[0]][1]) * (uv[f[2]][0] - uv[f[0]][0]));
    ASSERT_GT(area[t], 0);
    for(int k = 0; k < 3; ++k) { hO[f[k]] += area[t] / 3; hM[f[k]] += P.target[t] / 3; }
    SO += area[t]; SM += P.target[t];
  }
  // Step 4: Δg = h_M − h_Ω with Δ = −L, L the cotangent stiffness built from the angles.
  Eigen::MatrixXd L = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  for(const Face& f : P.faces)
    for(int k = 0; k < 3; ++k) {
      const int i = f[k], j = f[(k + 1) % 3], o = f[(k + 2) % 3];
      const double ax = uv[i][0] - uv[o][0], ay = uv[i][1] - uv[o][1], bx = uv[j][0] - uv[o][0], by = uv[j][1] - uv[o][1];
      const double angle = std::acos((ax * bx + ay * by) / std::hypot(ax, ay) / std::hypot(bx, by));
      const double w = 0.5 / std::tan(angle);
      L(i, j) -= w; L(j, i) -= w; L(i, i) += w; L(j, j) += w;
    }
  Eigen::VectorXd rhs(static_cast<Eigen::Index>(n));
  for(std::size_t i = 0; i < n; ++i) rhs[Eigen::Index(i)] = hO[i] - hM[i] * SO / SM;
  // Neumann problem: pin g_0 = 0 (any constant; the gradient ignores it).
  const Eigen::VectorXd g_red = L.bottomRightCorner(Eigen::Index(n - 1), Eigen::Index(n - 1))
                                  .fullPivLu().solve(rhs.tail(Eigen::Index(n - 1)));
  Eigen::VectorXd g = Eigen::VectorXd::Zero(Eigen::Index(n));
  g.tail(Eigen::Index(n - 1)) = g_red;
  // Step 5: per-face gradient (solve the 2×2 system), area-weighted at the vertices; corners fixed.
  std::vector<Vec2> vel(n, Vec2{{ 0, 0 }});
  std::vector<double> wsum(n, 0.);
  for(std::size_t t = 0; t < P.faces.size(); ++t) {
    const Face& f = P.faces[t];
    Eigen::Matrix2d E;
    E << uv[f[1]][0] - uv[f[0]][0], uv[f[1]][1] - uv[f[0]][1], uv[f[2]][0] - uv[f[0]][0], uv[f[2]][1] - uv[f[0]][1];
    const Eigen::Vector2d grad = E.inverse() * Eigen::Vector2d(g[f[1]] - g[f[0]], g[f[2]] - g[f[0]]);
    for(int k = 0; k < 3; ++k) {
      vel[f[k]][0] += area[t] * grad[0];
      vel[f[k]][1] += area[t] * grad[1];
      wsum[f[k]] += area[t];
    }
  }
  for(std::size_t v = 0; v < n; ++v) {
    const bool corner = v < 4;
    for(int j = 0; j < 2; ++j) vel[v][j] = corner ? 0 : vel[v][j] / wsum[v];
  }
  // Step 6: λ = μ · min_t λ̃_t with the brute-force area quadratic and μ = 0.8.
  double critical = std::numeric_limits<double>::infinity();
  for(const Face& f : P.faces) {
    const std::array<double, 3> q = brute_force_quadratic({{ uv[f[0]], uv[f[1]], uv[f[2]] }}, {{ vel[f[0]], vel[f[1]], vel[f[2]] }});
    critical = (std::min)(critical, schoolbook_root(q[0], q[1], q[2]));
  }
  ASSERT_TRUE(std::isfinite(critical));
  const double lambda = 0.8 * critical;

  SMP::Discrete_lie_flow_options options;
  options.mode = SMP::Discrete_lie_flow_mode::LITERAL;
  options.disk.border = SMP::Discrete_lie_flow_border::SQUARE;
  options.max_iterations = 1;
  options.record_history = true;
  options.paper.residual_threshold = 1e-30; // never met: one full step
  D::Default_spd_solver solver;
  SMP::Discrete_lie_flow_report R;
  std::vector<Vec2> flowed = uv;
  ASSERT_EQ(D::flow_disk(P, flowed, options, solver, R), SMP::OK) << R.message;
  ASSERT_EQ(R.iterations, 1u);
  ASSERT_EQ(R.history.size(), 1u);
  EXPECT_EQ(R.stop_reason, SMP::Discrete_lie_flow_stop_reason::ITERATION_CAP);
  EXPECT_NEAR(R.history[0].critical_step, critical, 1e-10 * critical);
  EXPECT_NEAR(R.history[0].step, lambda, 1e-10 * lambda);
  // Step 7.
  for(std::size_t v = 0; v < n; ++v)
    for(int j = 0; j < 2; ++j)
      EXPECT_NEAR(flowed[v][j], uv[v][j] + lambda * vel[v][j], 1e-10) << "vertex " << v << ", coordinate " << j;
}

// A fixed step that folds the flowing mesh is the literal mode's documented
// failure: stop reason COLLAPSED, the folded faces counted, the start returned.
TEST(Literal, FixedStepCollapseIsReported)
{
  D::Disk_problem P;
  std::vector<Vec2> uv;
  small_square(P, uv);
  SMP::Discrete_lie_flow_options options;
  options.mode = SMP::Discrete_lie_flow_mode::LITERAL;
  options.disk.border = SMP::Discrete_lie_flow_border::SQUARE;
  options.fixed_step = 1e3;
  D::Default_spd_solver solver;
  SMP::Discrete_lie_flow_report R;
  const std::vector<Vec2> start = uv;
  ASSERT_EQ(D::flow_disk(P, uv, options, solver, R), SMP::OK) << R.message;
  EXPECT_EQ(R.stop_reason, SMP::Discrete_lie_flow_stop_reason::COLLAPSED);
  EXPECT_EQ(R.iterations, 0u);
  EXPECT_GT(R.collapse_faces, 0u);
  EXPECT_EQ(R.flowing_inverted_faces, 0u);
  EXPECT_TRUE(uv == start);
  EXPECT_NE(R.message.find("collapsed"), std::string::npos) << R.message;
  // A small fixed step is taken as it is, every iteration.
  options.fixed_step = 1e-3;
  options.max_iterations = 3;
  options.record_history = true;
  uv = start;
  ASSERT_EQ(D::flow_disk(P, uv, options, solver, R), SMP::OK) << R.message;
  ASSERT_EQ(R.history.size(), 3u);
  for(const auto& h : R.history) EXPECT_EQ(h.step, 1e-3);
}

} // namespace

} // namespace dlf_test_literal
