// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Discrete Lie Flow parameterizer as a CGAL plug-in: Surface_mesh,
// Polyhedron_3 and Seam_mesh through `parameterize()` (with a temporary and a
// named object), one negative test per error code (with the element named in
// the message), meshes with holes (converged, fold-free, injective, the
// report about the caller's mesh), and the options that end a run (cap,
// callback, stall).

#include <gtest/gtest.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Unique_hash_map.h>
#include <CGAL/boost/graph/Seam_mesh.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_distortion.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <queue>
#include <regex>
#include <set>
#include <string>
#include <vector>

// The tests compile in unity batches (DLF_UNITY_BUILD): each file keeps its
// names in a namespace of its own.
namespace dlf_test_inputs {

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace D = CGAL::Surface_mesh_parameterization::internal::dlf;

namespace {

typedef CGAL::Simple_cartesian<double> K;
typedef K::Point_2 Point_2;
typedef K::Point_3 Point_3;
typedef CGAL::Surface_mesh<Point_3> SM;
typedef SM::Vertex_index SM_vertex;
typedef SM::Face_index SM_face;
typedef boost::graph_traits<SM>::halfedge_descriptor SM_halfedge;
typedef CGAL::Polyhedron_3<K> Poly;
typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_2 EP;
typedef std::array<double, 2> V2;
typedef std::array<double, 3> V3;
typedef std::array<int, 3> Tri;
typedef SMP::Discrete_lie_flow_parameterizer_3<SM> SM_dlf;

std::string mesh_path(const std::string& name) { return std::string(DLF_DATA_DIR) + "/meshes/" + name + ".off"; }

// ---------------------------------------------------------------------------
// Independent checks on any face graph
// ---------------------------------------------------------------------------

struct Indexed
{
  std::vector<V3> xyz;
  std::vector<V2> uv;
  std::vector<Tri> faces;
};

/// Index arrays of a triangle mesh and its uv map (all vertices and faces).
template <class Mesh, class UVmap>
Indexed extract(Mesh& mesh, UVmap uvmap)
{
  Indexed r;
  auto vim = get(CGAL::dynamic_vertex_property_t<int>(), mesh);
  const auto vpm = get(CGAL::vertex_point, mesh);
  int i = 0;
  for(auto v : vertices(mesh)) {
    put(vim, v, i++);
    const auto& p = get(vpm, v);
    r.xyz.push_back({{ CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()) }});
    const Point_2 q = get(uvmap, v);
    r.uv.push_back({{ q.x(), q.y() }});
  }
  for(auto f : faces(mesh)) {
    Tri t; int k = 0;
    for(auto v : vertices_around_face(halfedge(f, mesh), mesh)) { if(k < 3) t[k] = get(vim, v); ++k; }
    EXPECT_EQ(k, 3);
    r.faces.push_back(t);
  }
  return r;
}

struct Signs { std::size_t pos = 0, neg = 0, zero = 0; };
Signs exact_signs(const std::vector<V2>& uv, const std::vector<Tri>& faces)
{
  Signs s;
  for(const Tri& t : faces) {
    const CGAL::Orientation o = CGAL::orientation(EP(uv[t[0]][0], uv[t[0]][1]), EP(uv[t[1]][0], uv[t[1]][1]),
                                                  EP(uv[t[2]][0], uv[t[2]][1]));
    if(o == CGAL::POSITIVE) ++s.pos; else if(o == CGAL::NEGATIVE) ++s.neg; else ++s.zero;
  }
  return s;
}

double d_area(const Indexed& m)
{
  long double A = 0, U = 0;
  std::vector<long double> a(m.faces.size()), u(m.faces.size());
  for(std::size_t f = 0; f < m.faces.size(); ++f) {
    const Tri& t = m.faces[f];
    const V3 &p = m.xyz[t[0]], &q = m.xyz[t[1]], &r = m.xyz[t[2]];
    const long double e[3] = { (long double)q[0] - p[0], (long double)q[1] - p[1], (long double)q[2] - p[2] };
    const long double g[3] = { (long double)r[0] - p[0], (long double)r[1] - p[1], (long double)r[2] - p[2] };
    const long double cx = e[1] * g[2] - e[2] * g[1], cy = e[2] * g[0] - e[0] * g[2], cz = e[0] * g[1] - e[1] * g[0];
    a[f] = 0.5L * std::sqrt(cx * cx + cy * cy + cz * cz);
    const V2 &x = m.uv[t[0]], &y = m.uv[t[1]], &z = m.uv[t[2]];
    u[f] = 0.5L * std::fabs(((long double)y[0] - x[0]) * ((long double)z[1] - x[1]) - ((long double)y[1] - x[1]) * ((long double)z[0] - x[0]));
    A += a[f]; U += u[f];
  }
  long double e = 0;
  for(std::size_t f = 0; f < m.faces.size(); ++f) { const long double w = a[f] / A, v = u[f] / U; e += v + w * w / v; }
  return double(e);
}

/// A valid, area-preserving result: finite, every face of one strict
/// orientation (exact), d_area within the bound.
/// The README's promise: D_area ≤ 2.01, the default tolerance.
const double certified_d_area_bound = 2 + SMP::Discrete_lie_flow_options().tolerance;

void expect_good_map(const Indexed& m, double bound)
{
  for(const V2& p : m.uv) ASSERT_TRUE(std::isfinite(p[0]) && std::isfinite(p[1]));
  const Signs s = exact_signs(m.uv, m.faces);
  EXPECT_EQ(s.zero, 0u) << "degenerate faces";
  EXPECT_EQ((std::min)(s.pos, s.neg), 0u) << "inverted faces: " << s.pos << " positive, " << s.neg << " negative";
  EXPECT_LE(d_area(m), bound);
}

/// The numbers (whole tokens) in a message.
std::set<long> numbers_in(const std::string& msg)
{
  std::set<long> out;
  static const std::regex num("[0-9]+");
  for(auto it = std::sregex_iterator(msg.begin(), msg.end(), num); it != std::sregex_iterator(); ++it)
    out.insert(std::stol(it->str()));
  return out;
}

/// Whether a message identifies a face for the caller: by its index in the
/// caller's numbering ("face N") or by all of its vertices' indices.
::testing::AssertionResult names_face(const std::string& msg, long face_index, const std::vector<long>& vertices)
{
  const std::regex face_n("face ([0-9]+)");
  std::smatch m;
  if(std::regex_search(msg, m, face_n) && std::stol(m[1].str()) == face_index) return ::testing::AssertionSuccess();
  const std::set<long> nums = numbers_in(msg);
  bool all = !vertices.empty();
  for(long v : vertices) all = all && nums.count(v);
  if(all) return ::testing::AssertionSuccess();
  std::ostringstream s;
  s << "the message \"" << msg << "\" names neither face " << face_index << " nor its vertices";
  for(long v : vertices) s << " " << v;
  return ::testing::AssertionFailure() << s.str();
}

// ---------------------------------------------------------------------------
// Small generated meshes
// ---------------------------------------------------------------------------

/// An m×m grid of the unit square (z = 0), two triangles per cell; vertex
/// (i, j) has index j(m+1)+i.
SM grid(int m)
{
  SM sm;
  std::vector<SM_vertex> v;
  for(int j = 0; j <= m; ++j) for(int i = 0; i <= m; ++i) v.push_back(sm.add_vertex(Point_3(double(i) / m, double(j) / m, 0)));
  auto id = [&](int i, int j) { return v[std::size_t(j * (m + 1) + i)]; };
  for(int j = 0; j < m; ++j)
    for(int i = 0; i < m; ++i) {
      sm.add_face(id(i, j), id(i + 1, j), id(i + 1, j + 1));
      sm.add_face(id(i, j), id(i + 1, j + 1), id(i, j + 1));
    }
  return sm;
}

/// An m×n torus grid (radii 2 and 1) without its first face: genus 1, one border loop.
SM torus_with_a_hole(int m, int n)
{
  SM sm;
  std::vector<SM_vertex> v;
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < m; ++i) {
      const double a = 2 * M_PI * i / m, b = 2 * M_PI * j / n;
      v.push_back(sm.add_vertex(Point_3((2 + std::cos(b)) * std::cos(a), (2 + std::cos(b)) * std::sin(a), std::sin(b))));
    }
  auto id = [&](int i, int j) { return v[std::size_t((j % n) * m + (i % m))]; };
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < m; ++i) {
      if(i > 0 || j > 0) sm.add_face(id(i, j), id(i + 1, j), id(i + 1, j + 1));
      sm.add_face(id(i, j), id(i + 1, j + 1), id(i, j + 1));
    }
  return sm;
}

SM_halfedge border_halfedge(const SM& sm)
{
  for(SM_halfedge h : halfedges(sm)) if(is_border(h, sm)) return h;
  return boost::graph_traits<SM>::null_halfedge();
}

bool read_sm(const std::string& name, SM& sm)
{
  std::ifstream in(mesh_path(name));
  return in && (in >> sm) && !faces(sm).empty();
}

/// Calls the member `parameterize()` with the Surface_mesh's own numbering.
struct SM_call
{
  SM& sm;
  SM::Property_map<SM_vertex, Point_2> uv;
  SM::Property_map<SM_vertex, int> vim;
  SM::Property_map<SM_vertex, bool> vpm;
  explicit SM_call(SM& m) : sm(m)
  {
    uv = sm.add_property_map<SM_vertex, Point_2>("v:t_uv", Point_2(0, 0)).first;
    vim = sm.add_property_map<SM_vertex, int>("v:t_index").first;
    vpm = sm.add_property_map<SM_vertex, bool>("v:t_param", false).first;
    for(SM_vertex v : vertices(sm)) vim[v] = int(v.idx());
  }
  // The precise code, the report's; the entry point returns CGAL's nearest one.
  template <class P>
  SMP::Error_code run(P& p, SM_halfedge bhd)
  {
    const SMP::Error_code cgal = p.parameterize(sm, bhd, uv, vim, vpm);
    EXPECT_EQ(cgal, SMP::discrete_lie_flow_cgal_error_code(p.report().status)) << p.report().message;
    EXPECT_LE(int(cgal), int(SMP::ERROR_NO_1_TO_1_MAPPING)) << "a code CGAL's get_error_message explains";
    return p.report().status;
  }
};

// ---------------------------------------------------------------------------
// Mesh types through parameterize()
// ---------------------------------------------------------------------------

TEST(Mesh_types, SurfaceMeshTemporaryAndNamed)
{
  SM sm;
  ASSERT_TRUE(read_sm("nefertiti", sm));
  const SM_halfedge bhd = border_halfedge(sm);
  auto uv = sm.add_property_map<SM_vertex, Point_2>("v:uv").first;
  EXPECT_EQ(SMP::parameterize(sm, SM_dlf(), bhd, uv), SMP::OK);
  expect_good_map(extract(sm, uv), certified_d_area_bound);
  for(SM_vertex v : vertices(sm)) uv[v] = Point_2(0, 0);
  SM_dlf p;
  EXPECT_EQ(SMP::parameterize(sm, p, bhd, uv), SMP::OK);
  const Indexed m = extract(sm, uv);
  expect_good_map(m, certified_d_area_bound);
  // The named object passed by value still sees its run.
  EXPECT_EQ(p.report().status, SMP::OK);
  EXPECT_EQ(p.report().stop_reason, SMP::Discrete_lie_flow_stop_reason::CONVERGED);
  EXPECT_GT(p.report().iterations, 0u);
  EXPECT_NEAR(p.report().final_d_area, d_area(m), 1e-9);
  EXPECT_EQ(p.report().domain_faces.size(), num_faces(sm));
}

TEST(Mesh_types, Polyhedron3TemporaryAndNamed)
{
  Poly poly;
  std::ifstream in(mesh_path("nefertiti"));
  ASSERT_TRUE(in >> poly);
  typedef boost::graph_traits<Poly>::vertex_descriptor vd;
  typedef boost::graph_traits<Poly>::halfedge_descriptor hd;
  typedef CGAL::Unique_hash_map<vd, Point_2> UV_uhm;
  typedef SMP::Discrete_lie_flow_parameterizer_3<Poly> Poly_dlf;
  hd bhd;
  for(hd h : halfedges(poly)) if(is_border(h, poly)) { bhd = h; break; }
  ASSERT_TRUE(is_border(bhd, poly));
  {
    UV_uhm uhm;
    boost::associative_property_map<UV_uhm> uv(uhm);
    EXPECT_EQ(SMP::parameterize(poly, Poly_dlf(), bhd, uv), SMP::OK);
    expect_good_map(extract(poly, uv), certified_d_area_bound);
  }
  {
    UV_uhm uhm;
    boost::associative_property_map<UV_uhm> uv(uhm);
    Poly_dlf p;
    EXPECT_EQ(SMP::parameterize(poly, p, bhd, uv), SMP::OK);
    const Indexed m = extract(poly, uv);
    expect_good_map(m, certified_d_area_bound);
    EXPECT_EQ(p.report().status, SMP::OK);
    EXPECT_EQ(p.report().stop_reason, SMP::Discrete_lie_flow_stop_reason::CONVERGED);
    EXPECT_GT(p.report().iterations, 0u);
    EXPECT_NEAR(p.report().final_d_area, d_area(m), 1e-9);
  }
}

typedef SM::Property_map<boost::graph_traits<SM>::edge_descriptor, bool> Seam_edge_pmap;
typedef SM::Property_map<SM_vertex, bool> Seam_vertex_pmap;
typedef CGAL::Seam_mesh<SM, Seam_edge_pmap, Seam_vertex_pmap> Seam;

/// Vertices of a shortest edge path of `hops` edges from `from` (BFS).
std::vector<SM_vertex> edge_path(const SM& sm, SM_vertex from, std::size_t hops)
{
  std::map<SM_vertex, SM_vertex> parent;
  std::map<SM_vertex, std::size_t> dist;
  std::queue<SM_vertex> q;
  q.push(from); dist[from] = 0;
  SM_vertex last = from;
  while(!q.empty()) {
    const SM_vertex v = q.front(); q.pop();
    if(dist[v] == hops) { last = v; break; }
    for(SM_vertex w : vertices_around_target(halfedge(v, sm), sm))
      if(!dist.count(w)) { dist[w] = dist[v] + 1; parent[w] = v; q.push(w); }
  }
  std::vector<SM_vertex> path(1, last);
  while(path.back() != from) path.push_back(parent[path.back()]);
  return path;
}

TEST(Mesh_types, SeamMeshOfAClosedSphereTemporaryAndNamed)
{
  SM sm;
  ASSERT_TRUE(read_sm("sphere", sm));
  ASSERT_EQ(border_halfedge(sm), boost::graph_traits<SM>::null_halfedge()) << "not closed";
  ASSERT_EQ(long(num_vertices(sm)) - long(num_edges(sm)) + long(num_faces(sm)), 2) << "not genus 0";
  Seam_edge_pmap sem = sm.add_property_map<boost::graph_traits<SM>::edge_descriptor, bool>("e:on_seam", false).first;
  Seam_vertex_pmap svm = sm.add_property_map<SM_vertex, bool>("v:on_seam", false).first;
  Seam mesh(sm, sem, svm);
  const std::vector<SM_vertex> path = edge_path(sm, *vertices(sm).begin(), 5);
  ASSERT_EQ(path.size(), 6u);
  for(std::size_t k = 0; k + 1 < path.size(); ++k) ASSERT_TRUE(mesh.add_seam(path[k], path[k + 1]));
  typedef boost::graph_traits<Seam>::halfedge_descriptor seam_halfedge;
  seam_halfedge bhd;
  bool found = false;
  for(seam_halfedge h : halfedges(mesh)) if(is_border(h, mesh)) { bhd = h; found = true; break; }
  ASSERT_TRUE(found);
  // The cut: the 4 inner path vertices are doubled, one border loop of 10 edges.
  EXPECT_EQ(num_vertices(mesh), num_vertices(sm) + 4);
  std::size_t loop = 0;
  for(seam_halfedge h : halfedges_around_face(bhd, mesh)) { (void)h; ++loop; }
  EXPECT_EQ(loop, 10u);

  typedef SM::Property_map<SM_halfedge, Point_2> UV_pmap; // uv on the halfedges, as in CGAL's examples
  typedef SMP::Discrete_lie_flow_parameterizer_3<Seam> Seam_dlf;
  UV_pmap uv = sm.add_property_map<SM_halfedge, Point_2>("h:uv").first;
  EXPECT_EQ(SMP::parameterize(mesh, Seam_dlf(), bhd, uv), SMP::OK);
  const Indexed m1 = extract(mesh, uv);
  expect_good_map(m1, certified_d_area_bound);
  for(SM_halfedge h : halfedges(sm)) uv[h] = Point_2(0, 0);
  Seam_dlf p;
  EXPECT_EQ(SMP::parameterize(mesh, p, bhd, uv), SMP::OK) << p.report().message;
  const Indexed m = extract(mesh, uv);
  expect_good_map(m, certified_d_area_bound);
  EXPECT_EQ(p.report().status, SMP::OK);
  EXPECT_EQ(p.report().stop_reason, SMP::Discrete_lie_flow_stop_reason::CONVERGED);
  EXPECT_GT(p.report().iterations, 0u);
  EXPECT_NEAR(p.report().final_d_area, d_area(m), 1e-9);
  // The two sides of the seam are apart in the domain.
  std::set<std::pair<double, double> > distinct;
  for(const V2& q : m.uv) distinct.insert(std::make_pair(q[0], q[1]));
  EXPECT_EQ(distinct.size(), m.uv.size());
}

// ---------------------------------------------------------------------------
// Error codes
// ---------------------------------------------------------------------------

TEST(Errors, EveryCodeHasAMessageAndAName)
{
  std::set<std::string> messages, names;
  const int codes[] = { SMP::OK, SMP::ERROR_EMPTY_MESH, SMP::ERROR_NON_TRIANGULAR_MESH, SMP::ERROR_NO_TOPOLOGICAL_DISC,
                        SMP::ERROR_NO_TOPOLOGICAL_BALL, SMP::ERROR_BORDER_TOO_SHORT, SMP::ERROR_NON_CONVEX_BORDER,
                        SMP::ERROR_CANNOT_SOLVE_LINEAR_SYSTEM, SMP::ERROR_NO_1_TO_1_MAPPING, SMP::ERROR_WRONG_PARAMETER,
                        SMP::ERROR_INITIAL_MAP_FOLDED, SMP::ERROR_DEGENERATE_INPUT, SMP::ERROR_INVALID_DENSITY,
                        SMP::ERROR_FLOW_STALLED, SMP::ERROR_NOT_GENUS_0 };
  for(int c : codes) {
    messages.insert(SMP::discrete_lie_flow_error_message(c));
    names.insert(SMP::discrete_lie_flow_error_name(c));
    EXPECT_STRNE(SMP::discrete_lie_flow_error_message(c), "Unknown error") << c;
  }
  EXPECT_EQ(messages.size(), sizeof(codes) / sizeof(int));
  EXPECT_EQ(names.size(), sizeof(codes) / sizeof(int));
  EXPECT_STREQ(SMP::discrete_lie_flow_error_name(SMP::ERROR_INITIAL_MAP_FOLDED), "ERROR_INITIAL_MAP_FOLDED");
}

TEST(Errors, EmptyMesh)
{
  SM sm;
  SM_call call(sm);
  SM_dlf p;
  EXPECT_EQ(call.run(p, boost::graph_traits<SM>::null_halfedge()), SMP::ERROR_EMPTY_MESH);
  EXPECT_EQ(p.report().status, SMP::ERROR_EMPTY_MESH);
  EXPECT_FALSE(p.report().message.empty());
}

// A quad among triangles; the quad is not the first face the flow meets.
// The message names the quad by its vertices.
TEST(Errors, NonTriangularMesh)
{
  SM sm = grid(3);
  // Replace the two triangles of the cell (1, 1) by one quad.
  const int m = 3;
  auto vid = [&](int i, int j) { return SM_vertex(SM::size_type(j * (m + 1) + i)); };
  std::vector<SM_face> cell;
  for(SM_face f : faces(sm)) {
    std::set<SM_vertex> vs;
    for(SM_vertex v : vertices_around_face(halfedge(f, sm), sm)) vs.insert(v);
    if(vs.count(vid(1, 1)) && vs.count(vid(2, 2))) cell.push_back(f);
  }
  ASSERT_EQ(cell.size(), 2u);
  for(SM_face f : cell) CGAL::Euler::remove_face(halfedge(f, sm), sm);
  const SM_face quad = sm.add_face(vid(1, 1), vid(2, 1), vid(2, 2), vid(1, 2));
  ASSERT_NE(quad, SM::null_face());
  sm.collect_garbage();
  SM_face q;
  for(SM_face f : faces(sm)) if(degree(f, sm) == 4) q = f;
  SM_call call(sm);
  SM_dlf p;
  // Start next to a triangle far from the quad.
  SM_halfedge bhd = border_halfedge(sm);
  EXPECT_EQ(call.run(p, bhd), SMP::ERROR_NON_TRIANGULAR_MESH);
  EXPECT_EQ(p.report().status, SMP::ERROR_NON_TRIANGULAR_MESH);
  std::vector<long> qv;
  for(SM_vertex v : vertices_around_face(halfedge(q, sm), sm)) qv.push_back(long(v.idx()));
  EXPECT_TRUE(names_face(p.report().message, long(q.idx()), qv));
}

TEST(Errors, NotADisk)
{
  {
    // A closed mesh, given a halfedge that is not on a border.
    SM sm;
    ASSERT_TRUE(read_sm("sphere", sm));
    SM_call call(sm);
    SM_dlf p;
    EXPECT_EQ(call.run(p, *halfedges(sm).begin()), SMP::ERROR_NO_TOPOLOGICAL_DISC);
    EXPECT_NE(p.report().message.find("border"), std::string::npos) << p.report().message;
  }
  {
    // A torus with one face removed: one border loop, genus 1.
    SM sm = torus_with_a_hole(8, 6);
    SM_call call(sm);
    SM_dlf p;
    EXPECT_EQ(call.run(p, border_halfedge(sm)), SMP::ERROR_NO_TOPOLOGICAL_DISC);
    const std::string& msg = p.report().message;
    EXPECT_NE(msg.find("genus 1"), std::string::npos) << msg;
    EXPECT_NE(msg.find("1 border loop"), std::string::npos) << msg;
    EXPECT_NE(msg.find("genus 0"), std::string::npos) << "the message should say what is taken: " << msg;
  }
  {
    // Two copies of that torus: the message says the halfedge's component is one of several.
    SM sm = torus_with_a_hole(8, 6);
    const SM other = torus_with_a_hole(5, 4);
    CGAL::copy_face_graph(other, sm);
    SM_call call(sm);
    SM_dlf p;
    EXPECT_EQ(call.run(p, border_halfedge(sm)), SMP::ERROR_NO_TOPOLOGICAL_DISC);
    EXPECT_NE(p.report().message.find("connected components"), std::string::npos) << p.report().message;
  }
}

// ---------------------------------------------------------------------------
// Meshes with holes: genus 0, several border loops
// ---------------------------------------------------------------------------

/// The border loops of a Surface_mesh, each as its border halfedges.
std::vector<std::vector<SM_halfedge> > border_loops(const SM& sm)
{
  std::vector<std::vector<SM_halfedge> > loops;
  std::set<SM_halfedge> seen;
  for(SM_halfedge h : halfedges(sm))
    if(is_border(h, sm) && !seen.count(h)) {
      loops.emplace_back();
      for(SM_halfedge b : halfedges_around_face(h, sm)) { loops.back().push_back(b); seen.insert(b); }
    }
  return loops;
}

double loop_length(const SM& sm, const std::vector<SM_halfedge>& loop)
{
  double l = 0;
  for(SM_halfedge h : loop) l += std::sqrt(CGAL::squared_distance(sm.point(source(h, sm)), sm.point(target(h, sm))));
  return l;
}

/// Twice the signed area enclosed by a loop of the uv map.
double twice_loop_area(const SM& sm, const SM::Property_map<SM_vertex, Point_2>& uv, const std::vector<SM_halfedge>& loop)
{
  double a = 0;
  for(SM_halfedge h : loop) {
    const Point_2 &p = uv[source(h, sm)], &q = uv[target(h, sm)];
    a += p.x() * q.y() - p.y() * q.x();
  }
  return a;
}

/// Whether a map of a genus-0 mesh with holes is injective, given that its
/// faces are all positive (exact): it is iff its border loops are simple and
/// pairwise disjoint and every hole is wound against the outer loop; the
/// faces then cover the outer polygon once minus the holes, and their areas
/// add up so.
::testing::AssertionResult injective(const SM& sm, const SM::Property_map<SM_vertex, Point_2>& uv, SM_halfedge bhd)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel::Segment_2 ES;
  const std::vector<std::vector<SM_halfedge> > loops = border_loops(sm);
  std::vector<std::pair<ES, std::pair<SM_vertex, SM_vertex> > > segments;
  for(const auto& loop : loops)
    for(SM_halfedge h : loop) {
      const Point_2 &p = uv[source(h, sm)], &q = uv[target(h, sm)];
      segments.push_back({ ES(EP(p.x(), p.y()), EP(q.x(), q.y())), { source(h, sm), target(h, sm) } });
    }
  std::size_t crossings = 0;
  for(std::size_t i = 0; i < segments.size(); ++i)
    for(std::size_t j = i + 1; j < segments.size(); ++j) {
      const auto &a = segments[i].second, &b = segments[j].second;
      if(a.first == b.first || a.first == b.second || a.second == b.first || a.second == b.second) continue;
      if(CGAL::do_intersect(segments[i].first, segments[j].first)) ++crossings;
    }
  if(crossings != 0) return ::testing::AssertionFailure() << crossings << " pairs of border edges of the map cross";
  double faces_area = 0;
  for(SM_face f : faces(sm)) {
    std::vector<Point_2> c;
    for(SM_vertex v : vertices_around_face(halfedge(f, sm), sm)) c.push_back(uv[v]);
    faces_area += std::abs(CGAL::area(c[0], c[1], c[2]));
  }
  double outer = 0, holes = 0;
  for(const auto& loop : loops) {
    const double a = 0.5 * std::abs(twice_loop_area(sm, uv, loop));
    (std::find(loop.begin(), loop.end(), bhd) != loop.end() ? outer : holes) += a;
  }
  if(!(std::abs(faces_area - (outer - holes)) <= 1e-9 * outer))
    return ::testing::AssertionFailure() << "the faces cover " << faces_area << ", the domain minus the holes is "
                                         << outer - holes << ": some place is covered twice";
  return ::testing::AssertionSuccess();
}

/// The halfedge of the longest border loop (3D length): `dlf disk`'s default outer loop.
SM_halfedge longest_loop(const SM& sm)
{
  const std::vector<std::vector<SM_halfedge> > loops = border_loops(sm);
  std::size_t best = 0;
  for(std::size_t k = 1; k < loops.size(); ++k)
    if(loop_length(sm, loops[k]) > loop_length(sm, loops[best])) best = k;
  return loops[best].front();
}

/// What a run on a mesh with holes must give: converged, D_area ≤ 2.01 by
/// the package's distortion function on the output map, every caller face
/// positive by the exact predicate, injective, the report about the caller's
/// vertices and faces.
/// With `converge` false (an iteration cap in `opt`), the run need only
/// improve its start.
void expect_holes_run(SM& sm, SM_halfedge bhd, std::size_t max_iterations, const std::string& name,
                      bool converge = true, const SMP::Discrete_lie_flow_options& opt = SMP::Discrete_lie_flow_options())
{
  SCOPED_TRACE(name);
  const std::size_t loops = border_loops(sm).size();
  SM_call call(sm);
  SM_dlf p(SM_dlf::Initial_parameterizer(), opt);
  ASSERT_EQ(call.run(p, bhd), SMP::OK) << p.report().message;
  const SMP::Discrete_lie_flow_report& R = p.report();
  if(converge) {
    EXPECT_EQ(R.stop_reason, SMP::Discrete_lie_flow_stop_reason::CONVERGED);
    EXPECT_LE(R.iterations, max_iterations);
  } else {
    EXPECT_LT(R.final_d_area, R.initial_d_area);
  }
  EXPECT_EQ(R.holes, loops - 1);
  EXPECT_NE(R.message.find("Tutte"), std::string::npos) << "the message should say the start is the library's: " << R.message;
  // On the circle the outer loop is convex: Tutte's embedding of the filled
  // disk inside it is bijective, no fallback.
  if(R.border == SMP::Discrete_lie_flow_border::CIRCLE)
    EXPECT_NE(R.message.find("initial map: Tutte's embedding of the filled disk inside the initial parameterizer's outer loop"),
              std::string::npos) << R.message;
  const SMP::Discrete_lie_flow_distortion d = SMP::discrete_lie_flow_distortion(sm, call.uv);
  if(converge) EXPECT_LE(d.d_area, certified_d_area_bound);
  EXPECT_EQ(d.inverted_faces + d.degenerate_faces, 0u);
  const Indexed m = extract(sm, call.uv);
  const Signs s = exact_signs(m.uv, m.faces);
  EXPECT_EQ(s.zero, 0u);
  EXPECT_EQ((std::min)(s.pos, s.neg), 0u);
  EXPECT_TRUE(injective(sm, call.uv, bhd));
  // The report speaks of the caller's mesh only.
  EXPECT_EQ(R.vertices, num_vertices(sm));
  EXPECT_EQ(R.faces, num_faces(sm));
  EXPECT_EQ(R.domain_faces.size(), num_faces(sm));
  EXPECT_EQ(R.target_area.size(), num_vertices(sm));
  EXPECT_EQ(R.domain_area.size(), num_vertices(sm));
  EXPECT_EQ(R.face_density.size(), num_faces(sm));
  EXPECT_EQ(R.caller_inverted_faces, 0u);
  EXPECT_EQ(R.flowing_inverted_faces, 0u);
  EXPECT_NEAR(R.final_d_area, d_area(m), 1e-9);
  EXPECT_NEAR(R.final_metrics.d_area, d.d_area, 1e-9);
  for(const auto& t : p.domain_triangles()) for(SM_vertex v : t) EXPECT_TRUE(sm.is_valid(v));
  if(opt.disk.coarse_to_fine_faces > 0 && num_faces(sm) >= opt.disk.coarse_to_fine_faces)
    EXPECT_GE(R.levels.size(), 2u) << "no coarse levels: " << R.levels_refused;
}

TEST(Holes, AnnulusGrid)
{
  // A 9×9 grid without its middle 3×3 cells: two border loops, genus 0.
  SM sm = grid(9);
  std::vector<SM_face> middle;
  for(SM_face f : faces(sm)) {
    bool inside = true;
    for(SM_vertex v : vertices_around_face(halfedge(f, sm), sm)) {
      const Point_3& p = sm.point(v);
      inside = inside && p.x() > 0.3 && p.x() < 0.7 && p.y() > 0.3 && p.y() < 0.7;
    }
    if(inside) middle.push_back(f);
  }
  ASSERT_EQ(middle.size(), 18u);
  for(SM_face f : middle) CGAL::Euler::remove_face(halfedge(f, sm), sm);
  sm.collect_garbage();
  ASSERT_EQ(border_loops(sm).size(), 2u);
  ASSERT_EQ(long(num_vertices(sm)) - long(num_edges(sm)) + long(num_faces(sm)), 0) << "an annulus";
  expect_holes_run(sm, longest_loop(sm), 200, "annulus");
  // The hole keeps about its share of the area (1/9 of the square).
  SM_call call(sm);
  SM_dlf p;
  const SM_halfedge bhd = longest_loop(sm);
  ASSERT_EQ(call.run(p, bhd), SMP::OK);
  double outer = 0, hole = 0;
  for(const auto& loop : border_loops(sm))
    (std::find(loop.begin(), loop.end(), bhd) == loop.end() ? hole : outer) = std::abs(twice_loop_area(sm, call.uv, loop));
  EXPECT_GT(hole / outer, 0.07);
  EXPECT_LT(hole / outer, 0.16);
  // The check bites: the hole's rim blown up 3 times about its centre
  // overlaps the faces around it.
  EXPECT_TRUE(injective(sm, call.uv, bhd));
  for(const auto& loop : border_loops(sm))
    if(std::find(loop.begin(), loop.end(), bhd) == loop.end()) {
      double cx = 0, cy = 0;
      for(SM_halfedge h : loop) { cx += call.uv[target(h, sm)].x() / loop.size(); cy += call.uv[target(h, sm)].y() / loop.size(); }
      for(SM_halfedge h : loop) {
        const Point_2 q = call.uv[target(h, sm)];
        call.uv[target(h, sm)] = Point_2(cx + 3 * (q.x() - cx), cy + 3 * (q.y() - cy));
      }
    }
  EXPECT_FALSE(injective(sm, call.uv, bhd));
}

TEST(Holes, CgalMeshesWithHoles)
{
  // The genus-0 meshes of CGAL's data set with several border loops.
  for(const char* name : { "pig", "head", "holes", "mech-holes-shark", "lion", "blade" }) {
    SM sm;
    ASSERT_TRUE(read_sm(name, sm)) << name;
    ASSERT_GT(border_loops(sm).size(), 1u) << name;
    expect_holes_run(sm, longest_loop(sm), 200, name);
  }
}

// The holes' fill flows through the coarse levels with the caller's faces.
TEST(Holes, CoarseToFine)
{
  SMP::Discrete_lie_flow_options opt;
  opt.disk.coarse_to_fine_faces = 1000;
  for(const char* name : { "lion", "holes", "blade" }) {
    SM sm;
    ASSERT_TRUE(read_sm(name, sm)) << name;
    expect_holes_run(sm, longest_loop(sm), 200, std::string(name) + ", coarse to fine", true, opt);
  }
}

TEST(Holes, AnyLoopMayBeOuter)
{
  SM sm;
  ASSERT_TRUE(read_sm("head", sm));
  const std::vector<std::vector<SM_halfedge> > loops = border_loops(sm);
  ASSERT_EQ(loops.size(), 3u);
  // The neck is the longest loop; with an eye as the border the whole head
  // passes through 10 border edges, and the flow's tail is slow (measured:
  // D_area 2.17 at the 500-iteration cap): an injective map that improves
  // its start is what is promised there.
  SMP::Discrete_lie_flow_options capped;
  capped.max_iterations = 60;
  for(const auto& loop : loops) {
    const bool neck = loop.size() > 30;
    expect_holes_run(sm, loop.front(), 200, "head, outer loop of " + std::to_string(loop.size()), neck,
                     neck ? SMP::Discrete_lie_flow_options() : capped);
  }
}

TEST(Holes, PaperModeRefusesThem)
{
  SM sm;
  ASSERT_TRUE(read_sm("pig", sm));
  SM_call call(sm);
  SM_dlf p;
  p.options().mode = SMP::Discrete_lie_flow_mode::PAPER;
  EXPECT_EQ(call.run(p, longest_loop(sm)), SMP::ERROR_NO_TOPOLOGICAL_DISC);
  EXPECT_NE(p.report().message.find("holes"), std::string::npos) << p.report().message;
}

TEST(Errors, WrongVertexIndexMap)
{
  SM sm = grid(4);
  SM_call call(sm);
  for(SM_vertex v : vertices(sm)) call.vim[v] = 0; // not a numbering
  SM_dlf p;
  EXPECT_EQ(call.run(p, border_halfedge(sm)), SMP::ERROR_WRONG_PARAMETER);
  EXPECT_NE(p.report().message.find("index map"), std::string::npos) << p.report().message;
}

TEST(Errors, DegenerateInputZeroAreaFace)
{
  SM sm = grid(4); // vertex (i, j) = j·5 + i
  // Face (1,1), (2,1), (2,2): move (2,2) onto the line y = 1/4 through the others.
  const SM_vertex a(6), b(7), c(12);
  sm.point(c) = Point_3(0.625, 0.25, 0);
  SM_face bad = SM::null_face();
  for(SM_face f : faces(sm)) {
    std::set<SM_vertex> vs;
    for(SM_vertex v : vertices_around_face(halfedge(f, sm), sm)) vs.insert(v);
    if(vs == std::set<SM_vertex>{ a, b, c }) bad = f;
  }
  ASSERT_NE(bad, SM::null_face());
  SM_call call(sm);
  SM_dlf p;
  EXPECT_EQ(call.run(p, border_halfedge(sm)), SMP::ERROR_DEGENERATE_INPUT);
  EXPECT_EQ(p.report().status, SMP::ERROR_DEGENERATE_INPUT);
  EXPECT_TRUE(names_face(p.report().message, long(bad.idx()), { 6, 7, 12 }));
}

TEST(Errors, DegenerateInputNonFiniteCoordinate)
{
  for(double bad : { std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity() }) {
    SM sm = grid(4);
    sm.point(SM_vertex(13)) = Point_3(0.5, bad, 0);
    SM_call call(sm);
    SM_dlf p;
    EXPECT_EQ(call.run(p, border_halfedge(sm)), SMP::ERROR_DEGENERATE_INPUT);
    EXPECT_TRUE(numbers_in(p.report().message).count(13)) << "the message should name vertex 13: " << p.report().message;
    EXPECT_NE(p.report().message.find("vertex"), std::string::npos) << p.report().message;
    for(SM_vertex v : vertices(sm)) ASSERT_TRUE(std::isfinite(call.uv[v].x()) && std::isfinite(call.uv[v].y()));
  }
}

// The density messages name the face by its vertices, as the zero-area one does.
TEST(Errors, InvalidDensity)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for(double rho : { 0., -1., nan, std::numeric_limits<double>::infinity() }) {
    SM sm = grid(4);
    auto dens = sm.add_property_map<SM_face, double>("f:density", 1.).first;
    const SM_face bad(SM::size_type(13));
    dens[bad] = rho;
    SM_call call(sm);
    SM_dlf p;
    p.set_face_density(dens);
    EXPECT_EQ(call.run(p, border_halfedge(sm)), SMP::ERROR_INVALID_DENSITY) << "density " << rho;
    std::vector<long> bv;
    for(SM_vertex v : vertices_around_face(halfedge(bad, sm), sm)) bv.push_back(long(v.idx()));
    EXPECT_TRUE(names_face(p.report().message, 13, bv)) << "density " << rho;
  }
  {
    // Per vertex: a NaN density at one vertex.
    SM sm = grid(4);
    auto dens = sm.add_property_map<SM_vertex, double>("v:density", 1.).first;
    dens[SM_vertex(12)] = nan;
    SM_call call(sm);
    SM_dlf p;
    p.set_vertex_density(dens);
    EXPECT_EQ(call.run(p, border_halfedge(sm)), SMP::ERROR_INVALID_DENSITY);
  }
  {
    // Options: the wrong number of values.
    SM sm = grid(4);
    SM_call call(sm);
    SMP::Discrete_lie_flow_options o;
    o.face_density.assign(num_faces(sm) - 1, 1.);
    SM_dlf p(SM_dlf::Initial_parameterizer(), o);
    EXPECT_EQ(call.run(p, border_halfedge(sm)), SMP::ERROR_INVALID_DENSITY);
    const std::set<long> nums = numbers_in(p.report().message);
    EXPECT_TRUE(nums.count(long(num_faces(sm))) && nums.count(long(num_faces(sm)) - 1)) << p.report().message;
  }
  {
    // Options: right size, a zero.
    SM sm = grid(4);
    SM_call call(sm);
    SMP::Discrete_lie_flow_options o;
    o.face_density.assign(num_faces(sm), 0.);
    SM_dlf p(SM_dlf::Initial_parameterizer(), o);
    EXPECT_EQ(call.run(p, border_halfedge(sm)), SMP::ERROR_INVALID_DENSITY);
  }
}

/// An initial parameterizer that writes a folded map: Tutte, then one
/// interior vertex pushed outside its ring.
struct Folding_initial
{
  SM_vertex victim;
  template <class UV, class VI, class VP>
  SMP::Error_code parameterize(SM& sm, SM_halfedge bhd, UV uv, VI vi, VP vp)
  {
    SM_dlf::Initial_parameterizer tutte;
    const SMP::Error_code c = tutte.parameterize(sm, bhd, uv, vi, vp);
    put(uv, victim, Point_2(2, 2));
    return c;
  }
};

TEST(Errors, InitialMapFolded_ThroughParameterize)
{
  SM sm = grid(4);
  SM_call call(sm);
  typedef SMP::Discrete_lie_flow_parameterizer_3<SM, Folding_initial> P;
  Folding_initial init;
  init.victim = SM_vertex(12);
  P p(init);
  EXPECT_EQ(call.run(p, border_halfedge(sm)), SMP::ERROR_INITIAL_MAP_FOLDED);
  // The named face is one of the caller's faces, folded in the initial map.
  const std::string& msg = p.report().message;
  const std::regex vre("vertices ([0-9]+), ([0-9]+), ([0-9]+)");
  std::smatch mm;
  ASSERT_TRUE(std::regex_search(msg, mm, vre)) << msg;
  const std::set<SM_vertex> named = { SM_vertex(SM::size_type(std::stol(mm[1].str()))), SM_vertex(SM::size_type(std::stol(mm[2].str()))),
                                       SM_vertex(SM::size_type(std::stol(mm[3].str()))) };
  bool is_face = false, folded = false;
  const Indexed m = extract(sm, call.uv);
  const Signs s = exact_signs(m.uv, m.faces);
  const CGAL::Orientation majority = s.pos >= s.neg ? CGAL::POSITIVE : CGAL::NEGATIVE;
  for(SM_face f : faces(sm)) {
    std::set<SM_vertex> vs;
    std::vector<EP> q;
    for(SM_vertex v : vertices_around_face(halfedge(f, sm), sm)) { vs.insert(v); q.push_back(EP(call.uv[v].x(), call.uv[v].y())); }
    if(vs != named) continue;
    is_face = true;
    folded = CGAL::orientation(q[0], q[1], q[2]) != majority;
  }
  EXPECT_TRUE(is_face) << msg;
  EXPECT_TRUE(folded) << msg;
  EXPECT_TRUE(named.count(SM_vertex(12))) << msg;
}

/// A disk problem in index form: the m×m grid, its uv the grid itself.
void grid_problem(int m, D::Disk_problem& P, std::vector<D::Vec2>& uv)
{
  auto id = [m](int i, int j) { return j * (m + 1) + i; };
  for(int j = 0; j <= m; ++j)
    for(int i = 0; i <= m; ++i) {
      P.xyz.push_back({{ double(i), double(j), 0.1 * ((i * 7 + j * 3) % 5) }});
      uv.push_back({{ double(i), double(j) }});
    }
  for(int j = 0; j < m; ++j)
    for(int i = 0; i < m; ++i) {
      P.faces.push_back({{ id(i, j), id(i + 1, j), id(i + 1, j + 1) }});
      P.faces.push_back({{ id(i, j), id(i + 1, j + 1), id(i, j + 1) }});
    }
  for(const D::Face& f : P.faces) P.target.push_back(D::triangle_area_3(P.xyz[f[0]], P.xyz[f[1]], P.xyz[f[2]]));
  for(int i = 0; i < m; ++i) P.boundary.push_back(id(i, 0));
  for(int j = 0; j < m; ++j) P.boundary.push_back(id(m, j));
  for(int i = m; i > 0; --i) P.boundary.push_back(id(i, m));
  for(int j = m; j > 0; --j) P.boundary.push_back(id(0, j));
}

TEST(Errors, InitialMapFolded_RunFlow)
{
  for(const bool degenerate : { false, true }) {
    D::Disk_problem P;
    std::vector<D::Vec2> uv;
    grid_problem(5, P, uv);
    // Vertex (2, 2) = 14: across its neighbour (3, 3), or onto the line through (2, 1) and (3, 2).
    const int v = 14;
    uv[v] = degenerate ? D::Vec2{{ 2.5, 1.5 }} : D::Vec2{{ 3.5, 3.5 }};
    const std::vector<D::Vec2> before = uv;
    const D::Orientation_count oc = D::count_orientations_2(uv, P.faces);
    ASSERT_FALSE(oc.all_positive());
    const SMP::Discrete_lie_flow_options options;
    D::Default_spd_solver solver;
    SMP::Discrete_lie_flow_report report;
    EXPECT_EQ(D::flow_disk(P, uv, options, solver, report), SMP::ERROR_INITIAL_MAP_FOLDED);
    EXPECT_EQ(report.status, SMP::ERROR_INITIAL_MAP_FOLDED);
    EXPECT_TRUE(uv == before) << "the map was changed on error";
    // The message names the first bad face by index and vertices; check it is bad.
    const std::regex re("face ([0-9]+) \\(vertices ([0-9]+), ([0-9]+), ([0-9]+)\\)");
    std::smatch mm;
    const std::string msg = report.message;
    ASSERT_TRUE(std::regex_search(msg, mm, re)) << msg;
    const std::size_t f = std::stoul(mm[1].str());
    ASSERT_LT(f, P.faces.size());
    const D::Face& t = P.faces[f];
    EXPECT_EQ(t[0], std::stoi(mm[2].str()));
    EXPECT_EQ(t[1], std::stoi(mm[3].str()));
    EXPECT_EQ(t[2], std::stoi(mm[4].str()));
    const CGAL::Orientation o = CGAL::orientation(EP(uv[t[0]][0], uv[t[0]][1]), EP(uv[t[1]][0], uv[t[1]][1]), EP(uv[t[2]][0], uv[t[2]][1]));
    EXPECT_NE(o, CGAL::POSITIVE) << msg;
    EXPECT_NE(msg.find(degenerate ? "1 degenerate" : "0 degenerate"), std::string::npos) << msg;
  }
}

// A mirrored initial map (all faces negative) is accepted and stays mirrored:
// every face keeps the initial map's orientation.
TEST(Run_flow, MirroredInitialMapIsAccepted)
{
  D::Disk_problem P;
  std::vector<D::Vec2> uv;
  grid_problem(6, P, uv);
  for(D::Vec2& q : uv) q[0] = -q[0]; // every face negative
  ASSERT_EQ(D::count_orientations_2(uv, P.faces).inverted, P.faces.size());
  const std::vector<D::Face> caller = P.faces;
  const SMP::Discrete_lie_flow_options options;
  D::Default_spd_solver solver;
  SMP::Discrete_lie_flow_report report;
  ASSERT_EQ(D::flow_disk(P, uv, options, solver, report), SMP::OK) << report.message;
  const Signs s = exact_signs(uv, std::vector<Tri>(caller.begin(), caller.end()));
  EXPECT_EQ(s.pos, 0u);
  EXPECT_EQ(s.zero, 0u);
  EXPECT_EQ(s.neg, caller.size());
  EXPECT_EQ(report.caller_inverted_faces, 0u);
  EXPECT_LE(report.final_d_area, report.initial_d_area);
}

TEST(Errors, FlowStalled)
{
  SM sm;
  ASSERT_TRUE(read_sm("nefertiti", sm));
  const SM_halfedge bhd = border_halfedge(sm);
  // The initial map alone, for comparison.
  auto uv0 = sm.add_property_map<SM_vertex, Point_2>("v:uv0").first;
  ASSERT_EQ(SMP::parameterize(sm, SM_dlf::Initial_parameterizer(), bhd, uv0), SMP::OK);
  // Paper mode with a fixed step that folds at once: the paper's "collapse".
  SMP::Discrete_lie_flow_options o;
  o.mode = SMP::Discrete_lie_flow_mode::PAPER;
  o.fixed_step = 10;
  SM_call call(sm);
  SM_dlf p(SM_dlf::Initial_parameterizer(), o);
  EXPECT_EQ(call.run(p, bhd), SMP::ERROR_FLOW_STALLED);
  EXPECT_EQ(p.report().status, SMP::ERROR_FLOW_STALLED);
  EXPECT_EQ(p.report().stop_reason, SMP::Discrete_lie_flow_stop_reason::STALLED);
  EXPECT_EQ(p.report().iterations, 0u);
  EXPECT_FALSE(p.report().message.empty());
  // The map holds the (valid) initial map.
  for(SM_vertex v : vertices(sm)) { EXPECT_EQ(call.uv[v], uv0[v]); }
  // Certified mode, a fixed step too long and no backtracking allowed.
  SMP::Discrete_lie_flow_options c;
  c.fixed_step = 1e6;
  c.max_backtracks = 0;
  SM_dlf q(SM_dlf::Initial_parameterizer(), c);
  EXPECT_EQ(call.run(q, bhd), SMP::ERROR_FLOW_STALLED);
  EXPECT_EQ(q.report().iterations, 0u);
  // There the start is the flow's own Tutte map: the report's, bit for bit,
  // and the initial parameterizer's to rounding.
  ASSERT_EQ(q.report().initial_uv.size(), num_vertices(sm));
  for(SM_vertex v : vertices(sm)) {
    EXPECT_EQ(call.uv[v], Point_2(q.report().initial_uv[v.idx()][0], q.report().initial_uv[v.idx()][1]));
    EXPECT_LT(CGAL::squared_distance(call.uv[v], uv0[v]), 1e-24);
  }
}

// ---------------------------------------------------------------------------
// Options that end a run
// ---------------------------------------------------------------------------

TEST(Options, IterationCapAndCallback)
{
  SM sm;
  ASSERT_TRUE(read_sm("mushroom", sm));
  const SM_halfedge bhd = border_halfedge(sm);
  for(const auto mode : { SMP::Discrete_lie_flow_mode::CERTIFIED, SMP::Discrete_lie_flow_mode::PAPER }) {
    SMP::Discrete_lie_flow_options o;
    o.mode = mode;
    o.max_iterations = 2;
    o.record_history = true;
    SM_call call(sm);
    SM_dlf p(SM_dlf::Initial_parameterizer(), o);
    ASSERT_EQ(call.run(p, bhd), SMP::OK) << p.report().message;
    EXPECT_EQ(p.report().stop_reason, SMP::Discrete_lie_flow_stop_reason::ITERATION_CAP);
    EXPECT_EQ(p.report().iterations, 2u);
    EXPECT_EQ(p.report().history.size(), 2u);
    EXPECT_LT(p.report().final_d_area, p.report().initial_d_area);
    if(mode == SMP::Discrete_lie_flow_mode::CERTIFIED) {
      Indexed m = extract(sm, call.uv);
      expect_good_map(m, p.report().initial_d_area);
      EXPECT_NEAR(d_area(m), p.report().final_d_area, 1e-9 * p.report().final_d_area);
    }

    std::vector<SMP::Discrete_lie_flow_iteration> seen;
    o.max_iterations = 500;
    // A fresh start: CGAL's fixed-border parameterizers keep the vertices
    // marked as parameterized, and the paper mode's map after 2 iterations
    // may fold the caller's triangles.
    for(SM_vertex v : vertices(sm)) call.vpm[v] = false;
    o.callback = [&seen](const SMP::Discrete_lie_flow_iteration& it) { seen.push_back(it); return it.iteration < 3; };
    SM_dlf q(SM_dlf::Initial_parameterizer(), o);
    ASSERT_EQ(call.run(q, bhd), SMP::OK) << q.report().message;
    EXPECT_EQ(q.report().stop_reason, SMP::Discrete_lie_flow_stop_reason::INTERRUPTED);
    EXPECT_EQ(q.report().iterations, 3u);
    ASSERT_EQ(seen.size(), 3u);
    ASSERT_EQ(q.report().history.size(), 3u);
    for(std::size_t k = 0; k < 3; ++k) {
      EXPECT_EQ(seen[k].iteration, k + 1);
      EXPECT_EQ(seen[k].d_area, q.report().history[k].d_area);
      EXPECT_GT(seen[k].step, 0);
    }
  }
}

} // namespace

} // namespace dlf_test_inputs
