// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The paper mode on the sphere: spherical Delaunay edge flips, and maps of
// closed genus-0 meshes of CGAL's data set. Every property of a result is
// recomputed here from the positions and the returned flowing triangulation
// (exact orientation and in-circle tests with CGAL's predicates, norms,
// D_area and solid angles in long double); the report is only compared
// against those recomputations.

#include <gtest/gtest.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_sphere_3.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/sphere/sphere_edge_flips.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <utility>
#include <vector>

// The tests compile in unity batches (DLF_UNITY_BUILD): each file keeps its
// names in a namespace of its own.
namespace dlf_test_sphere_paper {

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace D = CGAL::Surface_mesh_parameterization::internal::dlf;

namespace {

typedef CGAL::Simple_cartesian<double> K;
typedef CGAL::Surface_mesh<K::Point_3> SM;
typedef SM::Vertex_index SM_vertex;
typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
typedef std::array<double, 3> V3;
typedef std::array<int, 3> Tri;

Epick::Point_3 ep(const V3& q) { return Epick::Point_3(q[0], q[1], q[2]); }

V3 unit(double x, double y, double z)
{
  const double l = std::sqrt(x * x + y * y + z * z);
  return {{ x / l, y / l, z / l }};
}

SM read_mesh(const std::string& name)
{
  SM sm;
  EXPECT_TRUE(CGAL::Polygon_mesh_processing::IO::read_polygon_mesh(std::string(DLF_DATA_DIR) + "/meshes/" + name + ".off", sm))
    << name;
  return sm;
}

/// Exact counts of det[p, q, r] ≤ 0 over `faces`, with CGAL::orientation on Point_3.
std::size_t non_positive_faces(const std::vector<V3>& p, const std::vector<Tri>& faces)
{
  std::size_t bad = 0;
  for(const Tri& t : faces)
    if(CGAL::orientation(Epick::Point_3(CGAL::ORIGIN), ep(p[std::size_t(t[0])]), ep(p[std::size_t(t[1])]),
                         ep(p[std::size_t(t[2])])) != CGAL::POSITIVE)
      ++bad;
  return bad;
}

/// Edges whose opposite vertex lies strictly inside the spherical circumcircle
/// of the other face (the edge map is rebuilt here); -1 if the faces are not
/// a closed surface with every edge shared by two oppositely oriented faces.
long non_delaunay_edges(const std::vector<V3>& p, const std::vector<Tri>& faces)
{
  std::map<std::pair<int, int>, int> opposite; // directed edge → the third vertex of its face
  for(const Tri& t : faces)
    for(int k = 0; k < 3; ++k)
      if(!opposite.emplace(std::make_pair(t[(k + 1) % 3], t[(k + 2) % 3]), t[k]).second) return -1;
  long n = 0;
  for(const auto& e : opposite) {
    const auto o = opposite.find(std::make_pair(e.first.second, e.first.first));
    if(o == opposite.end()) return -1;
    if(e.first.first > e.first.second) continue;
    // face (a, b, c) = (third, from, to); d the other face's third vertex
    const int a = e.second, b = e.first.first, c = e.first.second, d = o->second;
    if(CGAL::orientation(ep(p[std::size_t(a)]), ep(p[std::size_t(b)]), ep(p[std::size_t(c)]), ep(p[std::size_t(d)])) ==
       CGAL::POSITIVE)
      ++n;
  }
  return n;
}

/// Solid angle of the spherical triangle (Van Oosterom–Strackee), long double.
long double solid_angle(const V3& a, const V3& b, const V3& c)
{
  typedef long double L;
  const L det = L(a[0]) * (L(b[1]) * c[2] - L(b[2]) * c[1]) - L(a[1]) * (L(b[0]) * c[2] - L(b[2]) * c[0]) +
                L(a[2]) * (L(b[0]) * c[1] - L(b[1]) * c[0]);
  const L den = 1 + (L(a[0]) * b[0] + L(a[1]) * b[1] + L(a[2]) * b[2]) + (L(b[0]) * c[0] + L(b[1]) * c[1] + L(b[2]) * c[2]) +
                (L(c[0]) * a[0] + L(c[1]) * a[1] + L(c[2]) * a[2]);
  return 2 * std::atan2(det, den);
}

long double flat_area(const V3& a, const V3& b, const V3& c)
{
  const long double u[3] = { (long double)b[0] - a[0], (long double)b[1] - a[1], (long double)b[2] - a[2] };
  const long double v[3] = { (long double)c[0] - a[0], (long double)c[1] - a[1], (long double)c[2] - a[2] };
  const long double x = u[1] * v[2] - u[2] * v[1], y = u[2] * v[0] - u[0] * v[2], z = u[0] * v[1] - u[1] * v[0];
  return 0.5L * std::sqrt(x * x + y * y + z * z);
}

/// D_area of the flat triangles between the sphere points over `faces`,
/// each against the 3D triangle between the same input vertices (ρ ≡ 1: the
/// flowing targets; at least 1e-3 times the smallest input face, the flow's
/// guard against a flip joining three collinear input vertices), in long double.
double d_area(const std::vector<V3>& xyz, const std::vector<V3>& p, const std::vector<Tri>& faces,
              const std::vector<Tri>& input_faces)
{
  long double smallest = std::numeric_limits<long double>::infinity();
  for(const Tri& t : input_faces)
    smallest = std::min(smallest, flat_area(xyz[std::size_t(t[0])], xyz[std::size_t(t[1])], xyz[std::size_t(t[2])]));
  long double A = 0, U = 0;
  std::vector<long double> a(faces.size()), u(faces.size());
  for(std::size_t f = 0; f < faces.size(); ++f) {
    const Tri& t = faces[f];
    a[f] = std::max(flat_area(xyz[std::size_t(t[0])], xyz[std::size_t(t[1])], xyz[std::size_t(t[2])]), 1e-3L * smallest);
    u[f] = flat_area(p[std::size_t(t[0])], p[std::size_t(t[1])], p[std::size_t(t[2])]);
    A += a[f]; U += u[f];
  }
  long double e = 0;
  for(std::size_t f = 0; f < faces.size(); ++f) {
    const long double r = (u[f] / U) / (a[f] / A);
    e += (a[f] / A) * (r + 1 / r);
  }
  return double(e);
}

// ---------------------------------------------------------------------------
// Spherical edge flips
// ---------------------------------------------------------------------------

// A quad near the north pole: faces (a, b, c) and (d, c, b) share the edge bc;
// the circumcircle of abc (seen from above) is about the unit circle of the
// tangent plane scaled by s, so d = (0, y) is inside it for |y| < 1.
D::Flip_triangulation quad(std::vector<V3>& p, double y)
{
  const double s = 0.1;
  p = { unit(0, s, 1), unit(-s, 0, 1), unit(s, 0, 1), unit(0, s * y, 1) };
  return D::Flip_triangulation({ {{ 0, 1, 2 }}, {{ 3, 2, 1 }} });
}

int shared_halfedge(const D::Flip_triangulation& tri)
{
  for(int h = 0; h < 6; ++h)
    if(tri.twin[std::size_t(h)] >= 0) return h;
  return -1;
}

TEST(Sphere_paper_flips, OppositeVertexInsideTheCircumcircleIsFlipped)
{
  std::vector<V3> p;
  D::Flip_triangulation tri = quad(p, -0.2);
  ASSERT_EQ(non_positive_faces(p, tri.faces), 0u);
  const int h = shared_halfedge(tri);
  EXPECT_FALSE(D::sphere_edge_is_locally_delaunay(tri, p, h));
  EXPECT_TRUE(D::sphere_flip_is_valid(tri, p, h));
  std::size_t changed = 0;
  EXPECT_EQ(D::make_delaunay_sphere(tri, p, [&](int) { ++changed; }, 100), 1u);
  EXPECT_EQ(changed, 2u);
  // Now the edge ad (vertices 0 and 3) is shared, both faces positive and Delaunay.
  EXPECT_EQ(non_positive_faces(p, tri.faces), 0u);
  EXPECT_EQ(D::count_non_delaunay_edges_sphere(tri, p), 0u);
  bool ad = false;
  for(const Tri& t : tri.faces) {
    int hits = 0;
    for(int v : t) hits += (v == 0 || v == 3);
    ad = ad || hits == 2;
  }
  EXPECT_TRUE(ad);
}

TEST(Sphere_paper_flips, OppositeVertexOutsideTheCircumcircleIsKept)
{
  std::vector<V3> p;
  D::Flip_triangulation tri = quad(p, -2);
  ASSERT_EQ(non_positive_faces(p, tri.faces), 0u);
  const std::vector<Tri> before = tri.faces;
  EXPECT_TRUE(D::sphere_edge_is_locally_delaunay(tri, p, shared_halfedge(tri)));
  EXPECT_EQ(D::make_delaunay_sphere(tri, p, [](int) {}, 100), 0u);
  EXPECT_EQ(tri.faces, before);
}

TEST(Sphere_paper_flips, FlipThatWouldFoldIsRefused)
{
  // d outside the circumcircle and the quad a, b, d, c reflex at b: the new
  // face (a, b, d) would be negative, so the flip is invalid whatever the test says.
  std::vector<V3> p;
  D::Flip_triangulation tri = quad(p, 0);
  const double s = 0.1;
  p[3] = unit(-1.5 * s, -0.1 * s, 1);
  ASSERT_EQ(non_positive_faces(p, tri.faces), 0u);
  EXPECT_FALSE(D::sphere_flip_is_valid(tri, p, shared_halfedge(tri)));
  EXPECT_TRUE(D::sphere_edge_is_locally_delaunay(tri, p, shared_halfedge(tri)));
  EXPECT_EQ(D::make_delaunay_sphere(tri, p, [](int) {}, 100), 0u);
}

TEST(Sphere_paper_flips, LawsonFlipsReachTheConvexHull)
{
  // sphere.off projected on the sphere, its vertices jittered tangentially
  // (keeping every face positive): the flips must reach the Delaunay
  // triangulation, i.e. every other point below the plane of every face.
  const SM sm = read_mesh("sphere");
  std::vector<V3> p;
  for(SM_vertex v : vertices(sm)) p.push_back(unit(sm.point(v).x(), sm.point(v).y(), sm.point(v).z()));
  std::vector<Tri> faces;
  for(auto f : CGAL::faces(sm)) {
    Tri t;
    int k = 0;
    for(SM_vertex v : vertices_around_face(halfedge(f, sm), sm)) t[k++] = int(v.idx());
    faces.push_back(t);
  }
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-0.06, 0.06);
  std::vector<V3> q = p;
  for(int attempt = 0; attempt < 20; ++attempt) {
    for(std::size_t i = 0; i < p.size(); ++i) q[i] = unit(p[i][0] + jitter(rng), p[i][1] + jitter(rng), p[i][2] + jitter(rng));
    if(non_positive_faces(q, faces) == 0) break;
  }
  ASSERT_EQ(non_positive_faces(q, faces), 0u);
  D::Flip_triangulation tri(faces);
  const long before = non_delaunay_edges(q, tri.faces);
  ASSERT_GT(before, 0);
  const std::size_t flips = D::make_delaunay_sphere(tri, q, [](int) {}, 100000);
  EXPECT_GE(flips, std::size_t(before));
  EXPECT_EQ(non_positive_faces(q, tri.faces), 0u);
  EXPECT_EQ(non_delaunay_edges(q, tri.faces), 0);
  std::size_t outside = 0;
  for(const Tri& t : tri.faces)
    for(std::size_t v = 0; v < q.size(); ++v) {
      if(int(v) == t[0] || int(v) == t[1] || int(v) == t[2]) continue;
      if(CGAL::orientation(ep(q[std::size_t(t[0])]), ep(q[std::size_t(t[1])]), ep(q[std::size_t(t[2])]), ep(q[v])) !=
         CGAL::NEGATIVE)
        ++outside;
    }
  EXPECT_EQ(outside, 0u);
}

// ---------------------------------------------------------------------------
// Maps of CGAL's closed genus-0 meshes
// ---------------------------------------------------------------------------

struct Paper_run
{
  SMP::Discrete_lie_flow_report report;
  std::vector<V3> xyz, p;
  std::vector<Tri> faces;
  double seconds = 0;
};

Paper_run run_paper(const std::string& name, SMP::Discrete_lie_flow_options options = SMP::Discrete_lie_flow_options())
{
  Paper_run r;
  SM sm = read_mesh(name);
  for(SM_vertex v : vertices(sm)) r.xyz.push_back({{ sm.point(v).x(), sm.point(v).y(), sm.point(v).z() }});
  for(auto f : CGAL::faces(sm)) {
    Tri t;
    int k = 0;
    for(SM_vertex v : vertices_around_face(halfedge(f, sm), sm)) t[k++] = int(v.idx());
    r.faces.push_back(t);
  }
  options.mode = SMP::Discrete_lie_flow_mode::PAPER;
  SM::Property_map<SM_vertex, K::Point_3> sphere = sm.add_property_map<SM_vertex, K::Point_3>("v:sphere", K::Point_3(7, 7, 7)).first;
  const auto t0 = std::chrono::steady_clock::now();
  r.report = SMP::discrete_lie_flow_sphere(sm, sphere, options);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  for(SM_vertex v : vertices(sm)) r.p.push_back({{ sphere[v].x(), sphere[v].y(), sphere[v].z() }});
  return r;
}

void check_paper_map(const std::string& name, double max_d_area, bool flips = true)
{
  SCOPED_TRACE(name);
  const Paper_run run = run_paper(name);
  const SMP::Discrete_lie_flow_report& R = run.report;
  ASSERT_EQ(R.status, SMP::OK) << R.message;
  EXPECT_NE(R.stop_reason, SMP::Discrete_lie_flow_stop_reason::NOT_RUN);
  EXPECT_GT(R.iterations, 0u);
  for(const V3& q : run.p) ASSERT_NEAR(std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]), 1., 1e-12);

  // The flowing triangulation: as many faces, closed genus 0, never folded,
  // covering the sphere exactly once, Delaunay where the flow says so.
  std::vector<Tri> flowing(R.domain_faces.begin(), R.domain_faces.end());
  ASSERT_EQ(flowing.size(), run.faces.size());
  EXPECT_TRUE(D::validate_sphere_topology(run.p.size(), flowing).ok());
  EXPECT_EQ(non_positive_faces(run.p, flowing), 0u);
  EXPECT_EQ(R.flowing_inverted_faces, 0u);
  long double omega = 0;
  for(const Tri& t : flowing) omega += solid_angle(run.p[std::size_t(t[0])], run.p[std::size_t(t[1])], run.p[std::size_t(t[2])]);
  EXPECT_NEAR(double(omega), 4 * M_PI, 1e-9);
  const long nd = non_delaunay_edges(run.p, flowing);
  EXPECT_EQ(nd, long(R.flowing_non_delaunay_edges));
  EXPECT_EQ(nd, 0);
  if(flips) { EXPECT_GT(R.flips, 0u); } // sphere.off is Delaunay from the start

  // D_area on the flowing triangulation, from the start down.
  const double D_flow = d_area(run.xyz, run.p, flowing, run.faces);
  EXPECT_NEAR(R.final_d_area, D_flow, 1e-9 * D_flow);
  EXPECT_LT(D_flow, R.initial_d_area);
  EXPECT_LE(D_flow, max_d_area);
  EXPECT_NEAR(R.initial_d_area, R.initial_metrics.d_area, 1e-6 * R.initial_d_area); // start: the input faces
  EXPECT_TRUE(std::isfinite(R.final_metrics.d_area));

  // The caller's triangles: folds counted, not refused.
  const std::size_t caller = non_positive_faces(run.p, run.faces);
  EXPECT_EQ(R.caller_inverted_faces, caller);
  std::cout << "[sphere paper] " << name << ": " << run.faces.size() << " faces, " << R.iterations << " iterations ("
            << SMP::discrete_lie_flow_stop_reason_name(R.stop_reason) << "), d_area " << R.initial_d_area << " -> " << D_flow
            << " (flowing), flips " << R.flips << ", caller folds " << caller << ", " << run.seconds << " s" << std::endl;
}

TEST(Sphere_paper_map, SphereAndEllipsoid)
{
  check_paper_map("sphere", 2.01, false);
  check_paper_map("ellipsoid", 2.01);
}

TEST(Sphere_paper_map, Blobby) { check_paper_map("blobby", 2.05); }
// The paper's flow plateaus on the legs and horns: it must improve on the
// start (D_area 1.02e6), certified, to the benchmark's figure (10.04 on the
// flowing triangulation, doc/sphere_paper_mode.md) within 10%.
TEST(Sphere_paper_map, Cow) { check_paper_map("cow", 11.); }

TEST(Sphere_paper_map, WithoutFlipsTheInputTriangulationFlows)
{
  SMP::Discrete_lie_flow_options o;
  o.paper.delaunay_flips = false;
  const Paper_run run = run_paper("blobby", o);
  const SMP::Discrete_lie_flow_report& R = run.report;
  ASSERT_EQ(R.status, SMP::OK) << R.message;
  EXPECT_EQ(R.flips, 0u);
  ASSERT_EQ(R.domain_faces.size(), run.faces.size());
  for(std::size_t f = 0; f < run.faces.size(); ++f) EXPECT_EQ(R.domain_faces[f], run.faces[f]);
  // Then the caller's triangles are the flowing ones: never folded.
  EXPECT_EQ(non_positive_faces(run.p, run.faces), 0u);
  EXPECT_EQ(R.caller_inverted_faces, 0u);
  EXPECT_LT(R.final_d_area, R.initial_d_area);
}

TEST(Sphere_paper_map, DensityGoesToTheFlowingFaces)
{
  // Density 4 on the faces whose centroid has z > 0.5: their share of the
  // sphere must move towards 4 A_in / (4 A_in + A_out).
  const SM sm = read_mesh("sphere");
  SMP::Discrete_lie_flow_options o;
  std::vector<bool> north;
  double in = 0, out = 0;
  for(auto f : CGAL::faces(sm)) {
    std::vector<K::Point_3> q;
    for(SM_vertex v : vertices_around_face(halfedge(f, sm), sm)) q.push_back(sm.point(v));
    const double z = (q[0].z() + q[1].z() + q[2].z()) / 3, a = std::sqrt(CGAL::squared_area(q[0], q[1], q[2]));
    north.push_back(z > 0.5);
    (north.back() ? in : out) += a;
    o.face_density.push_back(north.back() ? 4. : 1.);
  }
  const Paper_run run = run_paper("sphere", o);
  const SMP::Discrete_lie_flow_report& R = run.report;
  ASSERT_EQ(R.status, SMP::OK) << R.message;
  std::vector<Tri> flowing(R.domain_faces.begin(), R.domain_faces.end());
  EXPECT_EQ(non_positive_faces(run.p, flowing), 0u);
  EXPECT_LT(R.final_d_area, R.initial_d_area);
  long double share = 0, total = 0;
  for(std::size_t f = 0; f < run.faces.size(); ++f) {
    const Tri& t = run.faces[f];
    const long double a = flat_area(run.p[std::size_t(t[0])], run.p[std::size_t(t[1])], run.p[std::size_t(t[2])]);
    total += a;
    if(north[f]) share += a;
  }
  const double prescribed = 4 * in / (4 * in + out), uniform = in / (in + out);
  EXPECT_NEAR(double(share / total), prescribed, 0.1 * prescribed) << "uniform share " << uniform;
}

TEST(Sphere_paper_map, HistoryCallbackAndErrors)
{
  SMP::Discrete_lie_flow_options o;
  o.record_history = true;
  std::size_t calls = 0;
  o.callback = [&calls](const SMP::Discrete_lie_flow_iteration&) { return ++calls < 3; };
  const Paper_run run = run_paper("ellipsoid", o);
  const SMP::Discrete_lie_flow_report& R = run.report;
  ASSERT_EQ(R.status, SMP::OK) << R.message;
  EXPECT_EQ(R.stop_reason, SMP::Discrete_lie_flow_stop_reason::INTERRUPTED);
  EXPECT_EQ(R.iterations, 3u);
  ASSERT_EQ(R.history.size(), 3u);
  std::size_t flips = 0;
  for(const SMP::Discrete_lie_flow_iteration& it : R.history) {
    EXPECT_TRUE(std::isfinite(it.d_area));
    EXPECT_GT(it.step, 0.);
    flips += it.flips;
  }
  EXPECT_LE(flips, R.flips); // the final pass may add some
  // Input errors are those of the certified mode.
  for(const char* name : { "pipe", "nefertiti" }) { // a torus, an open mesh
    const Paper_run refused = run_paper(name);
    EXPECT_EQ(int(refused.report.status), int(SMP::ERROR_NOT_GENUS_0)) << refused.report.message;
    EXPECT_EQ(refused.report.stop_reason, SMP::Discrete_lie_flow_stop_reason::NOT_RUN);
    for(const V3& q : refused.p) EXPECT_EQ(q[0], 7.);
  }
}

} // namespace

} // namespace dlf_test_sphere_paper
