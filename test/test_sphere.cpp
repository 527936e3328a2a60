// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The spherical Discrete Lie Flow: validation of the input (closed,
// connected, genus 0, triangles, non-degenerate), the certified initial map,
// the cubic critical root against bisection of the determinant, and maps of
// closed genus-0 meshes of CGAL's data set. Every property of a result is
// recomputed here from the positions (exact orientation with CGAL's
// predicates, norms, D_area in long double); the report is only compared
// against those recomputations.

#include <gtest/gtest.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/subdivision_method_3.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_sphere_3.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/sphere/sphere_certified_flow.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/sphere/sphere_coarse_to_fine.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/sphere/sphere_spherical_area.h>

#include "../benchmark/irregular_meshes.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

// The tests compile in unity batches (DLF_UNITY_BUILD): each file keeps its
// names in a namespace of its own.
namespace dlf_test_sphere {

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace D = CGAL::Surface_mesh_parameterization::internal::dlf;

namespace {

typedef CGAL::Simple_cartesian<double> K;
typedef CGAL::Surface_mesh<K::Point_3> SM;
typedef SM::Vertex_index SM_vertex;
typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
typedef std::array<double, 3> V3;
typedef std::array<int, 3> Tri;

std::string sphere_mesh_path(const std::string& name) { return std::string(DLF_DATA_DIR) + "/meshes/" + name + ".off"; }

SM read_sphere_mesh(const std::string& name)
{
  SM sm;
  EXPECT_TRUE(CGAL::Polygon_mesh_processing::IO::read_polygon_mesh(sphere_mesh_path(name), sm)) << name;
  return sm;
}

struct Index_mesh
{
  std::vector<V3> xyz;
  std::vector<Tri> faces;
};

Index_mesh index_mesh(const SM& sm)
{
  Index_mesh m;
  for(SM_vertex v : vertices(sm)) m.xyz.push_back({{ sm.point(v).x(), sm.point(v).y(), sm.point(v).z() }});
  for(auto f : faces(sm)) {
    Tri t;
    int k = 0;
    for(SM_vertex v : vertices_around_face(halfedge(f, sm), sm)) t[k++] = int(v.idx());
    m.faces.push_back(t);
  }
  return m;
}

/// Exact signs of det[p, q, r] (the orientation seen from the centre).
struct Sphere_signs { std::size_t pos = 0, neg = 0, zero = 0; };
Sphere_signs exact_sphere_signs(const std::vector<V3>& p, const std::vector<Tri>& faces)
{
  Sphere_signs s;
  const Epick::Point_3 O(0, 0, 0);
  for(const Tri& t : faces) {
    const V3 &a = p[std::size_t(t[0])], &b = p[std::size_t(t[1])], &c = p[std::size_t(t[2])];
    const CGAL::Orientation o = CGAL::orientation(O, Epick::Point_3(a[0], a[1], a[2]), Epick::Point_3(b[0], b[1], b[2]),
                                                  Epick::Point_3(c[0], c[1], c[2]));
    if(o == CGAL::POSITIVE) ++s.pos; else if(o == CGAL::NEGATIVE) ++s.neg; else ++s.zero;
  }
  return s;
}

long double flat_area(const V3& a, const V3& b, const V3& c)
{
  const long double u[3] = { (long double)b[0] - a[0], (long double)b[1] - a[1], (long double)b[2] - a[2] };
  const long double v[3] = { (long double)c[0] - a[0], (long double)c[1] - a[1], (long double)c[2] - a[2] };
  const long double x = u[1] * v[2] - u[2] * v[1], y = u[2] * v[0] - u[0] * v[2], z = u[0] * v[1] - u[1] * v[0];
  return 0.5L * std::sqrt(x * x + y * y + z * z);
}

/// D_area of doc/design.md on the flat triangles between the sphere points,
/// and the mean |log area ratio|, recomputed in long double.
std::pair<double, double> sphere_d_area(const std::vector<V3>& xyz, const std::vector<V3>& p, const std::vector<Tri>& faces)
{
  long double A = 0, U = 0;
  std::vector<long double> a(faces.size()), u(faces.size());
  for(std::size_t f = 0; f < faces.size(); ++f) {
    const Tri& t = faces[f];
    a[f] = flat_area(xyz[std::size_t(t[0])], xyz[std::size_t(t[1])], xyz[std::size_t(t[2])]);
    u[f] = flat_area(p[std::size_t(t[0])], p[std::size_t(t[1])], p[std::size_t(t[2])]);
    A += a[f]; U += u[f];
  }
  long double e = 0, l = 0;
  for(std::size_t f = 0; f < faces.size(); ++f) {
    const long double r = (u[f] / U) / (a[f] / A);
    e += (a[f] / A) * (r + 1 / r);
    l += std::fabs(std::log(r));
  }
  return std::make_pair(double(e), double(l / faces.size()));
}

/// Runs the public entry point on `sm`; returns the report and the sphere points (vertex order).
SMP::Discrete_lie_flow_report map_to_sphere(const SM& sm, std::vector<V3>& p,
                                                   const SMP::Discrete_lie_flow_options& options = SMP::Discrete_lie_flow_options())
{
  SM copy = sm;
  SM::Property_map<SM_vertex, K::Point_3> sphere = copy.add_property_map<SM_vertex, K::Point_3>("v:sphere", K::Point_3(7, 7, 7)).first;
  const SMP::Discrete_lie_flow_report r = SMP::discrete_lie_flow_sphere(copy, sphere, options);
  p.clear();
  for(SM_vertex v : vertices(copy)) p.push_back({{ sphere[v].x(), sphere[v].y(), sphere[v].z() }});
  return r;
}

// ---------------------------------------------------------------------------
// Validation
// ---------------------------------------------------------------------------

void expect_refused(const std::string& name, int code, const std::string& words)
{
  SCOPED_TRACE(name);
  const SM sm = read_sphere_mesh(name);
  std::vector<V3> p;
  const SMP::Discrete_lie_flow_report r = map_to_sphere(sm, p);
  EXPECT_EQ(int(r.status), code) << r.message;
  EXPECT_NE(r.message.find(words), std::string::npos) << r.message;
  EXPECT_EQ(r.stop_reason, SMP::Discrete_lie_flow_stop_reason::NOT_RUN);
  for(const V3& q : p) EXPECT_EQ(q[0], 7.); // nothing written
}

TEST(Sphere_validation, TorusIsRefused)
{
  expect_refused("pipe", SMP::ERROR_NOT_GENUS_0, "Euler characteristic 0");
  expect_refused("pipe", SMP::ERROR_NOT_GENUS_0, "genus 1");
  expect_refused("mpi_triang", SMP::ERROR_NOT_GENUS_0, "Euler characteristic");
}

TEST(Sphere_validation, OpenMeshIsRefused)
{
  expect_refused("nefertiti", SMP::ERROR_NOT_GENUS_0, "border edges");
}

TEST(Sphere_validation, SeveralComponentsAreRefused)
{
  expect_refused("blobby_3cc", SMP::ERROR_NOT_GENUS_0, "3 components");
  // Two disjoint tetrahedra: each is closed and genus 0, together they are not.
  SM sm = read_sphere_mesh("tetrahedron");
  SM other = sm;
  for(SM_vertex v : vertices(other)) other.point(v) = other.point(v) + K::Vector_3(5, 0, 0);
  sm.join(other);
  std::vector<V3> p;
  const SMP::Discrete_lie_flow_report r = map_to_sphere(sm, p);
  EXPECT_EQ(int(r.status), int(SMP::ERROR_NOT_GENUS_0));
  EXPECT_NE(r.message.find("2 components"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("Euler characteristic 4"), std::string::npos) << r.message;
}

TEST(Sphere_validation, QuadsAreRefused)
{
  expect_refused("cube_quad", SMP::ERROR_NON_TRIANGULAR_MESH, "has 4 vertices");
}

TEST(Sphere_validation, ZeroAreaFaceIsNamed)
{
  // Move a vertex of the octahedron onto the segment between two others of
  // one of its faces: that face has zero area.
  SM sm = read_sphere_mesh("octahedron");
  const Index_mesh m = index_mesh(sm);
  const Tri t = m.faces[3];
  const K::Point_3 a = sm.point(SM_vertex(SM::size_type(t[0]))), b = sm.point(SM_vertex(SM::size_type(t[1])));
  sm.point(SM_vertex(SM::size_type(t[2]))) = CGAL::midpoint(a, b);
  std::vector<V3> p;
  const SMP::Discrete_lie_flow_report r = map_to_sphere(sm, p);
  EXPECT_EQ(int(r.status), int(SMP::ERROR_DEGENERATE_INPUT));
  EXPECT_NE(r.message.find("zero area"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("face "), std::string::npos) << r.message;
}

TEST(Sphere_validation, NonFiniteVertexIsNamed)
{
  SM sm = read_sphere_mesh("sphere");
  sm.point(SM_vertex(17)) = K::Point_3(std::numeric_limits<double>::quiet_NaN(), 0, 0);
  std::vector<V3> p;
  const SMP::Discrete_lie_flow_report r = map_to_sphere(sm, p);
  EXPECT_EQ(int(r.status), int(SMP::ERROR_DEGENERATE_INPUT));
  EXPECT_NE(r.message.find("vertex 17"), std::string::npos) << r.message;
  for(const V3& q : p) EXPECT_EQ(q[0], 7.);
}

TEST(Sphere_validation, DensityAndModeAreChecked)
{
  const SM sm = read_sphere_mesh("sphere");
  std::vector<V3> p;
  SMP::Discrete_lie_flow_options o;
  o.face_density.assign(10, 1.);
  EXPECT_EQ(int(map_to_sphere(sm, p, o).status), int(SMP::ERROR_INVALID_DENSITY));
  o.face_density.assign(num_faces(sm), 1.);
  o.face_density[5] = -1;
  SMP::Discrete_lie_flow_report r = map_to_sphere(sm, p, o);
  EXPECT_EQ(int(r.status), int(SMP::ERROR_INVALID_DENSITY));
  EXPECT_NE(r.message.find("face 5"), std::string::npos) << r.message;
  // The paper mode validates the same way.
  o.mode = SMP::Discrete_lie_flow_mode::PAPER;
  r = map_to_sphere(sm, p, o);
  EXPECT_EQ(int(r.status), int(SMP::ERROR_INVALID_DENSITY));
  EXPECT_NE(r.message.find("face 5"), std::string::npos) << r.message;
  EXPECT_EQ(r.stop_reason, SMP::Discrete_lie_flow_stop_reason::NOT_RUN);
}

TEST(Sphere_validation, TopologyInIndexForm)
{
  // A tetrahedron is a sphere; with one face removed it is a disk; with a
  // face reversed it is not consistently oriented.
  std::vector<D::Face> tet = { {{ 0, 2, 1 }}, {{ 0, 1, 3 }}, {{ 1, 2, 3 }}, {{ 0, 3, 2 }} };
  EXPECT_TRUE(D::validate_sphere_topology(4, tet).ok());
  std::vector<D::Face> open(tet.begin(), tet.begin() + 3);
  D::Validation v = D::validate_sphere_topology(4, open);
  EXPECT_EQ(v.code, int(SMP::ERROR_NOT_GENUS_0));
  EXPECT_NE(v.message.find("3 border edges"), std::string::npos) << v.message;
  std::vector<D::Face> flipped = tet;
  std::swap(flipped[2][0], flipped[2][1]);
  v = D::validate_sphere_topology(4, flipped);
  EXPECT_EQ(v.code, int(SMP::ERROR_NOT_GENUS_0));
  EXPECT_NE(v.message.find("inconsistently oriented"), std::string::npos) << v.message;
  v = D::validate_sphere_topology(5, tet);
  EXPECT_NE(v.message.find("1 isolated vertices"), std::string::npos) << v.message;
}

// ---------------------------------------------------------------------------
// The cubic critical root of det[p_k + λ t_k]
// ---------------------------------------------------------------------------

long double det_along(const V3& p0, const V3& p1, const V3& p2, const V3& t0, const V3& t1, const V3& t2, long double l)
{
  long double a[3], b[3], c[3];
  for(int j = 0; j < 3; ++j) {
    a[j] = (long double)p0[j] + l * t0[j];
    b[j] = (long double)p1[j] + l * t1[j];
    c[j] = (long double)p2[j] + l * t2[j];
  }
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
}

/// The first λ in (0, L] where the determinant stops being positive, by a
/// fine scan and bisection; +∞ if it stays positive.
double bisected_root(const V3& p0, const V3& p1, const V3& p2, const V3& t0, const V3& t1, const V3& t2, double L)
{
  const int samples = 20000;
  long double lo = 0;
  for(int k = 1; k <= samples; ++k) {
    const long double x = (long double)L * k / samples;
    if(det_along(p0, p1, p2, t0, t1, t2, x) <= 0) {
      long double hi = x;
      for(int it = 0; it < 200 && hi - lo > 1e-18L * hi; ++it) {
        const long double mid = 0.5L * (lo + hi);
        if(det_along(p0, p1, p2, t0, t1, t2, mid) > 0) lo = mid; else hi = mid;
      }
      return double(hi);
    }
    lo = x;
  }
  return std::numeric_limits<double>::infinity();
}

V3 random_unit(std::mt19937& rng)
{
  std::normal_distribution<double> N(0, 1);
  return D::normalized(V3{{ N(rng), N(rng), N(rng) }});
}

V3 random_tangent(const V3& p, double scale, std::mt19937& rng)
{
  std::normal_distribution<double> N(0, scale);
  V3 t{{ N(rng), N(rng), N(rng) }};
  const double s = D::dot(t, p);
  for(int j = 0; j < 3; ++j) t[j] -= s * p[j];
  return t;
}

TEST(Sphere_cubic, RandomTrianglesAgainstBisection)
{
  std::mt19937 rng(5);
  int with_root = 0;
  for(int trial = 0; trial < 300; ++trial) {
    // Small positively oriented triangles around a random point, random tangent motions.
    const V3 c = random_unit(rng);
    const double size = std::pow(10., -double(trial % 4));
    V3 p[3];
    for(int k = 0; k < 3; ++k) {
      const V3 o = random_tangent(c, size, rng);
      p[k] = D::normalized(V3{{ c[0] + o[0], c[1] + o[1], c[2] + o[2] }});
    }
    if(det_along(p[0], p[1], p[2], V3{{ 0, 0, 0 }}, V3{{ 0, 0, 0 }}, V3{{ 0, 0, 0 }}, 0) < 0) std::swap(p[1], p[2]);
    V3 t[3];
    for(int k = 0; k < 3; ++k) t[k] = random_tangent(p[k], size, rng);
    const double r = D::critical_step_sphere(p[0], p[1], p[2], t[0], t[1], t[2]);
    const double b = bisected_root(p[0], p[1], p[2], t[0], t[1], t[2], 10.);
    if(std::isinf(b)) {
      EXPECT_TRUE(r > 10. * (1 - 1e-9)) << "trial " << trial << ": root " << r << " where bisection finds none in (0, 10]";
    } else {
      ++with_root;
      EXPECT_NEAR(r, b, 1e-7 * b) << "trial " << trial;
    }
  }
  EXPECT_GT(with_root, 50);
}

TEST(Sphere_cubic, NearMultipleRoots)
{
  // det(λ) = (λ − 1)² (3 − λ) + eps = −λ³ + 5λ² − 7λ + 3 + eps: a double root
  // at 1 (eps = 0), two close roots 1 ± √(−eps/2) (eps < 0), or none near 1.
  for(double eps : { 0., 1e-6, -1e-6, 1e-10, -1e-10 }) {
    SCOPED_TRACE(eps);
    const double root = D::smallest_positive_root(-1., 5., -7., 3. + eps);
    if(eps > 0) EXPECT_NEAR(root, 3., 1e-5);
    else if(eps < 0) EXPECT_NEAR(root, 1 - std::sqrt(-eps / 2), 1e-2 * std::sqrt(-eps));
    else EXPECT_NEAR(root, 1., 1e-7);
  }
}

TEST(Sphere_cubic, ShrinkingTriangleHasANearDoubleRoot)
{
  // Points c + v_k of the tangent plane at c moving by −v_k: det = (1 − λ)² det₀,
  // a double root at λ = 1; a small extra motion δ of p2 splits it into two
  // close roots. Bisection cannot see such a pair reliably, so the computed
  // root r is checked directly: det(r) ≈ 0 and det > 0 on a fine scan of (0, r).
  const V3 c{{ 0, 0, 1 }};
  const V3 v[3] = { {{ -0.1, -0.05, 0 }}, {{ 0.1, -0.05, 0 }}, {{ 0, 0.1, 0 }} };
  const V3 zero{{ 0, 0, 0 }};
  for(double delta : { 0., 1e-5, -1e-5, 1e-3, -1e-3 }) {
    SCOPED_TRACE(delta);
    V3 p[3], t[3];
    for(int k = 0; k < 3; ++k) {
      p[k] = {{ c[0] + v[k][0], c[1] + v[k][1], c[2] + v[k][2] }};
      t[k] = {{ -v[k][0], -v[k][1], -v[k][2] }};
    }
    t[2][1] += delta;
    const double r = D::critical_step_sphere(p[0], p[1], p[2], t[0], t[1], t[2]);
    ASSERT_TRUE(std::isfinite(r));
    if(delta == 0) EXPECT_NEAR(r, 1., 1e-7);
    const long double det0 = det_along(p[0], p[1], p[2], zero, zero, zero, 0);
    EXPECT_LE(std::fabs(det_along(p[0], p[1], p[2], t[0], t[1], t[2], r)), 1e-9L * det0);
    for(int k = 1; k < 20000; ++k)
      ASSERT_GT(det_along(p[0], p[1], p[2], t[0], t[1], t[2], (long double)r * (1 - 1e-7) * k / 20000), 0) << k;
  }
}

// ---------------------------------------------------------------------------
// Initial map and flow on CGAL's closed genus-0 meshes
// ---------------------------------------------------------------------------

TEST(Sphere_initial_map, CertifiedOnEveryMesh)
{
  for(const char* name : { "tetrahedron", "octahedron", "icosahedron", "cube", "sphere", "ellipsoid", "blobby", "cow" }) {
    SCOPED_TRACE(name);
    const Index_mesh m = index_mesh(read_sphere_mesh(name));
    D::Sphere_problem P;
    P.xyz = m.xyz;
    P.faces = m.faces;
    ASSERT_TRUE(D::validate_sphere_topology(P.xyz.size(), P.faces).ok());
    ASSERT_TRUE(D::validate_sphere_geometry(P, {}).ok());
    std::vector<V3> p;
    const D::Sphere_initial_outcome init = D::certified_sphere_initial_map<SMP::internal::dlf::Default_spd_solver>(P, p);
    ASSERT_TRUE(init.certified) << init.message;
    const Sphere_signs s = exact_sphere_signs(p, m.faces);
    EXPECT_EQ(s.pos, m.faces.size());
    for(const V3& q : p) EXPECT_NEAR(std::sqrt(D::dot(q, q)), 1., 1e-12);
  }
}

// The polish energy E(flat) + κ E(cone) (E the weighted D_area) and its
// gradient: directional derivatives along random moves against central
// finite differences, for area weights (β = 0) and half-uniform ones.
TEST(Sphere_flow, PolishGradientMatchesFiniteDifferences)
{
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(-1, 1);
  const SM sm = read_sphere_mesh("octahedron");
  const Index_mesh m = index_mesh(sm);
  std::vector<V3> p;
  for(const V3& q : m.xyz) p.push_back(D::normalized(V3{{ q[0] + 0.1 * U(rng), q[1] + 0.1 * U(rng), q[2] + 0.1 * U(rng) }}));
  ASSERT_EQ(exact_sphere_signs(p, m.faces).pos, m.faces.size());
  std::vector<double> target(m.faces.size());
  for(double& t : target) t = 1 + 0.5 * (U(rng) + 1);
  const double kappa = 0.1;
  for(double beta : { 0., 0.5 }) {
    SCOPED_TRACE(beta);
    const D::Weighted_area_energy energy(target, beta);
    const auto E = [&](const std::vector<V3>& x) {
      std::vector<double> a, c;
      D::signed_areas_sphere(x, m.faces, a);
      D::cone_areas_sphere(x, m.faces, c);
      return energy.value(a) + kappa * energy.value(c);
    };
    std::vector<double> a, c, dA, dC;
    D::signed_areas_sphere(p, m.faces, a);
    D::cone_areas_sphere(p, m.faces, c);
    energy.derivatives(a, dA);
    energy.derivatives(c, dC);
    for(double& x : dC) x *= kappa;
    std::vector<V3> g;
    D::polish_position_gradient(p, m.faces, dA, dC, g);
    for(int trial = 0; trial < 5; ++trial) {
      std::vector<V3> d(p.size());
      for(V3& x : d) x = {{ U(rng), U(rng), U(rng) }};
      double analytic = 0;
      for(std::size_t v = 0; v < p.size(); ++v) analytic += D::dot(g[v], d[v]);
      const double e = 1e-6;
      std::vector<V3> plus = p, minus = p;
      for(std::size_t v = 0; v < p.size(); ++v)
        for(int j = 0; j < 3; ++j) { plus[v][j] += e * d[v][j]; minus[v][j] -= e * d[v][j]; }
      const double fd = (E(plus) - E(minus)) / (2 * e);
      EXPECT_NEAR(analytic, fd, 1e-6 * (std::abs(fd) + 1));
    }
  }
}

// The opening's local sweeps: with the flat areas' weight 0 the sweeps
// minimise the opening's energy alone (the D_area of the cone areas,
// recomputed here from scratch with Area_barrier_energy), keep every face
// positive by the exact predicate, leave every vertex outside the given set
// where it was, and hand back the areas of the moved map.
TEST(Sphere_flow, OpeningSweepsLowerTheConeDArea)
{
  const Index_mesh m = index_mesh(read_sphere_mesh("sphere966"));
  // Radial projection from a point off the centre: a certified map that
  // crowds the faces near the south pole into a small cap.
  std::vector<V3> p;
  for(const V3& q : m.xyz) {
    const V3 x = D::normalized(q);
    p.push_back(D::normalized(V3{{ x[0], x[1], x[2] + 0.8 }}));
  }
  ASSERT_EQ(exact_sphere_signs(p, m.faces).pos, m.faces.size());
  std::vector<double> target(m.faces.size());
  for(std::size_t t = 0; t < target.size(); ++t) {
    const V3 &a = m.xyz[std::size_t(m.faces[t][0])], &b = m.xyz[std::size_t(m.faces[t][1])], &c = m.xyz[std::size_t(m.faces[t][2])];
    target[t] = double(flat_area(a, b, c));
  }
  // The corners of the faces in the crowded cap and one ring around them.
  std::vector<char> active_mark(p.size(), 0);
  for(const Tri& t : m.faces) {
    bool low = false;
    for(int k = 0; k < 3; ++k) low = low || p[std::size_t(t[k])][2] < -0.9;
    if(low) for(int k = 0; k < 3; ++k) active_mark[std::size_t(t[k])] = 1;
  }
  std::vector<std::size_t> active;
  for(std::size_t v = 0; v < p.size(); ++v) if(active_mark[v]) active.push_back(v);
  ASSERT_GT(active.size(), 10u);
  ASSERT_LT(active.size(), p.size() / 4);

  const D::Area_barrier_energy cone_d_area(target);
  std::vector<double> flat, cone;
  D::signed_areas_sphere(p, m.faces, flat);
  D::cone_areas_sphere(p, m.faces, cone);
  const double E0 = cone_d_area.value(cone);
  const D::Vertex_faces around(p.size(), m.faces);
  const std::vector<V3> before = p;
  double E_prev = E0;
  for(int sweep = 0; sweep < 5; ++sweep) {
    const D::Relaxation_outcome r =
      D::relax_sphere_vertices(m.faces, around, D::Weighted_area_energy(target, 0), 1, 0.8, active, p, flat, cone, 0);
    EXPECT_GT(r.moved, 0u);
    std::vector<double> flat_now, cone_now;
    D::signed_areas_sphere(p, m.faces, flat_now);
    D::cone_areas_sphere(p, m.faces, cone_now);
    for(std::size_t t = 0; t < m.faces.size(); ++t) {
      ASSERT_NEAR(flat[t], flat_now[t], 1e-12 * flat_now[t]) << "face " << t;
      ASSERT_NEAR(cone[t], cone_now[t], 1e-12 * cone_now[t]) << "face " << t;
    }
    const double E = cone_d_area.value(cone_now);
    EXPECT_LT(E, E_prev) << "sweep " << sweep;
    E_prev = E;
  }
  // D_area's excess over its minimum 2, most of it in the cap: a tenth of it gone.
  EXPECT_LT(E_prev - 2, 0.9 * (E0 - 2)) << "the crowded cap was not opened: " << E0 << " -> " << E_prev;
  EXPECT_EQ(exact_sphere_signs(p, m.faces).pos, m.faces.size());
  for(std::size_t v = 0; v < p.size(); ++v) {
    if(!active_mark[v]) EXPECT_EQ(p[v], before[v]) << "vertex " << v << " is not in the swept set";
    EXPECT_NEAR(D::dot(p[v], p[v]), 1, 1e-12);
  }
}

// The spherical area element of the opening: the octant is π/2; the areas
// of a positively oriented map of a closed mesh add up to 4π; a small face
// has its cone area up to second order; a face spread over nearly a
// hemisphere (corners just above one great circle) is close to 2π while its
// cone area is close to 0; the sign is the determinant's; and the gradient
// is that of central differences.
TEST(Sphere_flow, SphericalAreaElement)
{
  const double pi = 3.14159265358979323846;
  EXPECT_NEAR(D::spherical_area_sphere({{ 1, 0, 0 }}, {{ 0, 1, 0 }}, {{ 0, 0, 1 }}), pi / 2, 1e-15);
  EXPECT_NEAR(D::spherical_area_sphere({{ 1, 0, 0 }}, {{ 0, 0, 1 }}, {{ 0, 1, 0 }}), -pi / 2, 1e-15);

  const Index_mesh m = index_mesh(read_sphere_mesh("sphere966"));
  std::vector<V3> p;
  for(const V3& q : m.xyz) p.push_back(D::normalized(q));
  ASSERT_EQ(exact_sphere_signs(p, m.faces).pos, m.faces.size());
  std::vector<double> sph, cone;
  D::spherical_areas_sphere(p, m.faces, sph);
  D::cone_areas_sphere(p, m.faces, cone);
  long double total = 0;
  for(std::size_t t = 0; t < sph.size(); ++t) {
    total += sph[t];
    EXPECT_GT(sph[t], 0);
    EXPECT_NEAR(sph[t], cone[t], 0.02 * cone[t]) << "face " << t; // edges about 0.1: second order
  }
  EXPECT_NEAR(double(total), 4 * pi, 1e-12);

  // Three corners 1e-4 above the equator, 120° apart: nearly the northern hemisphere.
  const double z = 1e-4, r = std::sqrt(1 - z * z);
  const V3 a{{ r, 0, z }}, b{{ r * std::cos(2 * pi / 3), r * std::sin(2 * pi / 3), z }}, c{{ r * std::cos(4 * pi / 3), r * std::sin(4 * pi / 3), z }};
  EXPECT_GT(D::cone_area_sphere(a, b, c), 0);
  EXPECT_LT(D::cone_area_sphere(a, b, c), 1e-3);
  EXPECT_NEAR(D::spherical_area_sphere(a, b, c), 2 * pi, 2e-3);

  // Gradient of Σ w_t u_t against central differences on a small patch of faces.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(-1, 1);
  std::vector<double> w(m.faces.size());
  for(double& x : w) x = U(rng);
  std::vector<V3> g;
  D::spherical_position_gradient(p, m.faces, w, g);
  const auto total_at = [&](const std::vector<V3>& x) {
    std::vector<double> s;
    D::spherical_areas_sphere(x, m.faces, s);
    long double e = 0;
    for(std::size_t t = 0; t < s.size(); ++t) e += w[t] * s[t];
    return double(e);
  };
  for(std::size_t v : { std::size_t(0), std::size_t(17), std::size_t(400) })
    for(std::size_t j = 0; j < 3; ++j) {
      std::vector<V3> plus = p, minus = p;
      const double h = 1e-6;
      plus[v][j] += h;
      minus[v][j] -= h;
      EXPECT_NEAR(g[v][j], (total_at(plus) - total_at(minus)) / (2 * h), 1e-6 * (1 + std::abs(g[v][j]))) << "vertex " << v << " coordinate " << j;
    }
}

// The weighted D_area: Σ ω (r + 1/r) computed face by face in long double,
// ≥ 2 with equality exactly at the targets; β = 0 is the area-weighted
// energy; the running sums follow single-face changes.
TEST(Sphere_flow, WeightedAreaEnergyIsItsDefinition)
{
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> U(0.2, 3);
  const std::size_t F = 50;
  std::vector<double> target(F), u(F);
  for(double& t : target) t = U(rng);
  for(double& x : u) x = U(rng);
  target[7] = 1e-15; // a 3D triangle collinear up to rounding: its weight is capped at 100 a
  long double T = 0, S = 0;
  for(std::size_t t = 0; t < F; ++t) { T += target[t]; S += u[t]; }
  for(double beta : { 0., 0.5, 1. }) {
    SCOPED_TRACE(beta);
    const D::Weighted_area_energy energy(target, beta);
    long double expected = 0, W = 0;
    for(std::size_t t = 0; t < F; ++t) {
      const long double a = target[t] / T, w = (1 - beta) * a + beta * (std::min)(1.L / F, 100 * a), r = (u[t] / S) / a;
      expected += w * (r + 1 / r);
      W += w;
    }
    expected /= W;
    EXPECT_NEAR(energy.value(u), double(expected), 1e-12 * double(expected));
    EXPECT_GT(energy.value(u), 2.);
    std::vector<double> scaled(target);
    for(double& x : scaled) x *= 7.5; // at the targets, whatever the total
    EXPECT_NEAR(energy.value(scaled), 2., 1e-13);
    D::Weighted_area_energy::Sums s = energy.sums(u);
    std::vector<double> v = u;
    v[3] *= 1.7;
    v[11] *= 0.4;
    energy.change(s, 3, u[3], v[3]);
    energy.change(s, 11, u[11], v[11]);
    EXPECT_NEAR(energy.value(s), energy.value(v), 1e-12 * energy.value(v));
  }
  EXPECT_NEAR(D::Weighted_area_energy(target, 0).value(u), D::Area_barrier_energy(target).value(u), 1e-12);
  u[5] = 0;
  EXPECT_EQ(D::Weighted_area_energy(target, 0.5).value(u), std::numeric_limits<double>::infinity());
}

// The Gauss–Newton matrix against its definition: xᵀ A x = Σ_t w_t (∂u_t · x)²
// + ε xᵀ S x, with ∂u_t · x by finite differences of the area elements along
// the tangent move x and S the Sobolev matrix applied to each 3D coordinate.
TEST(Sphere_flow, GaussNewtonMatrixIsItsDefinition)
{
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> U(-1, 1);
  const SM sm = read_sphere_mesh("sphere");
  const Index_mesh m = index_mesh(sm);
  std::vector<V3> p;
  for(const V3& q : m.xyz) p.push_back(D::normalized(q));
  const D::Tangent_frames T(p);
  for(std::size_t v = 0; v < p.size(); ++v) {
    EXPECT_NEAR(D::dot(T.e1[v], p[v]), 0., 1e-15);
    EXPECT_NEAR(D::dot(T.e2[v], p[v]), 0., 1e-15);
    EXPECT_NEAR(D::dot(T.e1[v], T.e2[v]), 0., 1e-15);
  }
  std::vector<double> w(m.faces.size()), wc(m.faces.size());
  for(double& x : w) x = 1 + U(rng) * U(rng);
  for(double& x : wc) x = 0.1 * (1 + U(rng) * U(rng));
  const D::Sparse_matrix S = D::sphere_sobolev_matrix(p, m.faces, 0.1);
  const double eps = 1e-2;
  double ratio = 0;
  const D::Sparse_matrix A = D::sphere_gauss_newton_matrix(p, m.faces, w, wc, T, S, eps, ratio);
  ASSERT_EQ(A.rows(), Eigen::Index(2 * p.size()));
  EXPECT_GT(ratio, 0.);
  for(int trial = 0; trial < 3; ++trial) {
    Eigen::VectorXd x(A.rows());
    for(Eigen::Index i = 0; i < x.size(); ++i) x[i] = U(rng);
    std::vector<V3> move(p.size());
    for(std::size_t v = 0; v < p.size(); ++v) move[v] = T.vector(v, x[Eigen::Index(2 * v)], x[Eigen::Index(2 * v + 1)]);
    const double e = 1e-7;
    std::vector<V3> plus = p, minus = p;
    for(std::size_t v = 0; v < p.size(); ++v)
      for(int j = 0; j < 3; ++j) { plus[v][j] += e * move[v][j]; minus[v][j] -= e * move[v][j]; }
    std::vector<double> up, um, cp, cm;
    D::signed_areas_sphere(plus, m.faces, up);
    D::signed_areas_sphere(minus, m.faces, um);
    D::cone_areas_sphere(plus, m.faces, cp);
    D::cone_areas_sphere(minus, m.faces, cm);
    double expected = 0;
    for(std::size_t f = 0; f < m.faces.size(); ++f) {
      const double du = (up[f] - um[f]) / (2 * e), dc = (cp[f] - cm[f]) / (2 * e);
      expected += w[f] * du * du + wc[f] * dc * dc;
    }
    for(int c = 0; c < 3; ++c) {
      Eigen::VectorXd X(Eigen::Index(p.size()));
      for(std::size_t v = 0; v < p.size(); ++v) X[Eigen::Index(v)] = move[v][std::size_t(c)];
      expected += eps * ratio * X.dot(S * X);
    }
    EXPECT_NEAR(x.dot(A * x), expected, 1e-6 * expected);
  }
}

// The flow refills its matrices in place (Fixed_pattern_matrix): after the
// first assembly, the same contributions for other points must give exactly
// (bit for bit) what setFromTriplets gives, pattern included.
TEST(Sphere_flow, FixedPatternRefillIsSetFromTriplets)
{
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> U(-1, 1);
  const SM sm = read_sphere_mesh("sphere");
  const Index_mesh m = index_mesh(sm);
  D::Fixed_pattern_matrix K, A;
  for(int round = 0; round < 3; ++round) {
    std::vector<V3> p;
    for(const V3& q : m.xyz) p.push_back(D::normalized(V3{{ q[0] + 0.01 * U(rng), q[1] + 0.01 * U(rng), q[2] + 0.01 * U(rng) }}));
    const D::Sparse_matrix S = D::sphere_sobolev_matrix(p, m.faces, 0.1);
    const D::Sparse_matrix& S2 = K.assemble(p.size(), [&](auto&& add) { D::sphere_sobolev_contributions(p, m.faces, 0.1, add); });
    const D::Tangent_frames T(p);
    std::vector<double> w(m.faces.size()), wc(m.faces.size());
    for(double& x : w) x = 1 + U(rng) * U(rng);
    for(double& x : wc) x = 0.1 * (1 + U(rng) * U(rng));
    double ratio = 0, ratio2 = 0;
    const D::Sparse_matrix H = D::sphere_gauss_newton_matrix(p, m.faces, w, wc, T, S, 1e-2, ratio);
    const D::Sparse_matrix& H2 = A.assemble(2 * p.size(), [&](auto&& add) {
      D::sphere_gauss_newton_contributions(p, m.faces, w, wc, T, S2, 1e-2, ratio2, add);
    });
    EXPECT_EQ(ratio, ratio2);
    for(const auto& pair : { std::make_pair(&S, &S2), std::make_pair(&H, &H2) }) {
      const D::Sparse_matrix &X = *pair.first, &Y = *pair.second;
      ASSERT_EQ(X.nonZeros(), Y.nonZeros());
      EXPECT_TRUE(std::equal(X.outerIndexPtr(), X.outerIndexPtr() + X.outerSize() + 1, Y.outerIndexPtr()));
      EXPECT_TRUE(std::equal(X.innerIndexPtr(), X.innerIndexPtr() + X.nonZeros(), Y.innerIndexPtr()));
      EXPECT_TRUE(std::equal(X.valuePtr(), X.valuePtr() + X.nonZeros(), Y.valuePtr()));
    }
  }
}

struct Sphere_case
{
  const char* name;
  double max_d_area;          // what the default run must reach
  // true: converged, mean |log r| <= 0.02 (the default log_area_tolerance);
  // false: this mesh's own triangles keep it short of that goal, asserted
  // too (a row that starts converging is a change to look at, and to write here)
  bool converges = true;
  double min_plane_distance = 0; // if > 0: every output triangle's plane at least this far from the centre
};

void check_sphere_map(const Sphere_case& c, const SM& sm)
{
  SCOPED_TRACE(c.name);
  const Index_mesh m = index_mesh(sm);
  std::vector<V3> p;
  const auto t0 = std::chrono::steady_clock::now();
  const SMP::Discrete_lie_flow_report r = map_to_sphere(sm, p);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ASSERT_EQ(r.status, SMP::OK) << r.message;
  ASSERT_EQ(p.size(), m.xyz.size());
  for(const V3& q : p) ASSERT_NEAR(std::sqrt(D::dot(q, q)), 1., 1e-12);
  const Sphere_signs s = exact_sphere_signs(p, m.faces);
  EXPECT_EQ(s.neg, 0u);
  EXPECT_EQ(s.zero, 0u);
  EXPECT_EQ(r.caller_inverted_faces, 0u);
  const std::pair<double, double> d = sphere_d_area(m.xyz, p, m.faces);
  EXPECT_NEAR(r.final_d_area, d.first, 1e-9 * d.first);
  EXPECT_NEAR(r.final_metrics.d_area, d.first, 1e-9 * d.first);
  EXPECT_NEAR(r.final_metrics.log_area_mean_abs, d.second, 1e-9);
  EXPECT_LE(d.first, c.max_d_area);
  EXPECT_LE(r.final_d_area, r.initial_d_area);
  if(c.min_plane_distance > 0) {
    double h = 1;
    for(const Tri& t : m.faces) {
      const V3 &a = p[std::size_t(t[0])], &b = p[std::size_t(t[1])], &q = p[std::size_t(t[2])];
      const V3 N = D::cross(D::sub(b, a), D::sub(q, a));
      h = (std::min)(h, D::dot(a, N) / std::sqrt(D::dot(N, N)));
    }
    EXPECT_GE(h, c.min_plane_distance);
  }
  const bool all_goals = r.stop_reason == SMP::Discrete_lie_flow_stop_reason::CONVERGED &&
                         d.second <= SMP::Discrete_lie_flow_options().sphere.log_area_tolerance;
  EXPECT_EQ(all_goals, c.converges) << "stop " << SMP::discrete_lie_flow_stop_reason_name(r.stop_reason)
                                    << ", mean |log r| " << d.second << ": " << r.message;
  std::cout << "[sphere] " << c.name << ": " << m.faces.size() << " faces, start d_area " << r.initial_d_area
            << ", " << r.iterations << " iterations (" << SMP::discrete_lie_flow_stop_reason_name(r.stop_reason) << "), d_area "
            << d.first << ", mean |log r| " << d.second << ", inverted " << s.neg + s.zero << ", " << seconds << " s"
            << std::endl;
}

void check_sphere_map(const Sphere_case& c) { check_sphere_map(c, read_sphere_mesh(c.name)); }

// ---------------------------------------------------------------------------
// Generated shapes with long protrusions (the start is the crux)
// ---------------------------------------------------------------------------

/// The unit icosphere, each triangle split `level` times into four.
SM icosphere(int level)
{
  const double t = (1 + std::sqrt(5.)) / 2;
  std::vector<V3> v = { {{ -1, t, 0 }}, {{ 1, t, 0 }}, {{ -1, -t, 0 }}, {{ 1, -t, 0 }}, {{ 0, -1, t }}, {{ 0, 1, t }},
                        {{ 0, -1, -t }}, {{ 0, 1, -t }}, {{ t, 0, -1 }}, {{ t, 0, 1 }}, {{ -t, 0, -1 }}, {{ -t, 0, 1 }} };
  std::vector<Tri> f = { {{ 0, 11, 5 }}, {{ 0, 5, 1 }}, {{ 0, 1, 7 }}, {{ 0, 7, 10 }}, {{ 0, 10, 11 }}, {{ 1, 5, 9 }},
                         {{ 5, 11, 4 }}, {{ 11, 10, 2 }}, {{ 10, 7, 6 }}, {{ 7, 1, 8 }}, {{ 3, 9, 4 }}, {{ 3, 4, 2 }},
                         {{ 3, 2, 6 }}, {{ 3, 6, 8 }}, {{ 3, 8, 9 }}, {{ 4, 9, 5 }}, {{ 2, 4, 11 }}, {{ 6, 2, 10 }},
                         {{ 8, 6, 7 }}, {{ 9, 8, 1 }} };
  for(V3& x : v) x = D::normalized(x);
  for(int l = 0; l < level; ++l) {
    std::map<std::pair<int, int>, int> mid;
    const auto middle = [&](int a, int b) {
      const std::pair<int, int> key((std::min)(a, b), (std::max)(a, b));
      const auto it = mid.find(key);
      if(it != mid.end()) return it->second;
      const V3& p = v[std::size_t(a)];
      const V3& q = v[std::size_t(b)];
      v.push_back(D::normalized(V3{{ p[0] + q[0], p[1] + q[1], p[2] + q[2] }}));
      return mid[key] = int(v.size()) - 1;
    };
    std::vector<Tri> g;
    for(const Tri& t3 : f) {
      const int ab = middle(t3[0], t3[1]), bc = middle(t3[1], t3[2]), ca = middle(t3[2], t3[0]);
      g.push_back({{ t3[0], ab, ca }});
      g.push_back({{ t3[1], bc, ab }});
      g.push_back({{ t3[2], ca, bc }});
      g.push_back({{ ab, bc, ca }});
    }
    f.swap(g);
  }
  SM sm;
  for(const V3& x : v) sm.add_vertex(K::Point_3(x[0], x[1], x[2]));
  for(const Tri& t3 : f) sm.add_face(SM_vertex(t3[0]), SM_vertex(t3[1]), SM_vertex(t3[2]));
  return sm;
}

/// Isotropic remeshing to edge length `edge`: long protrusions get as many
/// vertex rings along them as a scanned shape would (what compresses a
/// Tutte start is the number of rings per ring size, not the 3D length).
SM remeshed(SM sm, double edge)
{
  CGAL::Polygon_mesh_processing::isotropic_remeshing(faces(sm), edge, sm, CGAL::parameters::number_of_iterations(3));
  sm.collect_garbage();
  return sm;
}

/// A starfish: the unit sphere with five arms of length `arm` in the
/// equatorial plane (radial bumps of angular width `width`), remeshed.
SM starfish(double arm, double width, double edge)
{
  SM sm = icosphere(4);
  const double pi = 3.14159265358979323846;
  for(SM_vertex v : vertices(sm)) {
    const K::Point_3 q = sm.point(v);
    double r = 1;
    for(int k = 0; k < 5; ++k) {
      const double c = q.x() * std::cos(2 * pi * k / 5) + q.y() * std::sin(2 * pi * k / 5);
      const double a = std::acos((std::max)(-1., (std::min)(1., c))) / width;
      r += arm * std::exp(-a * a);
    }
    sm.point(v) = K::Point_3(r * q.x(), r * q.y(), r * q.z());
  }
  return remeshed(sm, edge);
}

/// A dumbbell: two unit lobes at z = ±0.75 `length` joined by a neck of
/// radius `neck` (a surface of revolution over the sphere), remeshed.
SM dumbbell(double length, double neck, double edge)
{
  SM sm = icosphere(4);
  for(SM_vertex v : vertices(sm)) {
    const K::Point_3 q = sm.point(v);
    const double lobe = (std::abs(q.z()) - 0.75) / 0.25;
    const double w = neck + (1 - neck) * std::exp(-lobe * lobe);
    sm.point(v) = K::Point_3(w * q.x(), w * q.y(), length * q.z());
  }
  return remeshed(sm, edge);
}

// Starts of e^12 and e^20: converged like the protrusions of CGAL's meshes.
TEST(Sphere_map, GeneratedStarfish)
{
  check_sphere_map({ "starfish", 2.01 }, starfish(3, 0.2, 0.15));
}

TEST(Sphere_map, GeneratedDumbbell) { check_sphere_map({ "dumbbell", 2.01 }, dumbbell(3, 0.25, 0.12)); }

// Stretched 6× with a neck of radius 0.1: the Tutte start is off by ~e^54 and
// the flow does not open it within the cap, but every iterate stays certified.
TEST(Sphere_map, LongNeckStaysCertified)
{
  const SM sm = dumbbell(6, 0.1, 0.12);
  const Index_mesh m = index_mesh(sm);
  SMP::Discrete_lie_flow_options o;
  o.max_iterations = 40;
  std::vector<V3> p;
  const SMP::Discrete_lie_flow_report r = map_to_sphere(sm, p, o);
  ASSERT_EQ(r.status, SMP::OK) << r.message;
  EXPECT_GT(r.initial_d_area, 1e20);
  const Sphere_signs s = exact_sphere_signs(p, m.faces);
  EXPECT_EQ(s.pos, m.faces.size());
  for(const V3& q : p) ASSERT_NEAR(std::sqrt(D::dot(q, q)), 1., 1e-12);
  const std::pair<double, double> d = sphere_d_area(m.xyz, p, m.faces);
  EXPECT_TRUE(std::isfinite(d.first));
  EXPECT_LT(d.first, 1e-3 * r.initial_d_area);
  EXPECT_NE(r.stop_reason, SMP::Discrete_lie_flow_stop_reason::CONVERGED);
}

TEST(Sphere_map, SphereAndEllipsoid)
{
  check_sphere_map({ "sphere", 2.001 });
  check_sphere_map({ "ellipsoid", 2.001 });
  check_sphere_map({ "icosahedron", 2.01 }); // 20 faces
}

TEST(Sphere_map, Blobby) { check_sphere_map({ "blobby", 2.01 }); }
TEST(Sphere_map, Hand) { check_sphere_map({ "hand", 2.01 }); }
TEST(Sphere_map, Cow) { check_sphere_map({ "cow", 2.01 }); }
TEST(Sphere_map, Homer) { check_sphere_map({ "homer", 2.01 }); }
// Compressed starts (e^6 and e^30): the polish's relaxation sweeps are what
// converge these (before them: plateaus at mean |log r| 0.06 and 0.03).
TEST(Sphere_map, Triceratops) { check_sphere_map({ "triceratops", 2.01 }); }
TEST(Sphere_map, Camel) { check_sphere_map({ "camel", 2.01 }); }
// Coarse CAD meshes with 3D slivers: the polish's uniform share of the face
// weights is what brings their small faces' mean |log r| to 0.02 (before:
// plateaus at D_area 2.0049 / 2.0105 with means 0.063 / 0.044).
TEST(Sphere_map, HandleAndSpool)
{
  check_sphere_map({ "handle", 2.01 });
  check_sphere_map({ "spool", 2.01 });
}
// Arms off a body: with a damped flat area element the polish ended at
// D_area 2.07 with 24 long slivers along great circles (planes within 0.05
// of the centre) holding 84% of D_area − 2. The cone term of the polish
// energy keeps the barrier without hiding them: D_area 2.009 now (a
// plateau, so the bound leaves room for rounding), the mean near 0.05.
// At least 0.1 here; the bound leaves room for rounding-level changes (another
// sparse solver gave 0.094). The damped polish of 2fc79b8 left 24 planes
// closer than 0.05 to the centre.
TEST(Sphere_map, CactusHasNoGreatCircleSlivers) { check_sphere_map({ "cactus", 2.01, false, 0.05 }); }

TEST(Sphere_map, CoarseMeshesMeetTheGoalsOnceRefined)
{
  // cactus and part stop at a mean |log r| of 0.054 and 0.038 on their own
  // triangles (doc/sphere.md, "Coarse connectivity"); after one Loop
  // subdivision (four times the faces, slightly smoothed) they converge
  // with every goal met.
  for(const char* name : { "cactus", "part" }) {
    SM sm = read_sphere_mesh(name);
    CGAL::Subdivision_method_3::Loop_subdivision(sm, CGAL::parameters::number_of_iterations(1));
    check_sphere_map({ name, 2.01 }, sm);
  }
}

// ---------------------------------------------------------------------------
// The claim of doc/sphere_benchmark.md on the whole data set: every closed,
// connected, genus-0 triangle mesh with at least 200 faces (34 of them) is
// mapped with every triangle positive (exact) and D_area <= 2.01; 29 of them
// also converge with mean |log r| <= 0.02, and the other five are the
// coarse CAD meshes named there. The meshes are found by their topology;
// the names are only the expectation, compared as a whole.
// ---------------------------------------------------------------------------

bool closed_genus_0(SM& sm)
{
  if(faces(sm).empty() || !CGAL::is_triangle_mesh(sm) || !CGAL::is_closed(sm)) return false;
  auto cc = sm.add_property_map<SM::Face_index, std::size_t>("f:test_cc", 0).first;
  const std::size_t components = CGAL::Polygon_mesh_processing::connected_components(sm, cc);
  sm.remove_property_map(cc);
  return components == 1 && long(num_vertices(sm)) - long(num_edges(sm)) + long(num_faces(sm)) == 2;
}

TEST(Sphere_data_set, EveryClosedGenus0Mesh)
{
  const std::filesystem::path dir = std::filesystem::path(DLF_DATA_DIR) / "meshes";
  ASSERT_TRUE(std::filesystem::is_directory(dir)) << dir;
  std::vector<std::filesystem::path> files;
  for(const auto& e : std::filesystem::directory_iterator(dir))
    if(e.path().extension() == ".off") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  std::size_t meshes = 0, all_goals = 0;
  std::vector<std::string> short_of_goals;
  for(const std::filesystem::path& file : files) {
    // The file's own connectivity first (as `dlf` reads it), then the
    // repairing reader for polygon soups.
    SM sm;
    bool ok = false;
    try {
      ok = CGAL::IO::read_polygon_mesh(file.string(), sm) && closed_genus_0(sm);
      if(!ok) { sm.clear(); ok = CGAL::Polygon_mesh_processing::IO::read_polygon_mesh(file.string(), sm) && closed_genus_0(sm); }
    } catch(const std::exception&) { ok = false; }
    if(!ok || num_faces(sm) < 200) continue;
    ++meshes;
    SCOPED_TRACE(file.filename().string());
    const Index_mesh m = index_mesh(sm);
    std::vector<V3> p;
    const SMP::Discrete_lie_flow_report r = map_to_sphere(sm, p);
    ASSERT_EQ(r.status, SMP::OK) << r.message;
    for(const V3& q : p) ASSERT_NEAR(std::sqrt(D::dot(q, q)), 1., 1e-12);
    const Sphere_signs s = exact_sphere_signs(p, m.faces);
    EXPECT_EQ(s.pos, m.faces.size()) << s.neg << " inverted, " << s.zero << " degenerate";
    const std::pair<double, double> d = sphere_d_area(m.xyz, p, m.faces);
    EXPECT_LE(d.first, 2 + SMP::Discrete_lie_flow_options().tolerance);
    EXPECT_NEAR(r.final_d_area, d.first, 1e-9 * d.first);
    if(r.stop_reason == SMP::Discrete_lie_flow_stop_reason::CONVERGED && d.second <= SMP::Discrete_lie_flow_options().sphere.log_area_tolerance)
      ++all_goals;
    else
      short_of_goals.push_back(file.stem().string());
    std::cout << "[sphere data set] " << file.filename().string() << ": " << m.faces.size() << " faces, d_area "
              << d.first << ", mean |log r| " << d.second << " (" << SMP::discrete_lie_flow_stop_reason_name(r.stop_reason) << ")" << std::endl;
  }
  EXPECT_EQ(meshes, 34u) << "the data set changed: doc/sphere_benchmark.md counts 34 meshes";
  // 29 of 34 meet every goal under this machine's kernel (doc/sphere_benchmark.md);
  // Under OpenBLAS's generic Prescott kernel dino stops at a plateau short of
  // the mean |log r| goal (0.025 > 0.02): the set may differ by that mesh only.
  EXPECT_GE(all_goals, 28u) << "doc/sphere_benchmark.md: 29 of 34 meet every goal (28 when dino misses)";
  std::sort(short_of_goals.begin(), short_of_goals.end());
  std::vector<std::string> without_dino = short_of_goals;
  without_dino.erase(std::remove(without_dino.begin(), without_dino.end(), "dino"), without_dino.end());
  EXPECT_EQ(without_dino, (std::vector<std::string>{ "bull", "cactus", "oblong", "oblong-shuffled", "part" }));
}

TEST(Sphere_map, IrregularMeshes)
{
  // A scanned-like triangulation (benchmark/irregular_meshes.h): edge
  // collapses and tangential jitter give slivers (min angle 1.4°) and face
  // areas spanning two decades. Certified, converged with every goal met.
  struct Case { const char* name; std::vector<dlf_benchmark::Irregular_step> steps; };
  for(const Case& c : { Case{ "bear_bis", { { "decimate", 20 }, { "jitter", 90 } } } }) {
    SM sm = read_sphere_mesh(c.name);
    dlf_benchmark::make_irregular(sm, c.steps);
    ASSERT_TRUE(closed_genus_0(sm)) << c.name;
    double min_angle = 180;
    for(auto f : faces(sm)) {
      const auto h = halfedge(f, sm);
      const K::Point_3 P[3] = { sm.point(source(h, sm)), sm.point(target(h, sm)), sm.point(target(next(h, sm), sm)) };
      for(int k = 0; k < 3; ++k) {
        const K::Vector_3 a = P[(k + 1) % 3] - P[k], b = P[(k + 2) % 3] - P[k];
        min_angle = (std::min)(min_angle, std::atan2(std::sqrt(CGAL::cross_product(a, b).squared_length()), a * b) * 180 / CGAL_PI);
      }
    }
    EXPECT_LT(min_angle, 2.) << c.name << ": the generator no longer makes slivers";
    check_sphere_map({ c.name, 2.01 }, sm);
  }
}

TEST(Sphere_flow, CappedStepsDoNotShrinkTheRegularization)
{
  // The polish's ε shrinks only after a full step; a step cut short by a
  // face's critical root (no halvings) is no evidence that the model holds:
  // ε grows, up to the ceiling (never lowered by it); two halvings: × 4.
  D::Flow_step full, capped, tiny, halved, once;
  full.lambda = 1;
  capped.lambda = 0.3;
  tiny.lambda = 1e-3;
  halved.lambda = 0.5;
  halved.halvings = 2;
  once.lambda = 0.6;
  once.halvings = 1;
  const double ceiling = 1e-2;
  EXPECT_DOUBLE_EQ(D::sphere_regularization(1e-2, full, ceiling), 2.5e-3);
  EXPECT_DOUBLE_EQ(D::sphere_regularization(1e-3, capped, ceiling), 1e-3 / 0.3);
  EXPECT_DOUBLE_EQ(D::sphere_regularization(1e-3, tiny, ceiling), 4e-3);
  EXPECT_DOUBLE_EQ(D::sphere_regularization(5e-3, tiny, ceiling), 1e-2);
  EXPECT_DOUBLE_EQ(D::sphere_regularization(1e-1, tiny, ceiling), 1e-1);
  EXPECT_DOUBLE_EQ(D::sphere_regularization(1e-2, halved, ceiling), 4e-2);
  EXPECT_DOUBLE_EQ(D::sphere_regularization(1e-3, once, ceiling), 1e-3);
  EXPECT_DOUBLE_EQ(D::sphere_regularization(1e-8, full, ceiling), 1e-8);
  EXPECT_DOUBLE_EQ(D::sphere_regularization(1e4, halved, ceiling), 1e4);
}

TEST(Sphere_flow, CappedStepsAfterACrawlRegularizeMore)
{
  // In a polish that a crawling opening started far from the targets
  // (D_area 2.8), capped steps let ε grow past its starting value, up to
  // capped_far_ceiling; nearer the targets (D_area 2.05), or in a polish
  // started otherwise, only back to the start.
  const D::Sphere_flow_settings s;
  ASSERT_GT(s.capped_far_ceiling, s.newton_regularization);
  ASSERT_LT(s.capped_far_above, 2.8);
  ASSERT_LT(s.capped_far_above, s.crawl_far_below);
  ASSERT_GT(s.capped_far_above, s.newton_below);
  D::Flow_step tiny, full;
  tiny.lambda = 1e-3;
  full.lambda = 1;
  EXPECT_DOUBLE_EQ(D::sphere_capped_ceiling(s, 2.8, true), s.capped_far_ceiling);
  EXPECT_DOUBLE_EQ(D::sphere_capped_ceiling(s, 2.8, false), s.newton_regularization);
  EXPECT_DOUBLE_EQ(D::sphere_capped_ceiling(s, 2.05, true), s.newton_regularization);
  double after_crawl = s.newton_regularization, other = s.newton_regularization, near = s.newton_regularization;
  for(int k = 0; k < 20; ++k) {
    after_crawl = D::sphere_regularization(after_crawl, tiny, D::sphere_capped_ceiling(s, 2.8, true));
    other = D::sphere_regularization(other, tiny, D::sphere_capped_ceiling(s, 2.8, false));
    near = D::sphere_regularization(near, tiny, D::sphere_capped_ceiling(s, 2.05, true));
  }
  EXPECT_DOUBLE_EQ(after_crawl, s.capped_far_ceiling);
  EXPECT_DOUBLE_EQ(other, s.newton_regularization);
  EXPECT_DOUBLE_EQ(near, s.newton_regularization);
  // A full step near the targets shrinks the large ε again, by 4.
  EXPECT_DOUBLE_EQ(D::sphere_regularization(after_crawl, full, D::sphere_capped_ceiling(s, 2.05, true)), s.capped_far_ceiling / 4);
}

// The split of a mesh for parallel sweeps: every vertex once, in an
// interior or in the separator; no face with corners in two interiors
// (what lets the interiors move at once); a small separator; regions of
// about equal size.
TEST(Sphere_flow, SweepPartitionSeparatesTheInteriors)
{
  const Index_mesh m = index_mesh(read_sphere_mesh("bunny00"));
  const std::size_t n = m.xyz.size();
  const D::Sweep_partition part(m.xyz, m.faces, 8);
  ASSERT_EQ(part.interior.size(), 8u);
  std::vector<int> region(n, -2);
  for(std::size_t r = 0; r < 8; ++r) {
    EXPECT_GT(part.interior[r].size(), n / 16) << "region " << r;
    for(std::size_t v : part.interior[r]) {
      ASSERT_EQ(region[v], -2) << "vertex " << v << " twice";
      region[v] = int(r);
    }
  }
  for(std::size_t v : part.separator) {
    ASSERT_EQ(region[v], -2) << "vertex " << v << " twice";
    region[v] = -1;
  }
  for(std::size_t v = 0; v < n; ++v) ASSERT_NE(region[v], -2) << "vertex " << v << " missing";
  for(std::size_t t = 0; t < m.faces.size(); ++t) {
    int in = -1;
    for(int k = 0; k < 3; ++k) {
      const int r = region[std::size_t(m.faces[t][k])];
      if(r < 0) continue;
      EXPECT_TRUE(in < 0 || in == r) << "face " << t << " has corners in the interiors " << in << " and " << r;
      in = r;
    }
  }
  EXPECT_LT(part.separator.size(), n / 8) << "the regions are not compact";
}

namespace {

/// The sphere problem of `m` (targets from its areas) and the library's
/// certified Tutte start; false if either fails.
bool certified_tutte_start(const Index_mesh& m, D::Sphere_problem& P, std::vector<V3>& start)
{
  P.xyz = m.xyz;
  P.faces = m.faces;
  return D::validate_sphere_geometry(P, {}).ok() &&
         D::certified_sphere_initial_map<D::Default_spd_solver>(P, start, false).certified;
}

} // namespace

// The sweeps of a large mesh, run on the partition: whatever the number of
// threads, the same points to the last bit; every sweep lowers the energy,
// keeps every face positive by the exact predicate and leaves the areas
// those of the points.
TEST(Sphere_flow, PartitionedSweepsDoNotDependOnTheThreads)
{
  const Index_mesh m = index_mesh(read_sphere_mesh("bunny00"));
  D::Sphere_problem P;
  std::vector<V3> start;
  ASSERT_TRUE(certified_tutte_start(m, P, start));
  const D::Weighted_area_energy energy(P.target, 0.5);
  const D::Vertex_faces around(start.size(), P.faces);
  const D::Sweep_partition part(P.xyz, P.faces, 8);
  std::vector<std::vector<V3> > result;
  for(int threads : { 1, 2, 3 }) {
    std::vector<V3> p = start;
    std::vector<double> u, w;
    D::signed_areas_sphere(p, P.faces, u);
    D::cone_areas_sphere(p, P.faces, w);
    double E = energy.value(u) + 0.03 * energy.value(w);
    for(int sweep = 0; sweep < 3; ++sweep) {
      const D::Relaxation_outcome r = D::relax_sphere_vertices(P.faces, around, energy, 0.03, 0.8, part, threads, p, u, w);
      EXPECT_GT(r.moved, p.size() / 2);
      std::vector<double> u_now, w_now;
      D::signed_areas_sphere(p, P.faces, u_now);
      D::cone_areas_sphere(p, P.faces, w_now);
      for(std::size_t t = 0; t < P.faces.size(); ++t) {
        ASSERT_NEAR(u[t], u_now[t], 1e-12 * u_now[t]) << "face " << t;
        ASSERT_NEAR(w[t], w_now[t], 1e-12 * w_now[t]) << "face " << t;
      }
      const double E_now = energy.value(u_now) + 0.03 * energy.value(w_now);
      EXPECT_LT(E_now, E) << "sweep " << sweep << ", " << threads << " threads";
      E = E_now;
    }
    EXPECT_EQ(exact_sphere_signs(p, P.faces).pos, P.faces.size());
    result.push_back(p);
  }
  EXPECT_TRUE(result[1] == result[0]) << "2 threads differ from 1";
  EXPECT_TRUE(result[2] == result[0]) << "3 threads differ from 1";
}

// The certified flow's large-mesh path (parallel sweeps, fewer of them,
// coarse supernodes, the reused factorisation in the opening) on a mesh
// made to count as large: goals met, certified, and the same map on 1 and
// on 2 threads.
TEST(Sphere_flow, LargeMeshPathMeetsTheGoalsOnAnyNumberOfThreads)
{
  const Index_mesh m = index_mesh(read_sphere_mesh("homer"));
  D::Sphere_problem P;
  std::vector<V3> start;
  ASSERT_TRUE(certified_tutte_start(m, P, start));
  D::Sphere_flow_settings settings;
  settings.large_from = 0;
  std::vector<std::vector<V3> > result;
  std::size_t iterations = 0;
  for(int threads : { 1, 2 }) {
    SMP::Discrete_lie_flow_options opt;
    opt.sphere.threads = threads;
    std::vector<V3> p = start;
    D::Default_spd_solver solver;
    D::Sphere_certified_flow<D::Default_spd_solver> flow(P, p, opt, solver, settings);
    const D::Flow_outcome out = D::run_flow(flow, opt);
    EXPECT_EQ(int(out.stop_reason), int(SMP::Discrete_lie_flow_stop_reason::CONVERGED));
    EXPECT_LT(out.factorizations, out.iterations) << "no opening step reused its factorisation";
    EXPECT_EQ(exact_sphere_signs(p, P.faces).pos, P.faces.size());
    const std::pair<double, double> d = sphere_d_area(m.xyz, p, m.faces);
    EXPECT_LE(d.first, 2.01 + 1e-9);
    EXPECT_LE(d.second, 0.02);
    iterations = out.iterations;
    result.push_back(p);
  }
  EXPECT_GT(iterations, 0u);
  EXPECT_TRUE(result[1] == result[0]) << "2 threads differ from 1";
}

TEST(Sphere_map, TinyMeshes)
{
  // Few faces: the map exists and is certified; the area targets may be out of reach.
  for(const char* name : { "tetrahedron", "octahedron", "cube" }) {
    SCOPED_TRACE(name);
    const SM sm = read_sphere_mesh(name);
    const Index_mesh m = index_mesh(sm);
    std::vector<V3> p;
    const SMP::Discrete_lie_flow_report r = map_to_sphere(sm, p);
    ASSERT_EQ(r.status, SMP::OK) << r.message;
    EXPECT_EQ(exact_sphere_signs(p, m.faces).pos, m.faces.size());
    for(const V3& q : p) EXPECT_NEAR(std::sqrt(D::dot(q, q)), 1., 1e-12);
  }
}

TEST(Sphere_map, ScaleInvarianceAndCallback)
{
  SM sm = read_sphere_mesh("ellipsoid");
  std::vector<V3> p1, p2, p3;
  const SMP::Discrete_lie_flow_report r1 = map_to_sphere(sm, p1);
  SM small = sm, large = sm;
  for(SM_vertex v : vertices(small)) small.point(v) = CGAL::ORIGIN + (small.point(v) - CGAL::ORIGIN) * 1e-8;
  for(SM_vertex v : vertices(large)) large.point(v) = CGAL::ORIGIN + (large.point(v) - CGAL::ORIGIN) * 1e8;
  const SMP::Discrete_lie_flow_report r2 = map_to_sphere(small, p2), r3 = map_to_sphere(large, p3);
  ASSERT_EQ(r2.status, SMP::OK);
  ASSERT_EQ(r3.status, SMP::OK);
  EXPECT_EQ(r1.iterations, r2.iterations);
  EXPECT_EQ(r1.iterations, r3.iterations);
  EXPECT_NEAR(r1.final_d_area, r2.final_d_area, 1e-9);
  EXPECT_NEAR(r1.final_d_area, r3.final_d_area, 1e-9);

  // Callback: called once per iteration, and stops the flow when it says so.
  SMP::Discrete_lie_flow_options o;
  std::size_t calls = 0;
  o.tolerance = 0; // never converged
  o.callback = [&calls](const SMP::Discrete_lie_flow_iteration& it) { ++calls; EXPECT_EQ(it.iteration, calls); return calls < 3; };
  const SMP::Discrete_lie_flow_report r4 = map_to_sphere(sm, p1, o);
  ASSERT_EQ(r4.status, SMP::OK);
  EXPECT_EQ(calls, 3u);
  EXPECT_EQ(r4.iterations, 3u);
  EXPECT_EQ(r4.stop_reason, SMP::Discrete_lie_flow_stop_reason::INTERRUPTED);
  o.callback = nullptr;
  o.max_iterations = 2;
  const SMP::Discrete_lie_flow_report r5 = map_to_sphere(sm, p1, o);
  EXPECT_EQ(r5.iterations, 2u);
  EXPECT_EQ(r5.stop_reason, SMP::Discrete_lie_flow_stop_reason::ITERATION_CAP);
}

TEST(Sphere_map, DensityDoublesTheAreaOfAHemisphere)
{
  // ρ = 2 on the faces with z > 0: they should take two thirds of the sphere.
  const SM sm = read_sphere_mesh("sphere");
  const Index_mesh m = index_mesh(sm);
  SMP::Discrete_lie_flow_options o;
  o.tolerance = 1e-3;
  for(const Tri& t : m.faces) {
    const double z = m.xyz[std::size_t(t[0])][2] + m.xyz[std::size_t(t[1])][2] + m.xyz[std::size_t(t[2])][2];
    o.face_density.push_back(z > 0 ? 2. : 1.);
  }
  std::vector<V3> p;
  const SMP::Discrete_lie_flow_report r = map_to_sphere(sm, p, o);
  ASSERT_EQ(r.status, SMP::OK) << r.message;
  EXPECT_EQ(exact_sphere_signs(p, m.faces).pos, m.faces.size());
  long double heavy = 0, light = 0, heavy3 = 0, light3 = 0;
  for(std::size_t f = 0; f < m.faces.size(); ++f) {
    const Tri& t = m.faces[f];
    const long double a = flat_area(p[std::size_t(t[0])], p[std::size_t(t[1])], p[std::size_t(t[2])]);
    const long double a3 = flat_area(m.xyz[std::size_t(t[0])], m.xyz[std::size_t(t[1])], m.xyz[std::size_t(t[2])]);
    (o.face_density[f] > 1 ? heavy : light) += a;
    (o.face_density[f] > 1 ? heavy3 : light3) += a3;
  }
  // The README's promise: converged with each region's share (of the flat
  // triangles' area, the measure the flow holds) within 0.5%, relative.
  EXPECT_EQ(r.stop_reason, SMP::Discrete_lie_flow_stop_reason::CONVERGED) << SMP::discrete_lie_flow_stop_reason_name(r.stop_reason);
  const long double prescribed = 2 * heavy3 / (2 * heavy3 + light3), achieved = heavy / (heavy + light);
  EXPECT_LE(double(std::fabs(achieved - prescribed) / prescribed), 5e-3);
  EXPECT_LE(double(std::fabs(achieved - prescribed) / (1 - prescribed)), 5e-3);
}

} // namespace

// ---------------------------------------------------------------------------
// The start: conformal (the paper's kind) and the caller's own
// ---------------------------------------------------------------------------

namespace {

/// Mean |angle on the flat sphere triangle − angle on the 3D triangle| over
/// every corner, in radians: 0 for a conformal map of fine meshes.
double mean_angle_error(const std::vector<V3>& xyz, const std::vector<V3>& p, const std::vector<Tri>& faces)
{
  auto angle = [](const V3& a, const V3& b, const V3& c) {
    const V3 u = D::sub(b, a), v = D::sub(c, a);
    return std::atan2(D::norm3(D::cross(u, v)), D::dot(u, v));
  };
  double sum = 0;
  for(const Tri& t : faces)
    for(int k = 0; k < 3; ++k) {
      const std::size_t a = std::size_t(t[k]), b = std::size_t(t[(k + 1) % 3]), c = std::size_t(t[(k + 2) % 3]);
      sum += std::fabs(angle(p[a], p[b], p[c]) - angle(xyz[a], xyz[b], xyz[c]));
    }
  return sum / double(3 * faces.size());
}

} // namespace

// The cotangent-harmonic start is certified and far closer to conformal
// than Tutte's (uniform weights ignore the triangles' shapes) on smooth
// meshes (measured mean errors: ellipe0.003 0.066 against 0.212 rad, bear
// 0.058 against 0.189; on scanned or coarse meshes the angle defects at the
// vertices dominate both); the flow from it reaches the goals. Exact
// orientations and angles are recomputed here.
TEST(Sphere_start, ConformalStartIsCertifiedAndConformal)
{
  for(const char* name : { "ellipe0.003", "bear" }) {
    SCOPED_TRACE(name);
    const Index_mesh m = index_mesh(read_sphere_mesh(name));
    D::Sphere_problem P;
    P.xyz = m.xyz;
    P.faces = m.faces;
    ASSERT_TRUE(D::validate_sphere_geometry(P, {}).ok());
    std::vector<V3> tutte, conformal;
    const D::Sphere_initial_outcome t = D::certified_sphere_initial_map<D::Default_spd_solver>(P, tutte, false);
    const D::Sphere_initial_outcome c = D::certified_sphere_initial_map<D::Default_spd_solver>(P, conformal, true);
    ASSERT_TRUE(t.certified) << t.message;
    ASSERT_TRUE(c.certified) << c.message;
    EXPECT_EQ(exact_sphere_signs(conformal, m.faces).pos, m.faces.size());
    const double et = mean_angle_error(m.xyz, tutte, m.faces), ec = mean_angle_error(m.xyz, conformal, m.faces);
    EXPECT_LT(ec, 0.5 * et) << "tutte " << et << " conformal " << ec;
    EXPECT_LT(ec, 0.08) << "mean angle error of the conformal start, radians";
  }
  const SM cow = read_sphere_mesh("cow");
  SMP::Discrete_lie_flow_options o;
  o.sphere.start = SMP::Discrete_lie_flow_sphere_start::CONFORMAL;
  std::vector<V3> p;
  const SMP::Discrete_lie_flow_report r = map_to_sphere(cow, p, o);
  ASSERT_EQ(int(r.status), int(SMP::OK)) << r.message;
  EXPECT_EQ(int(r.sphere_start), int(SMP::Discrete_lie_flow_sphere_start::CONFORMAL));
  const Index_mesh m = index_mesh(cow);
  EXPECT_EQ(exact_sphere_signs(p, m.faces).pos, m.faces.size());
  EXPECT_LE(sphere_d_area(m.xyz, p, m.faces).first, 2.01 + 1e-9);
}

// Tutte's start reweighted by the area ratios: on camel (Tutte's start
// compressed to D_area 4.8e13) it is certified by the exact predicate, far
// less compressed, and no face holds a larger share of the sphere; the
// D_area it reports is the flat one recomputed here. On a mesh below
// `min_faces` (cow, sphere) the start is Tutte's, unchanged; and where every
// round is refused (cow with no size limit: no reweighted map lifts to a
// certified one) the map is left as it was.
TEST(Sphere_start, ReweightedTutteStartIsCertifiedAndLessCompressed)
{
  // Per mesh: whether the reweighting runs (above `min_faces` and far from
  // the targets), and whether every round is refused without a size limit.
  struct Row { const char* name; bool reweighted; bool refused_without_size_limit; };
  for(const Row row : { Row{ "camel", true, false }, Row{ "cow", false, true }, Row{ "sphere", false, false } }) {
    const char* name = row.name;
    SCOPED_TRACE(name);
    const Index_mesh m = index_mesh(read_sphere_mesh(name));
    D::Sphere_problem P;
    P.xyz = m.xyz;
    P.faces = m.faces;
    ASSERT_TRUE(D::validate_sphere_geometry(P, {}).ok());
    std::vector<V3> plain, reweighted;
    const D::Sphere_initial_outcome t = D::certified_sphere_initial_map<D::Default_spd_solver>(P, plain);
    const D::Sphere_initial_outcome r =
      D::certified_sphere_initial_map<D::Default_spd_solver>(P, reweighted, false, 3, true, false, true);
    ASSERT_TRUE(t.certified) << t.message;
    ASSERT_TRUE(r.certified) << r.message;
    EXPECT_EQ(t.reweightings, 0u);
    EXPECT_EQ(r.puncture, t.puncture);
    EXPECT_EQ(exact_sphere_signs(reweighted, m.faces).pos, m.faces.size());
    const double d_plain = sphere_d_area(m.xyz, plain, m.faces).first;
    const double d_reweighted = sphere_d_area(m.xyz, reweighted, m.faces).first;
    EXPECT_NEAR(d_reweighted, r.d_area, 1e-9 * d_reweighted);
    if(row.reweighted) {
      EXPECT_GE(r.reweightings, 1u);
      EXPECT_GT(d_plain, 1e13);
      EXPECT_LT(d_reweighted, 1e-6 * d_plain);
      EXPECT_LE(D::largest_face_share(reweighted, m.faces), D::largest_face_share(plain, m.faces));
    } else {
      EXPECT_EQ(r.reweightings, 0u);
      EXPECT_TRUE(reweighted == plain);
    }
    if(row.refused_without_size_limit) {
      D::Sphere_reweighting any_size;
      any_size.min_faces = 0;
      std::vector<V3> q = plain;
      double d = t.d_area, scale = t.scale;
      EXPECT_EQ(D::reweighted_tutte_map<D::Default_spd_solver>(P, t.puncture, D::Area_barrier_energy(P.target), q, d,
                                                               scale, any_size), 0u);
      EXPECT_TRUE(q == plain);
      EXPECT_EQ(d, t.d_area);
    }
  }
}

// Floater's mean-value weights of a flat fan, summed from the directed face
// contributions, equal the textbook formula (tan(α⁻/2) + tan(α⁺/2)) / |x_j − x_i|
// computed here from the angles by acos, and they reproduce the centre (linear
// precision), also when two spokes are collinear as at a needle fan's centre.
// The fan lies in a tilted plane, so nothing depends on z = 0.
TEST(Sphere_start, MeanValueWeightsOfAFlatFan)
{
  const double pi = 3.14159265358979323846;
  const V3 centre{{ 0.3, -0.2, 0.1 }}, e1{{ 0.8, 0.6, 0 }}, e2{{ -0.36, 0.48, 0.8 }}; // orthonormal
  // Spokes: angles and lengths; the 1st and the 4th are collinear through the centre.
  const double angle[] = { 0, 0.9, 2.0, pi, 3.9, 5.1 };
  const double length[] = { 1e-3, 0.7, 1.3, 2.0, 0.4, 0.9 };
  const int n = 6;
  D::Sphere_problem P;
  P.xyz.push_back(centre);
  for(int j = 0; j < n; ++j) {
    const double x = length[j] * std::cos(angle[j]), y = length[j] * std::sin(angle[j]);
    P.xyz.push_back(V3{{ centre[0] + x * e1[0] + y * e2[0], centre[1] + x * e1[1] + y * e2[1], centre[2] + x * e1[2] + y * e2[2] }});
  }
  for(int j = 0; j < n; ++j) P.faces.push_back(D::Face{{ 0, 1 + j, 1 + (j + 1) % n }});
  const std::vector<double> w = D::mean_value_corner_weights(P);
  ASSERT_EQ(w.size(), 6 * P.faces.size());
  std::vector<double> summed(std::size_t(n + 1), 0.);
  for(std::size_t f = 0; f < P.faces.size(); ++f)
    for(int k = 0; k < 3; ++k)
      if(P.faces[f][k] == 0) {
        summed[std::size_t(P.faces[f][(k + 1) % 3])] += w[6 * f + 2 * std::size_t(k)];
        summed[std::size_t(P.faces[f][(k + 2) % 3])] += w[6 * f + 2 * std::size_t(k) + 1];
      }
  auto spoke_angle = [&](int a, int b) {
    const V3 u = D::sub(P.xyz[std::size_t(a)], centre), v = D::sub(P.xyz[std::size_t(b)], centre);
    return std::acos(D::dot(u, v) / (D::norm3(u) * D::norm3(v)));
  };
  V3 combination{{ 0, 0, 0 }};
  double total = 0;
  for(int j = 1; j <= n; ++j) {
    const int before = 1 + (j + n - 2) % n, after = 1 + j % n;
    const double expected = (std::tan(spoke_angle(before, j) / 2) + std::tan(spoke_angle(j, after) / 2)) /
                            D::norm3(D::sub(P.xyz[std::size_t(j)], centre));
    EXPECT_NEAR(summed[std::size_t(j)], expected, 1e-12 * expected) << "spoke " << j;
    EXPECT_GT(summed[std::size_t(j)], 0);
    for(int c = 0; c < 3; ++c) combination[std::size_t(c)] += summed[std::size_t(j)] * P.xyz[std::size_t(j)][std::size_t(c)];
    total += summed[std::size_t(j)];
  }
  for(int c = 0; c < 3; ++c) EXPECT_NEAR(combination[std::size_t(c)] / total, centre[std::size_t(c)], 1e-13);
}

// The mean-value start is certified by the exact predicate on a mesh with
// slivers and on a data-set mesh. On fans of needles it keeps the needles
// as thin as in 3D, and compressed by the Tutte-like map they fall below
// what doubles on the unit sphere resolve: on cow with needles every
// puncture is refused (measured; the coarse start of `Sphere_map.
// SplitVerticesStartFromTheCoarseMesh` maps such meshes), and a refused
// start leaves the output untouched. Reported as such when used.
TEST(Sphere_start, MeanValueStartIsCertified)
{
  struct Case { const char* name; std::vector<dlf_benchmark::Irregular_step> steps; bool certified; };
  for(const Case& c : { Case{ "bear_bis", { { "decimate", 20 }, { "jitter", 90 } }, true }, Case{ "bear_bis", {}, true },
                        Case{ "cow", { { "needles", 2 } }, false } }) {
    SCOPED_TRACE(c.name + std::string(c.steps.empty() ? "" : " irregular"));
    SM sm = read_sphere_mesh(c.name);
    dlf_benchmark::make_irregular(sm, c.steps);
    const Index_mesh m = index_mesh(sm);
    D::Sphere_problem P;
    P.xyz = m.xyz;
    P.faces = m.faces;
    ASSERT_TRUE(D::validate_sphere_geometry(P, {}).ok());
    std::vector<V3> p;
    const D::Sphere_initial_outcome o =
      D::certified_sphere_initial_map<D::Default_spd_solver>(P, p, false, 3, true, false, true, true);
    ASSERT_EQ(o.certified, c.certified) << o.message;
    if(!o.certified) {
      EXPECT_TRUE(p.empty());
      EXPECT_NE(o.message.find("floating point"), std::string::npos) << o.message;
      continue;
    }
    const Sphere_signs s = exact_sphere_signs(p, m.faces);
    EXPECT_EQ(s.pos, m.faces.size()) << s.neg << " inverted, " << s.zero << " degenerate";
    EXPECT_NEAR(sphere_d_area(m.xyz, p, m.faces).first, o.d_area, 1e-9 * o.d_area);
  }
  SMP::Discrete_lie_flow_options o;
  o.sphere.start = SMP::Discrete_lie_flow_sphere_start::MEAN_VALUE;
  std::vector<V3> p;
  const SMP::Discrete_lie_flow_report r = map_to_sphere(read_sphere_mesh("blobby"), p, o);
  ASSERT_EQ(int(r.status), int(SMP::OK)) << r.message;
  EXPECT_EQ(int(r.sphere_start), int(SMP::Discrete_lie_flow_sphere_start::MEAN_VALUE));
  EXPECT_STREQ(SMP::discrete_lie_flow_sphere_start_name(r.sphere_start), "mean-value");
}

// Fans of needles (benchmark/irregular_meshes.h: a matching of edges, each
// split at two points) coarsen back to the mesh they were made from: every
// split point goes, the coarse faces are the original ones (the generator
// keeps the original vertices' indices first), the targets are conserved, and
// each split point's fraction is its 3D fraction along the edge.
TEST(Sphere_start, SplitVerticesCoarsenToTheOriginalMesh)
{
  const SM original = read_sphere_mesh("cow");
  SM sm = original;
  dlf_benchmark::make_irregular(sm, { { "needles", 2 } });
  const Index_mesh m0 = index_mesh(original), m = index_mesh(sm);
  ASSERT_GT(m.xyz.size(), m0.xyz.size());
  D::Sphere_problem P;
  P.xyz = m.xyz;
  P.faces = m.faces;
  ASSERT_TRUE(D::validate_sphere_geometry(P, {}).ok());
  // Exact edge splits (straight up to rounding) coarsen to exactly cow.
  const D::Split_vertex_coarsening c = D::coarsen_split_vertices(P, 1e-6);
  EXPECT_EQ(c.removed.size(), m.xyz.size() - m0.xyz.size());
  ASSERT_EQ(c.coarse.faces.size(), m0.faces.size());
  for(std::size_t v = 0; v < m0.xyz.size(); ++v) ASSERT_EQ(c.coarse_index[v], int(v));
  auto canonical = [](Tri t) { std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end()); return t; };
  std::vector<Tri> expected, got;
  for(const Tri& t : m0.faces) expected.push_back(canonical(t));
  for(const Tri& t : c.coarse.faces) got.push_back(canonical(t));
  std::sort(expected.begin(), expected.end());
  std::sort(got.begin(), got.end());
  EXPECT_TRUE(got == expected);
  double fine = 0, coarse = 0;
  for(double t : P.target) fine += t;
  for(double t : c.coarse.target) coarse += t;
  EXPECT_NEAR(coarse, fine, 1e-12 * fine);
  for(const D::Split_vertex& s : c.removed) {
    const V3 ab = D::sub(m.xyz[std::size_t(s.b)], m.xyz[std::size_t(s.a)]);
    const V3 av = D::sub(m.xyz[std::size_t(s.v)], m.xyz[std::size_t(s.a)]);
    ASSERT_NEAR(s.t, D::norm3(av) / D::norm3(ab), 1e-9);
  }
  // Nothing to remove on the data-set mesh itself.
  D::Sphere_problem Q;
  Q.xyz = m0.xyz;
  Q.faces = m0.faces;
  ASSERT_TRUE(D::validate_sphere_geometry(Q, {}).ok());
  EXPECT_TRUE(D::coarsen_split_vertices(Q, 1e-6).removed.empty());
  // Within the default tolerance a few of cow's own vertices are nearly
  // straight, too few for the coarse start (its map below is untouched).
  EXPECT_LT(double(D::coarsen_split_vertices(Q).removed.size()),
            D::Split_vertex_settings().least_fraction * double(Q.xyz.size()));
}

// The default certified map of a mesh with fans of needles starts from its
// coarse mesh: the prolongated start and the result are certified by the
// exact predicate here, and the goals are met; the data-set mesh itself
// starts as before (no split vertices).
TEST(Sphere_map, SplitVerticesStartFromTheCoarseMesh)
{
  SM sm = read_sphere_mesh("cow");
  const std::size_t before = num_vertices(sm);
  dlf_benchmark::make_irregular(sm, { { "needles", 2 } });
  const Index_mesh m = index_mesh(sm);
  std::vector<V3> p;
  const SMP::Discrete_lie_flow_report r = map_to_sphere(sm, p);
  ASSERT_EQ(int(r.status), int(SMP::OK)) << r.message;
  // Nearly every split point goes (a few of cow's own nearly straight
  // vertices of degree 4 go first and hold some back).
  EXPECT_GE(double(r.split_vertices_removed), 0.95 * double(m.xyz.size() - before));
  EXPECT_LE(r.split_vertices_removed, m.xyz.size() - before + before / 10);
  EXPECT_GT(r.coarse_iterations, 0u);
  EXPECT_EQ(r.initial_metrics.inverted_faces, 0u);
  const Sphere_signs s = exact_sphere_signs(p, m.faces);
  EXPECT_EQ(s.pos, m.faces.size()) << s.neg << " inverted, " << s.zero << " degenerate";
  const std::pair<double, double> d = sphere_d_area(m.xyz, p, m.faces);
  EXPECT_LE(d.first, 2.01 + 1e-9);
  EXPECT_LE(d.second, 0.02);
  std::vector<V3> q;
  const SMP::Discrete_lie_flow_report plain = map_to_sphere(read_sphere_mesh("cow"), q);
  ASSERT_EQ(int(plain.status), int(SMP::OK)) << plain.message;
  EXPECT_EQ(plain.split_vertices_removed, 0u);
  EXPECT_EQ(plain.coarse_iterations, 0u);
}

// Split points moved off their edges (needles, then a tangential jitter of
// 20%) are not straight up to rounding but within the default tolerance:
// the default map still starts from the coarse mesh, certified, goals met.
TEST(Sphere_map, JitteredSplitVerticesStartFromTheCoarseMesh)
{
  SM sm = read_sphere_mesh("cow");
  const std::size_t before = num_vertices(sm);
  dlf_benchmark::make_irregular(sm, { { "needles", 2 }, { "jitter", 20 } });
  const Index_mesh m = index_mesh(sm);
  D::Sphere_problem P;
  P.xyz = m.xyz;
  P.faces = m.faces;
  ASSERT_TRUE(D::validate_sphere_geometry(P, {}).ok());
  const std::size_t added = m.xyz.size() - before;
  EXPECT_LT(D::coarsen_split_vertices(P, 1e-6).removed.size(), added / 10); // no longer exact splits
  std::vector<V3> p;
  const SMP::Discrete_lie_flow_report r = map_to_sphere(sm, p);
  ASSERT_EQ(int(r.status), int(SMP::OK)) << r.message;
  EXPECT_GE(r.split_vertices_removed, added / 2);
  const Sphere_signs s = exact_sphere_signs(p, m.faces);
  EXPECT_EQ(s.pos, m.faces.size()) << s.neg << " inverted, " << s.zero << " degenerate";
  const std::pair<double, double> d = sphere_d_area(m.xyz, p, m.faces);
  EXPECT_LE(d.first, 2.01 + 1e-9);
  EXPECT_LE(d.second, 0.02);
}

// A caller's start: an earlier result starts a run that has nothing left to
// do; a folded one, a point at the centre and GIVEN without a map are refused.
TEST(Sphere_start, GivenStartIsCertifiedAndUsed)
{
  const SM sm = read_sphere_mesh("blobby");
  const Index_mesh m = index_mesh(sm);
  std::vector<V3> first;
  const SMP::Discrete_lie_flow_report r1 = map_to_sphere(sm, first);
  ASSERT_EQ(int(r1.status), int(SMP::OK)) << r1.message;

  auto run_from = [&](const std::vector<V3>& start, std::vector<V3>& out) {
    SM copy = sm;
    auto init = copy.add_property_map<SM_vertex, K::Point_3>("v:start").first;
    for(SM_vertex v : vertices(copy)) {
      const V3& q = start[v.idx()];
      init[v] = K::Point_3(3 * q[0], 3 * q[1], 3 * q[2]); // scaled off the sphere: normalised by the library
    }
    auto sphere = copy.add_property_map<SM_vertex, K::Point_3>("v:sphere").first;
    SMP::Discrete_lie_flow_sphere_parameterizer_3<SM> dlf;
    dlf.set_initial_map(init);
    dlf.parameterize(copy, sphere);
    out.clear();
    for(SM_vertex v : vertices(copy)) out.push_back({{ sphere[v].x(), sphere[v].y(), sphere[v].z() }});
    return dlf.report();
  };
  std::vector<V3> second;
  const SMP::Discrete_lie_flow_report r2 = run_from(first, second);
  ASSERT_EQ(int(r2.status), int(SMP::OK)) << r2.message;
  EXPECT_EQ(int(r2.sphere_start), int(SMP::Discrete_lie_flow_sphere_start::GIVEN));
  EXPECT_EQ(r2.puncture_face, -1);
  EXPECT_NEAR(r2.initial_metrics.d_area, sphere_d_area(m.xyz, first, m.faces).first, 1e-9);
  EXPECT_LE(r2.iterations, 1u);
  EXPECT_EQ(exact_sphere_signs(second, m.faces).pos, m.faces.size());

  // Swap the points of the two ends of an edge: the faces around it fold.
  std::vector<V3> folded = first;
  std::swap(folded[std::size_t(m.faces[0][0])], folded[std::size_t(m.faces[0][1])]);
  SMP::Discrete_lie_flow_report r3 = run_from(folded, second);
  EXPECT_EQ(int(r3.status), int(SMP::ERROR_INITIAL_MAP_FOLDED));
  EXPECT_NE(r3.message.find("inverted"), std::string::npos) << r3.message;
  EXPECT_NE(r3.message.find("first: face"), std::string::npos) << r3.message;

  std::vector<V3> centred = first;
  centred[5] = {{ 0, 0, 0 }};
  r3 = run_from(centred, second);
  EXPECT_EQ(int(r3.status), int(SMP::ERROR_INITIAL_MAP_FOLDED));
  EXPECT_NE(r3.message.find("vertex 5 is at the centre"), std::string::npos) << r3.message;

  SMP::Discrete_lie_flow_options o;
  o.sphere.start = SMP::Discrete_lie_flow_sphere_start::GIVEN;
  EXPECT_EQ(int(map_to_sphere(sm, second, o).status), int(SMP::ERROR_WRONG_PARAMETER));
}

// ---------------------------------------------------------------------------
// Coarse to fine
// ---------------------------------------------------------------------------

namespace {

/// The undirected edges of `faces` with the number of faces on each.
std::map<std::pair<int, int>, int> sphere_edge_faces(const std::vector<Tri>& faces)
{
  std::map<std::pair<int, int>, int> e;
  for(const Tri& t : faces)
    for(int k = 0; k < 3; ++k) ++e[std::minmax(t[k], t[(k + 1) % 3])];
  return e;
}

/// Options that send a data-set mesh through the coarse levels.
SMP::Discrete_lie_flow_options sphere_coarse_to_fine_options(std::size_t faces = 8000)
{
  SMP::Discrete_lie_flow_options o;
  o.sphere.coarse_to_fine_faces = faces;
  return o;
}

} // namespace

// Each level of homer's hierarchy: a closed manifold of genus 0 (every edge
// on two faces, χ = 2, one face per oriented edge), the whole target area,
// no two neighbours removed; then the coarsest level's map carried down
// level by level gives every finer face positive again (CGAL's predicate).
TEST(Sphere_coarse_to_fine, LevelsKeepGenusZeroTheTargetsAndPositiveFaces)
{
  const Index_mesh m = index_mesh(read_sphere_mesh("homer"));
  D::Sphere_problem P;
  P.xyz = m.xyz;
  P.faces = m.faces;
  ASSERT_TRUE(D::validate_sphere_geometry(P, {}).ok());
  long double total = 0;
  for(double a : P.target) total += a;
  const std::vector<D::Collapse_level> levels = D::build_sphere_levels(P, 1600, D::Sphere_coarse_to_fine_settings());
  ASSERT_GE(levels.size(), 4u);
  std::vector<Tri> faces = m.faces;
  for(const D::Collapse_level& L : levels) {
    const std::string at = "level of " + std::to_string(L.faces.size()) + " faces: ";
    const std::set<int> gone(L.from_above.removed.begin(), L.from_above.removed.end());
    ASSERT_EQ(gone.size(), L.from_above.removed.size());
    ASSERT_GT(gone.size(), 0u);
    for(const auto& e : sphere_edge_faces(faces)) EXPECT_FALSE(gone.count(e.first.first) && gone.count(e.first.second)) << at << "neighbours removed";
    std::set<int> used;
    std::set<std::pair<int, int> > directed;
    for(const Tri& t : L.faces) {
      for(int k = 0; k < 3; ++k) {
        ASSERT_EQ(gone.count(t[k]), 0u) << at << "a removed vertex is still used";
        used.insert(t[k]);
        EXPECT_TRUE(directed.insert(std::make_pair(t[k], t[(k + 1) % 3])).second) << at << "an oriented edge twice";
      }
    }
    const std::map<std::pair<int, int>, int> e = sphere_edge_faces(L.faces);
    for(const auto& x : e) EXPECT_EQ(x.second, 2) << at << "edge " << x.first.first << "-" << x.first.second;
    EXPECT_EQ(long(used.size()) - long(e.size()) + long(L.faces.size()), 2) << at << "not genus 0";
    long double sum = 0;
    for(double a : L.target) { EXPECT_GT(a, 0); sum += a; }
    EXPECT_NEAR(double(sum / total), 1.0, 1e-12) << at << "target area lost";
    faces = L.faces;
  }
  // The coarsest level mapped (its own certified start, flowed), then
  // carried down level by level: every finer face positive right after the
  // removed vertices are put back, and again after the level's sweeps.
  const SMP::Discrete_lie_flow_options opt;
  const D::Sphere_coarse_to_fine_settings settings;
  std::vector<V3> p(m.xyz.size(), V3{{ 0, 0, 0 }});
  SMP::Discrete_lie_flow_level top;
  ASSERT_TRUE(D::flow_coarsest_sphere_level<D::Default_spd_solver>(P, levels.back(), opt, settings, p, top));
  EXPECT_EQ(top.faces, levels.back().faces.size());
  EXPECT_LE(top.d_area, 2.01);
  const std::vector<std::size_t> order = D::morton_order(m.xyz);
  for(std::size_t l = levels.size(); l-- > 0;) {
    const std::vector<Tri>& F = l == 0 ? m.faces : levels[l - 1].faces;
    std::vector<V3> put_back = p;
    ASSERT_TRUE(D::prolong_sphere_level(levels[l].from_above, m.xyz, put_back)) << "level " << l;
    EXPECT_EQ(exact_sphere_signs(put_back, F).pos, F.size()) << "a face carried down to " << F.size() << " faces is not positive";
    for(int v : levels[l].from_above.removed) EXPECT_NEAR(std::sqrt(D::dot(put_back[std::size_t(v)], put_back[std::size_t(v)])), 1., 1e-12);
    const double d = D::carry_down_sphere_level(levels[l].from_above, F, l == 0 ? P.target : levels[l - 1].target, m.xyz, order, 1,
                                                l == 0, opt, settings, p);
    ASSERT_FALSE(std::isnan(d)) << "level " << l;
    EXPECT_EQ(exact_sphere_signs(p, F).pos, F.size()) << "a face swept on " << F.size() << " faces is not positive";
  }
  // The coarsest level's own Tutte start, mirrored: no removed vertex has a
  // positive star to go to.
  D::Sphere_problem C;
  std::vector<int> index(m.xyz.size(), -1), vertex_of;
  C.faces = levels.back().faces;
  for(Tri& t : C.faces)
    for(int& v : t) {
      if(index[std::size_t(v)] < 0) { index[std::size_t(v)] = int(vertex_of.size()); vertex_of.push_back(v); C.xyz.push_back(m.xyz[std::size_t(v)]); }
      v = index[std::size_t(v)];
    }
  C.target = levels.back().target;
  std::vector<V3> q;
  ASSERT_TRUE(D::certified_sphere_initial_map<D::Default_spd_solver>(C, q, false).certified);
  std::vector<V3> mirrored(m.xyz.size(), V3{{ 0, 0, 0 }});
  for(std::size_t i = 0; i < vertex_of.size(); ++i) mirrored[std::size_t(vertex_of[i])] = {{ q[i][0], q[i][1], -q[i][2] }};
  EXPECT_FALSE(D::prolong_sphere_level(levels.back().from_above, m.xyz, mirrored));
}

// The public entry point coarse to fine: the goals and the exact signs of
// the caller's faces, the levels in the report (coarsest first, growing to
// the caller's mesh, the coarsest flowed), and the same map on one and two
// threads, to the last bit.
TEST(Sphere_coarse_to_fine, MapMeetsTheGoalsOnAnyNumberOfThreads)
{
  const SM sm = read_sphere_mesh("homer");
  const Index_mesh m = index_mesh(sm);
  std::vector<std::vector<V3> > result;
  for(int threads : { 1, 2 }) {
    SMP::Discrete_lie_flow_options o = sphere_coarse_to_fine_options();
    o.sphere.threads = threads;
    std::vector<V3> p;
    const SMP::Discrete_lie_flow_report r = map_to_sphere(sm, p, o);
    ASSERT_EQ(r.status, SMP::OK) << r.message;
    EXPECT_EQ(r.stop_reason, SMP::Discrete_lie_flow_stop_reason::CONVERGED);
    EXPECT_EQ(exact_sphere_signs(p, m.faces).pos, m.faces.size());
    const std::pair<double, double> d = sphere_d_area(m.xyz, p, m.faces);
    EXPECT_LE(d.first, 2.01 + 1e-9);
    EXPECT_LE(d.second, 0.02);
    const auto& L = r.levels;
    ASSERT_GE(L.size(), 3u) << "no coarse levels: " << r.levels_refused;
    EXPECT_TRUE(r.levels_refused.empty()) << r.levels_refused;
    EXPECT_GT(L.front().iterations, 0u);
    EXPECT_LT(L.front().faces, m.faces.size() / 4);
    for(std::size_t k = 1; k < L.size(); ++k) {
      EXPECT_GT(L[k].faces, L[k - 1].faces);
      EXPECT_EQ(L[k].faces + 4, 2 * L[k].vertices) << "a closed genus-0 level has F = 2V - 4";
      EXPECT_EQ(L[k].iterations, 0u);
      EXPECT_GE(L[k].d_area, 2.0);
    }
    EXPECT_EQ(L.back().faces, m.faces.size());
    EXPECT_EQ(L.back().vertices, m.xyz.size());
    EXPECT_NEAR(r.initial_d_area, L.back().d_area, 1e-9 * L.back().d_area) << "the flow did not start from the map carried down";
    result.push_back(p);
  }
  EXPECT_TRUE(result[1] == result[0]) << "2 threads differ from 1";
  // Off: no levels, the plain start.
  std::vector<V3> p;
  const SMP::Discrete_lie_flow_report plain = map_to_sphere(sm, p, sphere_coarse_to_fine_options(0));
  ASSERT_EQ(plain.status, SMP::OK) << plain.message;
  EXPECT_TRUE(plain.levels.empty());
  EXPECT_GT(plain.initial_d_area, 100.);
}

// A tetrahedron has no coarser closed mesh: the levels are refused with
// the reason, and the plain start maps it.
TEST(Sphere_coarse_to_fine, RefusedWhenNoVertexCanGo)
{
  const SM sm = read_sphere_mesh("tetrahedron");
  const Index_mesh m = index_mesh(sm);
  std::vector<V3> p;
  const SMP::Discrete_lie_flow_report r = map_to_sphere(sm, p, sphere_coarse_to_fine_options(1));
  ASSERT_EQ(r.status, SMP::OK) << r.message;
  EXPECT_TRUE(r.levels.empty());
  EXPECT_NE(r.levels_refused.find("no vertex could be removed"), std::string::npos) << r.levels_refused;
  EXPECT_EQ(exact_sphere_signs(p, m.faces).pos, m.faces.size());
}

} // namespace dlf_test_sphere
