// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The metrics added for the paper's tables (doc/design.md, "Metrics"): the
// Table 1 "Wasserstein distance" and Area_total of area shares, the Beltrami
// coefficient of a map and of one map against another, and the transport
// cost between two maps, each against a hand computation or an independent
// formula (complex derivatives of a known affine map).

#include <gtest/gtest.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_distortion.h>

#include <cmath>
#include <complex>
#include <vector>

// The tests compile in unity batches (DLF_UNITY_BUILD): each file keeps its
// names in a namespace of its own.
namespace dlf_test_paper_metrics {

namespace {

namespace SMP = CGAL::Surface_mesh_parameterization;
typedef std::array<double, 2> P2;
typedef std::array<double, 3> P3;
typedef std::array<int, 3> Tri;
typedef std::complex<double> C;

struct Grid
{
  std::vector<P2> plane; // intrinsic coordinates
  std::vector<Tri> faces;
};

// An m×m grid with jittered interior vertices, so that faces differ.
Grid grid(int m)
{
  Grid g;
  for(int j = 0; j <= m; ++j)
    for(int i = 0; i <= m; ++i) {
      const bool inner = i > 0 && j > 0 && i < m && j < m;
      const double jx = inner ? 0.23 * std::sin(3.1 * i + 1.7 * j) : 0, jy = inner ? 0.19 * std::cos(2.3 * i - 0.9 * j) : 0;
      g.plane.push_back({{ i + jx, j + jy }});
    }
  for(int j = 0; j < m; ++j)
    for(int i = 0; i < m; ++i) {
      const int a = j * (m + 1) + i;
      g.faces.push_back({{ a, a + 1, a + m + 2 }});
      g.faces.push_back({{ a, a + m + 2, a + m + 1 }});
    }
  return g;
}

// The grid embedded in a tilted plane of R³ (an isometry of its coordinates).
std::vector<P3> tilted(const std::vector<P2>& plane)
{
  const double c = std::cos(0.7), s = std::sin(0.7);
  const double e1[3] = { c, 0, s }, e2[3] = { -s * s, c, c * s }; // orthonormal
  const double n2 = std::sqrt(e2[0] * e2[0] + e2[1] * e2[1] + e2[2] * e2[2]);
  std::vector<P3> out;
  for(const P2& p : plane)
    out.push_back({{ p[0] * e1[0] + p[1] * e2[0] / n2, p[0] * e1[1] + p[1] * e2[1] / n2 + 5,
                     p[0] * e1[2] + p[1] * e2[2] / n2 - 2 }});
  return out;
}

// f(z) = α z + β conj(z): its Beltrami coefficient is β / α everywhere.
std::vector<P2> affine(const std::vector<P2>& plane, C alpha, C beta)
{
  std::vector<P2> out;
  for(const P2& p : plane) {
    const C z(p[0], p[1]);
    const C w = alpha * z + beta * std::conj(z) + C(0.4, -1.3);
    out.push_back({{ w.real(), w.imag() }});
  }
  return out;
}

} // namespace

TEST(PaperMetrics, BeltramiOfAnAffineMapOnATiltedMesh)
{
  const Grid g = grid(6);
  const std::vector<P3> xyz = tilted(g.plane);
  for(const C beta : { C(0, 0), C(0.3, 0.1), C(-0.2, 0.5) }) {
    const C alpha(1.2, -0.4);
    const double expected = std::abs(beta / alpha);
    const SMP::Discrete_lie_flow_distortion d =
      SMP::discrete_lie_flow_distortion(xyz, affine(g.plane, alpha, beta), g.faces);
    EXPECT_EQ(d.inverted_faces, 0u);
    EXPECT_NEAR(d.beltrami_mean, expected, 1e-12);
    EXPECT_NEAR(d.beltrami_weighted_mean, expected, 1e-12);
    EXPECT_NEAR(d.beltrami_max, expected, 1e-12);
  }
  // One vertex pushed across its neighbours: its folded faces have |μ| > 1,
  // and the mean grows.
  std::vector<P2> folded = g.plane;
  folded[8] = {{ 3.6, 2.7 }};
  const SMP::Discrete_lie_flow_distortion d = SMP::discrete_lie_flow_distortion(xyz, folded, g.faces);
  EXPECT_GT(d.inverted_faces, 0u);
  EXPECT_GT(d.beltrami_max, 1);
}

TEST(PaperMetrics, Table1WassersteinAndAreaTotalOfAreaShares)
{
  // A regular grid (no jitter) whose left half is squeezed to half its width:
  // shares 1/F on the mesh, 2/(3F) and 4/(3F) on the domain.
  const int m = 4;
  std::vector<P2> plane, squeezed;
  std::vector<Tri> faces;
  for(int j = 0; j <= m; ++j)
    for(int i = 0; i <= m; ++i) {
      plane.push_back({{ double(i), double(j) }});
      squeezed.push_back({{ i < m / 2 ? i / 2. : i - m / 4., double(j) }});
    }
  for(int j = 0; j < m; ++j)
    for(int i = 0; i < m; ++i) {
      const int a = j * (m + 1) + i;
      faces.push_back({{ a, a + 1, a + m + 2 }});
      faces.push_back({{ a, a + m + 2, a + m + 1 }});
    }
  const double F = double(faces.size());
  const std::vector<P3> xyz = tilted(plane);
  const SMP::Discrete_lie_flow_distortion d = SMP::discrete_lie_flow_distortion(xyz, squeezed, faces);
  EXPECT_NEAR(d.wasserstein_table1, 1 / (3 * std::sqrt(F)), 1e-14);
  EXPECT_NEAR(d.area_total, 1. / 3, 1e-14);
  // Area preserved (a rotation and a scale): both vanish.
  const SMP::Discrete_lie_flow_distortion r = SMP::discrete_lie_flow_distortion(xyz, affine(plane, C(0.3, 2), C(0)), faces);
  EXPECT_NEAR(r.wasserstein_table1, 0, 1e-15);
  EXPECT_NEAR(r.area_total, 0, 1e-14);
  // A density of 2 on the right half makes the squeezed map exact (shares
  // 2/(3F) and 4/(3F) on both sides).
  std::vector<double> rho(faces.size(), 1.);
  for(std::size_t f = 0; f < faces.size(); ++f) {
    const Tri& t = faces[f];
    if(plane[std::size_t(t[0])][0] + plane[std::size_t(t[1])][0] + plane[std::size_t(t[2])][0] > 3 * m / 2.) rho[f] = 2;
  }
  EXPECT_NEAR(SMP::discrete_lie_flow_distortion(xyz, squeezed, faces, rho).wasserstein_table1, 0, 1e-14);
}

TEST(PaperMetrics, DifferenceOfTwoMaps)
{
  const Grid g = grid(5);
  const std::vector<P3> xyz = tilted(g.plane);
  const std::vector<P2> a = affine(g.plane, C(0.8, 0.3), C(0.1, -0.2));
  // b = a translated by (0.3, −0.4): transport cost 0.5, conformal.
  std::vector<P2> b = a;
  for(P2& p : b) { p[0] += 0.3; p[1] -= 0.4; }
  SMP::Discrete_lie_flow_map_difference d = SMP::discrete_lie_flow_map_difference(xyz, a, b, g.faces);
  EXPECT_NEAR(d.transport_cost, 0.5, 1e-14);
  EXPECT_NEAR(d.beltrami_max, 0, 1e-12);
  EXPECT_EQ(d.faces_not_compared, 0u);
  // b = γ a + δ conj(a): ψ = b ∘ a⁻¹ has μ = δ / γ whatever a is.
  const C gamma(0.9, 0.2), delta(0.25, -0.1);
  b.clear();
  for(const P2& p : a) {
    const C w = gamma * C(p[0], p[1]) + delta * std::conj(C(p[0], p[1]));
    b.push_back({{ w.real(), w.imag() }});
  }
  d = SMP::discrete_lie_flow_map_difference(xyz, a, b, g.faces);
  EXPECT_NEAR(d.beltrami_mean, std::abs(delta / gamma), 1e-12);
  EXPECT_NEAR(d.beltrami_weighted_mean, std::abs(delta / gamma), 1e-12);
  EXPECT_NEAR(d.beltrami_max, std::abs(delta / gamma), 1e-12);
  // Transport cost against the lumped masses computed here.
  std::vector<double> mass(a.size(), 0.);
  double total = 0;
  for(const Tri& t : g.faces) {
    const P2 &p = g.plane[std::size_t(t[0])], &q = g.plane[std::size_t(t[1])], &r = g.plane[std::size_t(t[2])];
    const double area = 0.5 * std::abs((q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]));
    for(int k = 0; k < 3; ++k) mass[std::size_t(t[k])] += area / 3;
    total += area;
  }
  double cost = 0;
  for(std::size_t i = 0; i < a.size(); ++i)
    cost += mass[i] / total * (std::pow(b[i][0] - a[i][0], 2) + std::pow(b[i][1] - a[i][1], 2));
  EXPECT_NEAR(d.transport_cost, std::sqrt(cost), 1e-13);
  // A collapsed face in b is left out and counted.
  b[7] = b[8];
  d = SMP::discrete_lie_flow_map_difference(xyz, a, b, g.faces);
  EXPECT_GT(d.faces_not_compared, 0u);
}

} // namespace dlf_test_paper_metrics
