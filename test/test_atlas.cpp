// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// discrete_lie_flow_atlas(): on CGAL's closed meshes of genus 0, 1 and 3 and
// a mesh of 3 components, the per-corner map is checked independently of
// the library: every corner in the unit square, every triangle positive by
// the exact predicate, charts (found from the uv seams) with disjoint
// boxes and simple borders (so no overlap, inside or between charts), the
// whole atlas's D_area, no triangle with three corners on its chart's
// border where the atlas cut the mesh; a density gets its share; the gutter
// is kept; bad inputs give their error and leave the map untouched.

#include <gtest/gtest.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_atlas_3.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/atlas/atlas_score.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

// The tests compile in unity batches (DLF_UNITY_BUILD): each file keeps its
// names in a namespace of its own.
namespace dlf_test_atlas {

namespace SMP = CGAL::Surface_mesh_parameterization;

namespace {

typedef CGAL::Simple_cartesian<double> K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Halfedge_index H;
typedef CGAL::Exact_predicates_inexact_constructions_kernel EK;

std::string mesh_path(const std::string& name) { return std::string(DLF_DATA_DIR) + "/meshes/" + name + ".off"; }

Mesh load(const std::string& name)
{
  Mesh m;
  EXPECT_TRUE(CGAL::Polygon_mesh_processing::IO::read_polygon_mesh(mesh_path(name), m)) << name;
  return m;
}

typedef Mesh::Property_map<H, K::Point_2> UV_map;

UV_map uv_map(Mesh& m) { return m.add_property_map<H, K::Point_2>("h:uv", K::Point_2(-7, -7)).first; }

/// What the uv map says, found without the library: charts from the seams.
struct Atlas_check
{
  std::size_t outside = 0, inverted = 0, degenerate = 0;
  std::size_t charts = 0, overlapping_boxes = 0, crossing_border_edges = 0;
  std::size_t three_border_corner_faces = 0;
  double d_area = 0;
  double min_box_gap = 1; // the smallest gap between two charts' boxes (along x or y)
};

Atlas_check check_atlas(const Mesh& m, UV_map uv, const std::vector<double>& density = std::vector<double>())
{
  Atlas_check c;
  std::vector<H> corner; // 3f + k: the halfedge ending at corner k of face f
  for(auto f : faces(m))
    for(H h : halfedges_around_face(halfedge(f, m), m)) corner.push_back(h);
  const std::size_t F = num_faces(m);
  auto P2 = [&](H h) { return EK::Point_2(uv[h].x(), uv[h].y()); };
  long double A = 0, U = 0;
  std::vector<long double> a(F), u(F);
  for(std::size_t f = 0; f < F; ++f) {
    for(int k = 0; k < 3; ++k) {
      const K::Point_2& p = uv[corner[3 * f + k]];
      if(!(p.x() >= 0 && p.x() <= 1 && p.y() >= 0 && p.y() <= 1)) ++c.outside;
    }
    const CGAL::Orientation o = CGAL::orientation(P2(corner[3 * f]), P2(corner[3 * f + 1]), P2(corner[3 * f + 2]));
    if(o == CGAL::NEGATIVE) ++c.inverted;
    if(o == CGAL::ZERO) ++c.degenerate;
    const K::Point_3 &p = m.point(target(corner[3 * f], m)), &q = m.point(target(corner[3 * f + 1], m)),
                     &r = m.point(target(corner[3 * f + 2], m));
    a[f] = (density.empty() ? 1. : density[f]) * std::sqrt(CGAL::squared_area(p, q, r));
    const K::Point_2 &x = uv[corner[3 * f]], &y = uv[corner[3 * f + 1]], &z = uv[corner[3 * f + 2]];
    u[f] = std::fabs(0.5L * ((long double)(y.x() - x.x()) * (z.y() - x.y()) - (long double)(y.y() - x.y()) * (z.x() - x.x())));
    A += a[f];
    U += u[f];
  }
  for(std::size_t f = 0; f < F; ++f) {
    const long double w = a[f] / A, v = u[f] / U;
    c.d_area += double(v + w * w / v);
  }
  // Charts: faces joined across an edge whose two ends have the same uv on both sides.
  std::vector<std::size_t> root(F);
  std::iota(root.begin(), root.end(), std::size_t(0));
  auto find = [&root](std::size_t x) { while(root[x] != x) x = root[x] = root[root[x]]; return x; };
  std::map<H, std::size_t> face_index, corner_index;
  for(std::size_t i = 0; i < corner.size(); ++i) { face_index[corner[i]] = i / 3; corner_index[corner[i]] = i; }
  std::vector<char> on_chart_border(corner.size(), 0); // per corner (its target)
  std::vector<std::pair<H, H> > border_edges;          // chart border edges as (from corner, to corner)
  for(std::size_t i = 0; i < corner.size(); ++i) {
    const H h = corner[i];
    const H prev_h = prev(h, m);
    const H o = opposite(h, m);
    bool joined = false;
    if(!is_border(o, m)) { // the edge source(h) → target(h); across, o runs target → source
      const H o_prev = prev(o, m);
      joined = uv[h] == uv[o_prev] && uv[prev_h] == uv[o];
      if(joined) root[find(i / 3)] = find(face_index[o]);
    }
    if(!joined) {
      on_chart_border[i] = 1;
      on_chart_border[corner_index[prev_h]] = 1;
      border_edges.emplace_back(prev_h, h);
    }
  }
  std::map<std::size_t, std::array<double, 4> > box;
  for(std::size_t f = 0; f < F; ++f) {
    auto it = box.emplace(find(f), std::array<double, 4>{{ 2, 2, -1, -1 }}).first;
    for(int k = 0; k < 3; ++k) {
      const K::Point_2& p = uv[corner[3 * f + k]];
      it->second = {{ std::min(it->second[0], p.x()), std::min(it->second[1], p.y()), std::max(it->second[2], p.x()),
                      std::max(it->second[3], p.y()) }};
    }
    if(on_chart_border[3 * f] && on_chart_border[3 * f + 1] && on_chart_border[3 * f + 2]) ++c.three_border_corner_faces;
  }
  c.charts = box.size();
  std::vector<std::array<double, 4> > boxes;
  for(const auto& b : box) boxes.push_back(b.second);
  for(std::size_t i = 0; i < boxes.size(); ++i)
    for(std::size_t j = i + 1; j < boxes.size(); ++j) {
      const auto &p = boxes[i], &q = boxes[j];
      const double gap = std::max(std::max(q[0] - p[2], p[0] - q[2]), std::max(q[1] - p[3], p[1] - q[3]));
      if(gap < 0) ++c.overlapping_boxes;
      c.min_box_gap = std::min(c.min_box_gap, gap);
    }
  // Chart borders are simple: no two border edges of one chart cross (exact).
  std::map<std::size_t, std::vector<EK::Segment_2> > segments;
  for(const auto& e : border_edges) segments[find(face_index[e.second])].emplace_back(P2(e.first), P2(e.second));
  for(const auto& s : segments) {
    const std::vector<EK::Segment_2>& S = s.second;
    if(S.size() > 3000) continue; // quadratic check: the test meshes' charts stay below
    for(std::size_t i = 0; i < S.size(); ++i)
      for(std::size_t j = i + 1; j < S.size(); ++j) {
        const bool share = S[i].source() == S[j].source() || S[i].source() == S[j].target() ||
                           S[i].target() == S[j].source() || S[i].target() == S[j].target();
        if(share) continue; // consecutive edges, or the two sides of a seam at its tip
        if(CGAL::do_intersect(S[i], S[j])) ++c.crossing_border_edges;
      }
  }
  return c;
}

void expect_valid_atlas(const std::string& name, const SMP::Discrete_lie_flow_atlas_report& r, const Atlas_check& c,
                        bool cut_by_atlas)
{
  SCOPED_TRACE(name);
  ASSERT_EQ(r.code, SMP::OK) << r.message;
  EXPECT_TRUE(r.converged()) << r.unconverged_charts << " charts did not converge";
  EXPECT_TRUE(r.valid());
  EXPECT_EQ(c.outside, 0u);
  EXPECT_EQ(c.inverted, 0u);
  EXPECT_EQ(c.degenerate, 0u);
  EXPECT_EQ(c.overlapping_boxes, 0u);
  EXPECT_EQ(c.crossing_border_edges, 0u);
  EXPECT_EQ(c.charts, r.charts);
  EXPECT_LE(c.d_area, 2.02);
  EXPECT_NEAR(c.d_area, r.metrics.d_area, 1e-9);
  if(cut_by_atlas) EXPECT_EQ(c.three_border_corner_faces, 0u) << "the atlas's seams left triangles with three border corners";
  EXPECT_GT(r.packing_efficiency, 0.5);
}

struct Closed_case { const char* name; std::size_t genus; std::size_t components; };

class AtlasClosed : public ::testing::TestWithParam<Closed_case> {};

TEST_P(AtlasClosed, ValidCertifiedAreaPreservingAtlas)
{
  const Closed_case& k = GetParam();
  Mesh m = load(k.name);
  UV_map uv = uv_map(m);
  const SMP::Discrete_lie_flow_atlas_report r = SMP::discrete_lie_flow_atlas(m, uv);
  const Atlas_check c = check_atlas(m, uv);
  expect_valid_atlas(k.name, r, c, true);
  EXPECT_EQ(r.components, k.components);
  EXPECT_EQ(r.max_genus, k.genus);
  EXPECT_GT(r.seam_length, 0.);
  EXPECT_EQ(r.three_border_corner_faces, 0u);
  // Charts below the coarse-to-fine size flow toward the small-chart
  // tolerance (0.001; a chart may plateau just above it: eight, 2.0015),
  // far under the 2.005–2.009 these meshes get at the flow's 0.01.
  EXPECT_LE(r.metrics.d_area, 2 + 2 * SMP::Discrete_lie_flow_atlas_options().small_chart_tolerance);
}

INSTANTIATE_TEST_SUITE_P(CgalData, AtlasClosed,
                         ::testing::Values(Closed_case{ "cow", 0, 1 }, Closed_case{ "knot1", 1, 1 },
                                           Closed_case{ "elephant", 3, 1 }, Closed_case{ "eight", 2, 1 }),
                         [](const ::testing::TestParamInfo<Closed_case>& i) { return std::string(i.param.name); });

TEST(Atlas, EveryComponentOneChartAndTheGutterKept)
{
  // blobby_3cc.off: three components, each a disk or a disk with a hole.
  Mesh m = load("blobby_3cc");
  UV_map uv = uv_map(m);
  SMP::Discrete_lie_flow_atlas_options o;
  o.gutter = 0.01;
  const SMP::Discrete_lie_flow_atlas_report r = SMP::discrete_lie_flow_atlas(m, uv, o);
  const Atlas_check c = check_atlas(m, uv);
  expect_valid_atlas("blobby_3cc", r, c, false);
  EXPECT_EQ(r.components, 3u);
  EXPECT_EQ(c.charts, 3u);
  EXPECT_GE(c.min_box_gap, o.gutter);
  EXPECT_EQ(r.seam_length, 0.); // disks and holes are not cut
}

// Charts whose flows stop short (one iteration, a goal no flow reaches) and
// cannot be split or peeled are laid out triangle by triangle: the atlas
// still converges, every triangle a chart of its own where it had to be.
// (So an atlas stops short only if a one-triangle chart did; its message
// would name the first such chart's missed goal.)
TEST(Atlas, ChartsStoppedShortAreLaidOutTriangleByTriangle)
{
  Mesh m = load("blobby_3cc");
  UV_map uv = uv_map(m);
  SMP::Discrete_lie_flow_atlas_options o;
  o.flow.max_iterations = 1;
  o.flow.tolerance = 1e-9;
  o.max_split_depth = 0;
  o.max_border_peels = 0;
  const SMP::Discrete_lie_flow_atlas_report r = SMP::discrete_lie_flow_atlas(m, uv, o);
  ASSERT_EQ(r.code, SMP::OK) << r.message;
  EXPECT_TRUE(r.converged()) << r.message;
  EXPECT_EQ(r.unconverged_charts, 0u);
  EXPECT_EQ(r.message, "Success");
  EXPECT_TRUE(r.valid());
  EXPECT_EQ(r.peeled_faces, std::size_t(num_faces(m)));
  EXPECT_EQ(r.charts, std::size_t(num_faces(m)));
}

TEST(Atlas, DensityGetsItsShare)
{
  // Faces on one side of a plane get density 4: their uv area is 4 times
  // their share of the surface area.
  Mesh m = load("cow");
  UV_map uv = uv_map(m);
  SMP::Discrete_lie_flow_atlas_options o;
  std::vector<double> rho;
  double x_mid = 0;
  for(auto v : vertices(m)) x_mid += m.point(v).x() / double(num_vertices(m));
  for(auto f : faces(m)) rho.push_back(m.point(target(halfedge(f, m), m)).x() > x_mid ? 4. : 1.);
  o.flow.face_density = rho;
  const SMP::Discrete_lie_flow_atlas_report r = SMP::discrete_lie_flow_atlas(m, uv, o);
  ASSERT_EQ(r.code, SMP::OK) << r.message;
  const Atlas_check c = check_atlas(m, uv, rho);
  EXPECT_EQ(c.inverted + c.degenerate + c.overlapping_boxes, 0u);
  EXPECT_LE(c.d_area, 2.02);
  double a[2] = { 0, 0 }, u[2] = { 0, 0 };
  std::size_t f = 0;
  for(auto fd : faces(m)) {
    std::vector<H> hs;
    for(H h : halfedges_around_face(halfedge(fd, m), m)) hs.push_back(h);
    const int side = rho[f++] > 1 ? 1 : 0;
    a[side] += std::sqrt(CGAL::squared_area(m.point(target(hs[0], m)), m.point(target(hs[1], m)), m.point(target(hs[2], m))));
    u[side] += CGAL::area(uv[hs[0]], uv[hs[1]], uv[hs[2]]);
  }
  EXPECT_NEAR((u[1] / a[1]) / (u[0] / a[0]), 4., 0.1);
}

TEST(Atlas, BadInputsGiveTheirErrorAndLeaveTheMapAlone)
{
  {
    Mesh m;
    UV_map uv = uv_map(m);
    const auto r = SMP::discrete_lie_flow_atlas(m, uv);
    EXPECT_EQ(r.code, SMP::ERROR_EMPTY_MESH);
    EXPECT_NE(r.message.find("no faces"), std::string::npos) << r.message;
  }
  {
    Mesh m; // a point cloud
    for(int i = 0; i < 5; ++i) m.add_vertex(K::Point_3(i, i * i, 0));
    UV_map uv = uv_map(m);
    const auto r = SMP::discrete_lie_flow_atlas(m, uv);
    EXPECT_EQ(r.code, SMP::ERROR_EMPTY_MESH);
    EXPECT_NE(r.message.find("5 vertices"), std::string::npos) << r.message;
  }
  {
    Mesh m; // every face degenerate: collinear corners
    auto a = m.add_vertex(K::Point_3(0, 0, 0)), b = m.add_vertex(K::Point_3(1, 0, 0)), c = m.add_vertex(K::Point_3(2, 0, 0)),
         d = m.add_vertex(K::Point_3(3, 0, 0));
    m.add_face(a, b, c);
    m.add_face(a, c, d);
    UV_map uv = uv_map(m);
    const auto r = SMP::discrete_lie_flow_atlas(m, uv);
    EXPECT_EQ(r.code, SMP::Error_code(SMP::ERROR_DEGENERATE_INPUT));
    EXPECT_NE(r.message.find("all 2 faces"), std::string::npos) << r.message;
    for(H h : halfedges(m)) EXPECT_EQ(uv[h], K::Point_2(-7, -7));
  }
  {
    Mesh m; // one degenerate face among good ones: named
    auto a = m.add_vertex(K::Point_3(0, 0, 0)), b = m.add_vertex(K::Point_3(1, 0, 0)), c = m.add_vertex(K::Point_3(0, 1, 0)),
         d = m.add_vertex(K::Point_3(2, 0, 0));
    m.add_face(a, b, c);
    m.add_face(a, d, b);
    UV_map uv = uv_map(m);
    const auto r = SMP::discrete_lie_flow_atlas(m, uv);
    EXPECT_EQ(r.code, SMP::Error_code(SMP::ERROR_DEGENERATE_INPUT));
    EXPECT_NE(r.message.find("face 1"), std::string::npos) << r.message;
  }
  {
    Mesh m = load("cube_quad"); // quadrilaterals
    UV_map uv = uv_map(m);
    const auto r = SMP::discrete_lie_flow_atlas(m, uv);
    EXPECT_EQ(r.code, SMP::ERROR_NON_TRIANGULAR_MESH);
    for(H h : halfedges(m)) EXPECT_EQ(uv[h], K::Point_2(-7, -7));
  }
  {
    Mesh m = load("cow");
    UV_map uv = uv_map(m);
    SMP::Discrete_lie_flow_atlas_options o;
    o.flow.mode = SMP::Discrete_lie_flow_mode::PAPER;
    EXPECT_EQ(SMP::discrete_lie_flow_atlas(m, uv, o).code, SMP::ERROR_WRONG_PARAMETER);
    o = SMP::Discrete_lie_flow_atlas_options();
    o.flow.face_density.assign(3, 1.);
    EXPECT_EQ(SMP::discrete_lie_flow_atlas(m, uv, o).code, SMP::Error_code(SMP::ERROR_INVALID_DENSITY));
  }
}

TEST(Atlas, TinyClosedMeshOneChartPerTriangle)
{
  // A tetrahedron has no seam that keeps a triangle between its sides.
  Mesh m = load("tetrahedron");
  UV_map uv = uv_map(m);
  const auto r = SMP::discrete_lie_flow_atlas(m, uv);
  const Atlas_check c = check_atlas(m, uv);
  ASSERT_EQ(r.code, SMP::OK) << r.message;
  EXPECT_EQ(c.inverted + c.degenerate + c.overlapping_boxes + c.outside, 0u);
  EXPECT_LE(c.d_area, 2.02);
}

TEST(Atlas, CutsLeaveOneDiskWithoutThreeBorderCornerTriangles)
{
  // The seam of genus-g pieces through the internal cut: one disk, and no
  // triangle between two seams.
  namespace D = CGAL::Surface_mesh_parameterization::internal::dlf;
  for(const char* name : { "knot1", "elephant", "eight", "cow" }) {
    Mesh m = load(name);
    D::Atlas_piece P;
    for(auto v : vertices(m)) P.xyz.push_back({{ m.point(v).x(), m.point(v).y(), m.point(v).z() }});
    for(auto f : faces(m)) {
      D::Face t;
      int k = 0;
      for(auto v : vertices_around_face(halfedge(f, m), m)) t[k++] = int(v);
      P.faces.push_back(t);
      P.caller_face.push_back(P.faces.size() - 1);
    }
    const std::vector<long> twin = D::halfedge_twins(P.faces);
    const D::Piece_topology T = D::piece_topology(P, twin);
    double length = 0;
    const std::vector<char> seam = D::piece_seam(P, twin, T, 4, length);
    D::Atlas_piece opened = P;
    D::open_along(opened, twin, seam);
    const std::vector<long> t2 = D::halfedge_twins(opened.faces);
    std::vector<int> component;
    EXPECT_EQ(D::face_components(opened.faces, t2, component), 1u) << name;
    EXPECT_TRUE(D::piece_topology(opened, t2).disk()) << name;
    EXPECT_EQ(D::three_border_corner_faces(opened, t2), 0u) << name;
    EXPECT_GT(length, 0.) << name;
  }
}

TEST(Atlas, TrianglesFixedByTheBorderBecomeChartsOfTheirOwn)
{
  // A grid with tall ears on one side (a jagged border): an ear has its
  // three corners on the border, which fixes its area, so the chart cannot
  // converge; the ears are peeled off (a chart each) and the grid converges.
  Mesh m;
  const int n = 8;
  std::vector<Mesh::Vertex_index> v;
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i) v.push_back(m.add_vertex(K::Point_3(i, j, 0.3 * std::sin(0.9 * i + 0.5 * j))));
  for(int j = 0; j + 1 < n; ++j)
    for(int i = 0; i + 1 < n; ++i) {
      m.add_face(v[j * n + i], v[j * n + i + 1], v[(j + 1) * n + i + 1]);
      m.add_face(v[j * n + i], v[(j + 1) * n + i + 1], v[(j + 1) * n + i]);
    }
  for(int i = 0; i + 1 < n; ++i) {
    const Mesh::Vertex_index e = m.add_vertex(K::Point_3(i + 0.5, -1.5 - (i % 3), 0));
    m.add_face(v[i], e, v[i + 1]);
  }
  ASSERT_EQ(num_faces(m), 105u);
  SMP::Discrete_lie_flow_atlas_options o;
  o.max_split_depth = 0; // the peel alone
  UV_map uv = uv_map(m);
  const SMP::Discrete_lie_flow_atlas_report r = SMP::discrete_lie_flow_atlas(m, uv, o);
  const Atlas_check c = check_atlas(m, uv);
  ASSERT_EQ(r.code, SMP::OK) << r.message;
  EXPECT_TRUE(r.converged());
  EXPECT_TRUE(r.valid());
  EXPECT_EQ(c.outside + c.inverted + c.degenerate + c.overlapping_boxes, 0u);
  EXPECT_EQ(r.peeled_faces, 9u); // the 7 ears and the grid's 2 corner triangles
  EXPECT_EQ(r.charts, 10u);
  EXPECT_EQ(c.charts, r.charts);
  EXPECT_LE(r.metrics.d_area, 2.02);
}

TEST(Atlas, ChartsThatCannotConvergeNorSplitBecomeTriangles)
{
  // A grid whose cells grow a thousandfold across it, its flow capped at
  // one iteration, no split and no peel allowed: the chart stops far from
  // its tolerance, so each triangle becomes a chart, laid out isometrically.
  Mesh m;
  const int n = 8;
  std::vector<Mesh::Vertex_index> v;
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i) v.push_back(m.add_vertex(K::Point_3(0.01 * i * i * i * i, 0.05 * j * j * j, 0)));
  for(int j = 0; j + 1 < n; ++j)
    for(int i = 0; i + 1 < n; ++i) {
      m.add_face(v[j * n + i], v[j * n + i + 1], v[(j + 1) * n + i + 1]);
      m.add_face(v[j * n + i], v[(j + 1) * n + i + 1], v[(j + 1) * n + i]);
    }
  ASSERT_EQ(num_faces(m), 98u);
  SMP::Discrete_lie_flow_atlas_options o;
  o.flow.max_iterations = 1;
  o.max_split_depth = 0;
  o.max_border_peels = 0;
  UV_map uv = uv_map(m);
  const SMP::Discrete_lie_flow_atlas_report r = SMP::discrete_lie_flow_atlas(m, uv, o);
  const Atlas_check c = check_atlas(m, uv);
  ASSERT_EQ(r.code, SMP::OK) << r.message;
  EXPECT_TRUE(r.converged());
  EXPECT_TRUE(r.valid());
  EXPECT_EQ(c.outside + c.inverted + c.degenerate + c.overlapping_boxes, 0u);
  EXPECT_EQ(r.peeled_faces, 98u);
  EXPECT_EQ(r.charts, 98u);
  EXPECT_EQ(c.charts, r.charts);
  EXPECT_NEAR(r.metrics.d_area, 2., 1e-9); // each triangle isometric
}

TEST(Atlas, HalfedgeTwinsPairOnlyEdgesOfTwoConsistentFaces)
{
  namespace D = SMP::internal::dlf;
  // A 9×9 grid of vertices with every third face flipped, a face repeating
  // a directed edge, and an edge of three faces; against a plain map of
  // directed edges: a halfedge a → b has a twin when a → b and b → a occur
  // once each.
  std::vector<D::Face> F;
  const int n = 9;
  for(int j = 0; j + 1 < n; ++j)
    for(int i = 0; i + 1 < n; ++i) {
      const int a = j * n + i, b = a + 1, c = a + n + 1, d = a + n;
      F.push_back(F.size() % 3 == 2 ? D::Face{{ a, c, b }} : D::Face{{ a, b, c }});
      F.push_back(D::Face{{ a, c, d }});
    }
  F.push_back(D::Face{{ 0, 1, 100 }});  // 0 → 1 once more
  F.push_back(D::Face{{ 101, 102, 103 }});
  F.push_back(D::Face{{ 102, 101, 104 }});
  F.push_back(D::Face{{ 102, 101, 105 }}); // 102 → 101 twice: an edge of three faces
  std::map<std::pair<int, int>, std::vector<long> > directed;
  for(std::size_t h = 0; h < 3 * F.size(); ++h) directed[{ F[h / 3][h % 3], F[h / 3][(h % 3 + 1) % 3] }].push_back(long(h));
  const std::vector<long> twin = D::halfedge_twins(F);
  ASSERT_EQ(twin.size(), 3 * F.size());
  std::size_t paired = 0;
  for(std::size_t h = 0; h < twin.size(); ++h) {
    const int a = F[h / 3][h % 3], b = F[h / 3][(h % 3 + 1) % 3];
    const std::vector<long>& self = directed[{ a, b }];
    const auto other = directed.find({ b, a });
    const long expected = self.size() == 1 && other != directed.end() && other->second.size() == 1 ? other->second[0] : -1;
    EXPECT_EQ(twin[h], expected) << "halfedge " << h << " (" << a << " -> " << b << ")";
    paired += twin[h] >= 0;
  }
  EXPECT_GT(paired, 200u);
  EXPECT_EQ(twin[0], -1); // 0 → 1 repeated
  EXPECT_EQ(twin[3 * (F.size() - 3)], -1); // 101 → 102 against two 102 → 101
}

TEST(Atlas, IterationCallbackOnlyForChartsOfCallbackFaces)
{
  // knot1 (6,400 faces, one chart): its flow's iterations reach the
  // callback with callback_faces at most its size, none above.
  for(const std::size_t limit : { std::size_t(0), std::size_t(6400), std::size_t(6401) }) {
    Mesh m = load("knot1");
    UV_map uv = uv_map(m);
    SMP::Discrete_lie_flow_atlas_options o;
    std::size_t calls = 0;
    o.flow.callback = [&calls](const SMP::Discrete_lie_flow_iteration&) { ++calls; return true; };
    o.callback_faces = limit;
    const SMP::Discrete_lie_flow_atlas_report r = SMP::discrete_lie_flow_atlas(m, uv, o);
    ASSERT_EQ(r.charts, 1u);
    if(limit <= 6400) {
      EXPECT_EQ(calls, r.chart_reports[0].iterations) << limit;
      EXPECT_GT(calls, 0u) << limit;
    }
    else
      EXPECT_EQ(calls, 0u);
  }
}

TEST(AtlasScore, ChartsSeamsFoldsAndOverlapsOfAnyAtlas)
{
  // The scorer of other tools' atlases: a square of two triangles (chart A),
  // a third triangle on its own uv (chart B) laid over A, a fourth mirrored
  // as a whole (chart C, not a fold) and A's second triangle folded back.
  namespace D = CGAL::Surface_mesh_parameterization::internal::dlf;
  const std::vector<D::Vec3> xyz = { {{ 0, 0, 0 }}, {{ 1, 0, 0 }}, {{ 1, 1, 0 }}, {{ 0, 1, 0 }}, {{ 2, 0, 0 }}, {{ 0, 2, 0 }} };
  const std::vector<D::Face> faces = { {{ 0, 1, 2 }}, {{ 0, 2, 3 }}, {{ 1, 4, 2 }}, {{ 3, 2, 5 }} };
  std::vector<D::Vec2> uv = { {{ 0, 0 }}, {{ 1, 0 }}, {{ 1, 1 }}, {{ 0, 1 }},       // A
                              {{ 0.5, 0.2 }}, {{ 1.5, 0.2 }}, {{ 1.5, 1.2 }},       // B: over A's first triangle
                              {{ 5, 5 }}, {{ 6, 5 }}, {{ 5, 4 }} };                // C: clockwise
  std::vector<D::Face> uv_faces = { {{ 0, 1, 2 }}, {{ 0, 2, 3 }}, {{ 4, 5, 6 }}, {{ 7, 8, 9 }} };
  D::Atlas_score S = D::score_atlas(xyz, faces, uv, uv_faces);
  EXPECT_EQ(S.charts, 3u);
  EXPECT_EQ(S.mirrored_charts, 1u);
  EXPECT_EQ(S.inverted_faces, 0u);
  EXPECT_EQ(S.overlapping_face_pairs, 1u); // B over A's first triangle; A's two triangles only touch
  EXPECT_EQ(S.overlapping_pairs_in_a_chart, 0u);
  EXPECT_NEAR(S.seam_length, 2., 1e-12); // edges 1-2 and 2-3 (no border edge counted)
  // Fold A's second triangle over its first: one inverted face, one overlap inside the chart.
  uv[3] = {{ 0.9, 0.1 }};
  S = D::score_atlas(xyz, faces, uv, uv_faces);
  EXPECT_EQ(S.inverted_faces, 1u);
  EXPECT_EQ(S.overlapping_pairs_in_a_chart, 1u);
  EXPECT_EQ(S.overlapping_face_pairs, 3u); // and B over both of A's
  // Triangles touching at a vertex or along an edge do not overlap.
  uv[3] = {{ 0, 1 }};
  uv[4] = {{ 1, 1 }}; uv[5] = {{ 2, 1 }}; uv[6] = {{ 2, 2 }};
  S = D::score_atlas(xyz, faces, uv, uv_faces);
  EXPECT_EQ(S.overlapping_face_pairs, 0u);
  EXPECT_NEAR(S.packing_efficiency, S.uv_area / (6. * 5.), 1e-12);
}

} // namespace

} // namespace dlf_test_atlas
