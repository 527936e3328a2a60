// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Discrete_lie_flow_parameterizer_3 in place of CGAL's parameterizers: the
// second template argument as CGAL means it (a border parameterizer), CGAL's
// constructors and calls, CGAL's error codes at every entry point, and a
// caller's start kept on meshes with holes (CGAL's lscm example data).

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Seam_mesh.h>
#include <CGAL/Polygon_mesh_processing/measure.h>

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_distortion.h>
#include <CGAL/Surface_mesh_parameterization/Given_uv_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Circular_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Square_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Two_vertices_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/LSCM_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_conformal_map_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Error_code.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

// The tests compile in unity batches (DLF_UNITY_BUILD): each file keeps its
// names in a namespace of its own.
namespace dlf_test_drop_in {

namespace {

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace D = SMP::internal::dlf;
typedef CGAL::Simple_cartesian<double> K;
typedef K::Point_2 Point_2;
typedef CGAL::Surface_mesh<K::Point_3> SM;
typedef boost::graph_traits<SM>::vertex_descriptor SM_vertex;
typedef boost::graph_traits<SM>::halfedge_descriptor SM_halfedge;
typedef boost::graph_traits<SM>::edge_descriptor SM_edge;
typedef SM::Property_map<SM_vertex, Point_2> UV_map;

typedef SMP::Circular_border_arc_length_parameterizer_3<SM> Circle;
typedef SMP::Square_border_uniform_parameterizer_3<SM> Square;
typedef SMP::Two_vertices_parameterizer_3<SM> Two_vertices;

// The second template argument, as CGAL means it.
static_assert(D::Is_border_parameterizer<Circle>::value, "a border parameterizer");
static_assert(D::Is_border_parameterizer<Square>::value, "a border parameterizer");
static_assert(D::Is_border_parameterizer<Two_vertices>::value, "a border parameterizer");
static_assert(!D::Is_border_parameterizer<SMP::Symmetric_barycentric_mapping_parameterizer_3<SM> >::value, "not a border");
static_assert(!D::Is_border_parameterizer<SMP::LSCM_parameterizer_3<SM> >::value, "not a border");
static_assert(D::Is_parameterizer_3<SMP::LSCM_parameterizer_3<SM>, SM>::value, "a Parameterizer_3");
static_assert(!D::Is_parameterizer_3<int, SM>::value, "an int is no parameterizer");
static_assert(std::is_same<SMP::Discrete_lie_flow_parameterizer_3<SM, Square>::Initial_parameterizer,
                           SMP::Symmetric_barycentric_mapping_parameterizer_3<SM, Square> >::value, "Tutte in the square");
static_assert(std::is_same<SMP::Discrete_lie_flow_parameterizer_3<SM, Two_vertices>::Initial_parameterizer,
                           SMP::LSCM_parameterizer_3<SM, Two_vertices> >::value, "LSCM, free border");
static_assert(std::is_same<SMP::Discrete_lie_flow_parameterizer_3<SM, SMP::LSCM_parameterizer_3<SM> >::Initial_parameterizer,
                           SMP::LSCM_parameterizer_3<SM> >::value, "an initial parameterizer is kept");
// CGAL's idiom: a parameterizer built from its border parameterizer.
static_assert(std::is_constructible<SMP::Discrete_lie_flow_parameterizer_3<SM, Square>, Square>::value, "from the border");
static_assert(std::is_constructible<SMP::Discrete_lie_flow_parameterizer_3<SM>, Circle>::value, "default start from its border");
static_assert(std::is_convertible<Circle, SMP::Symmetric_barycentric_mapping_parameterizer_3<SM> >::value,
              "Symmetric_barycentric_mapping_parameterizer_3 from its border, as CGAL's parameterizers");

std::string mesh_path(const std::string& name) { return std::string(DLF_DATA_DIR) + "/meshes/" + name + ".off"; }

bool read_sm(const std::string& name, SM& sm) { return CGAL::IO::read_polygon_mesh(mesh_path(name), sm) && !faces(sm).empty(); }

SM_halfedge longest(SM& sm) { return CGAL::Polygon_mesh_processing::longest_border(sm).first; }

// A code an entry point returned, as CGAL's programs print it.
void expect_cgal_explains(SMP::Error_code code, const std::string& what)
{
  const char* m = SMP::get_error_message(code);
  ASSERT_NE(m, nullptr) << what << ": code " << int(code);
  EXPECT_STRNE(m, "Unknown error") << what << ": code " << int(code);
  EXPECT_LE(int(code), int(SMP::ERROR_NO_1_TO_1_MAPPING)) << what;
}

// The final map, scored independently of the report.
SMP::Discrete_lie_flow_distortion score(SM& sm, UV_map uv) { return SMP::discrete_lie_flow_distortion(sm, uv); }

TEST(DropIn, BorderParameterizerAsSecondArgument)
{
  SM sm;
  ASSERT_TRUE(read_sm("nefertiti", sm));
  const SM_halfedge bhd = longest(sm);
  {
    UV_map uv = sm.add_property_map<SM_vertex, Point_2>("v:uv_circle").first;
    SMP::Discrete_lie_flow_parameterizer_3<SM, Circle> p;
    ASSERT_EQ(SMP::parameterize(sm, p, bhd, uv), SMP::OK) << p.report().message;
    EXPECT_TRUE(p.report().converged()) << p.report().message;
    EXPECT_EQ(p.report().border, SMP::Discrete_lie_flow_border::CIRCLE);
    const SMP::Discrete_lie_flow_distortion d = score(sm, uv);
    EXPECT_EQ(d.inverted_faces + d.degenerate_faces, 0u);
    EXPECT_LE(d.d_area, 2.01);
  }
  {
    // CGAL's square_border_parameterizer idiom: the corners given to the border.
    UV_map uv = sm.add_property_map<SM_vertex, Point_2>("v:uv_square").first;
    typedef SMP::Discrete_lie_flow_parameterizer_3<SM, Square> Parameterizer;
    std::vector<SM_vertex> loop;
    for(SM_halfedge h : halfedges_around_face(bhd, sm)) loop.push_back(target(h, sm));
    ASSERT_GE(loop.size(), 8u);
    const std::size_t q = loop.size() / 4;
    Square border(loop[0], loop[q], loop[2 * q], loop[3 * q]);
    Parameterizer p(border);
    ASSERT_EQ(SMP::parameterize(sm, p, bhd, uv), SMP::OK) << p.report().message;
    EXPECT_TRUE(p.report().converged()) << p.report().message;
    EXPECT_EQ(p.report().border, SMP::Discrete_lie_flow_border::SQUARE);
    // The given corners are the square's.
    const Point_2 c0 = uv[loop[0]], c1 = uv[loop[q]];
    EXPECT_NEAR(std::abs(c0.x() - c1.x()) + std::abs(c0.y() - c1.y()), 1.0, 1e-9) << "adjacent corners of the unit square";
    const SMP::Discrete_lie_flow_distortion d = score(sm, uv);
    EXPECT_EQ(d.inverted_faces + d.degenerate_faces, 0u);
    EXPECT_LE(d.d_area, 2.01);
    // A temporary, as CGAL's programs pass it.
    UV_map uv2 = sm.add_property_map<SM_vertex, Point_2>("v:uv_square2").first;
    EXPECT_EQ(SMP::parameterize(sm, Parameterizer(border), bhd, uv2), SMP::OK);
    for(SM_vertex v : vertices(sm)) ASSERT_EQ(uv[v], uv2[v]);
  }
  {
    // Two vertices: LSCM's free border, as CGAL's LSCM_parameterizer_3 takes
    // it: the border floats (it moves as freely as the interior).
    UV_map uv = sm.add_property_map<SM_vertex, Point_2>("v:uv_free").first;
    SMP::Discrete_lie_flow_parameterizer_3<SM, Two_vertices> p;
    ASSERT_EQ(SMP::parameterize(sm, p, bhd, uv), SMP::OK) << p.report().message;
    EXPECT_EQ(p.report().border, SMP::Discrete_lie_flow_border::FLOATING);
    EXPECT_TRUE(p.report().converged()) << p.report().message;
    EXPECT_EQ(score(sm, uv).inverted_faces, 0u);
    // LSCM named as the initial parameterizer: its outline is the domain, as before.
    UV_map uv2 = sm.add_property_map<SM_vertex, Point_2>("v:uv_lscm").first;
    SMP::Discrete_lie_flow_parameterizer_3<SM, SMP::LSCM_parameterizer_3<SM> > q;
    ASSERT_EQ(SMP::parameterize(sm, q, bhd, uv2), SMP::OK) << q.report().message;
    EXPECT_EQ(q.report().border, SMP::Discrete_lie_flow_border::FREE);
  }
}

TEST(DropIn, IterativeAuthalicCalls)
{
  SM sm;
  ASSERT_TRUE(read_sm("three_peaks", sm));
  const SM_halfedge bhd = longest(sm);
  typedef SMP::Discrete_lie_flow_parameterizer_3<SM, Circle> Parameterizer;
  Circle border;
  Parameterizer p(border);
  UV_map uv = sm.add_property_map<SM_vertex, Point_2>("v:uv").first;
  ASSERT_EQ(p.parameterize(sm, bhd, uv, 15u), SMP::OK) << p.report().message;
  EXPECT_TRUE(p.report().converged()) << p.report().message;
  EXPECT_LE(p.report().iterations, 15u);
  EXPECT_EQ(p.options().max_iterations, SMP::Discrete_lie_flow_options().max_iterations) << "the cap is for the call only";
  // The cap binds: one iteration, a valid map short of the targets.
  ASSERT_EQ(p.parameterize(sm, uv, 1u), SMP::OK);
  EXPECT_EQ(p.report().iterations, 1u);
  EXPECT_FALSE(p.report().converged());
  // The overload with the maps, iterations and error: in/out as CGAL's.
  auto vim = sm.add_property_map<SM_vertex, int>("v:index").first;
  auto vpm = sm.add_property_map<SM_vertex, bool>("v:param", false).first;
  for(SM_vertex v : vertices(sm)) vim[v] = int(v.idx());
  unsigned int iterations = 15;
  double error = -1;
  ASSERT_EQ(p.parameterize(sm, bhd, uv, vim, vpm, iterations, error), SMP::OK);
  EXPECT_EQ(iterations, p.report().iterations);
  EXPECT_GT(iterations, 0u);
  EXPECT_EQ(error, p.report().final_metrics.area_total);
  EXPECT_GT(error, 0.0);
  EXPECT_LT(error, p.report().initial_metrics.area_total);
  unsigned int only = 15;
  ASSERT_EQ(p.parameterize(sm, bhd, uv, vim, vpm, only), SMP::OK);
  EXPECT_EQ(only, iterations);
  ASSERT_EQ(p.parameterize(sm, bhd, uv, vim, vpm, 15u), SMP::OK);
}

// Every path that returns an error, through CGAL's entry points: a code of
// CGAL's enum that CGAL's get_error_message explains; the precise one in the report.
TEST(DropIn, CgalCodesAtCgalEntryPoints)
{
  for(int c = SMP::OK; c <= SMP::ERROR_NOT_GENUS_0 + 1; ++c)
    expect_cgal_explains(SMP::discrete_lie_flow_cgal_error_code(c), "code " + std::to_string(c));
  EXPECT_EQ(SMP::discrete_lie_flow_cgal_error_code(SMP::ERROR_INITIAL_MAP_FOLDED), SMP::ERROR_NO_1_TO_1_MAPPING);
  EXPECT_EQ(SMP::discrete_lie_flow_cgal_error_code(SMP::ERROR_NOT_GENUS_0), SMP::ERROR_NO_TOPOLOGICAL_DISC);

  typedef SMP::Discrete_lie_flow_parameterizer_3<SM> Dlf;
  struct Case { std::string name; SMP::Error_code cgal; int precise; };
  auto run = [](SM& sm, SM_halfedge bhd, Dlf& p, const Case& c) {
    UV_map uv = sm.add_property_map<SM_vertex, Point_2>("v:uv_case", Point_2(0, 0)).first;
    const SMP::Error_code code = SMP::parameterize(sm, p, bhd, uv);
    expect_cgal_explains(code, c.name);
    EXPECT_EQ(code, c.cgal) << c.name << ": " << p.report().message;
    EXPECT_EQ(int(p.report().status), c.precise) << c.name << ": " << p.report().message;
    // A temporary through CGAL's generic function: the same code.
    EXPECT_EQ(SMP::parameterize(sm, Dlf(p.initial_parameterizer(), p.options()), bhd, uv), c.cgal) << c.name;
  };
  { SM sm; Dlf p; run(sm, SM_halfedge(), p, { "empty", SMP::ERROR_EMPTY_MESH, SMP::ERROR_EMPTY_MESH }); }
  {
    SM sm; ASSERT_TRUE(read_sm("nefertiti", sm)); Dlf p;
    run(sm, *halfedges(sm).begin(), p, { "not a border halfedge", SMP::ERROR_NO_TOPOLOGICAL_DISC, SMP::ERROR_NO_TOPOLOGICAL_DISC });
    run(sm, SM_halfedge(), p, { "null halfedge", SMP::ERROR_NO_TOPOLOGICAL_DISC, SMP::ERROR_NO_TOPOLOGICAL_DISC });
  }
  {
    // A quad: not triangular.
    SM sm;
    const SM_vertex a = sm.add_vertex(K::Point_3(0, 0, 0)), b = sm.add_vertex(K::Point_3(1, 0, 0)),
                    c = sm.add_vertex(K::Point_3(1, 1, 0)), d = sm.add_vertex(K::Point_3(0, 1, 0));
    sm.add_face(a, b, c, d);
    Dlf p;
    run(sm, longest(sm), p, { "quad", SMP::ERROR_NON_TRIANGULAR_MESH, SMP::ERROR_NON_TRIANGULAR_MESH });
  }
  {
    // A zero-area face.
    SM sm;
    const SM_vertex a = sm.add_vertex(K::Point_3(0, 0, 0)), b = sm.add_vertex(K::Point_3(1, 0, 0)),
                    c = sm.add_vertex(K::Point_3(2, 0, 0)), d = sm.add_vertex(K::Point_3(1, 1, 0));
    sm.add_face(a, b, d); sm.add_face(b, c, d); sm.add_face(a, c, b);
    Dlf p;
    run(sm, longest(sm), p, { "degenerate", SMP::ERROR_CANNOT_SOLVE_LINEAR_SYSTEM, SMP::ERROR_DEGENERATE_INPUT });
  }
  {
    // A closed mesh: no border, CGAL's code for "not a disc".
    SM closed; ASSERT_TRUE(read_sm("sphere", closed));
    Dlf p;
    run(closed, longest(closed), p, { "closed", SMP::ERROR_NO_TOPOLOGICAL_DISC, SMP::ERROR_NO_TOPOLOGICAL_DISC });
  }
  {
    SM sm; ASSERT_TRUE(read_sm("nefertiti", sm));
    Dlf p;
    std::vector<double> density(num_faces(sm), 1.0);
    density[0] = 0;
    p.options().face_density = density;
    run(sm, longest(sm), p, { "zero density", SMP::ERROR_NO_1_TO_1_MAPPING, SMP::ERROR_INVALID_DENSITY });
    p.options().face_density.pop_back();
    run(sm, longest(sm), p, { "density size", SMP::ERROR_NO_1_TO_1_MAPPING, SMP::ERROR_INVALID_DENSITY });
  }
  {
    // A flow that cannot take a single step (certified, no backtracking).
    SM sm; ASSERT_TRUE(read_sm("nefertiti", sm));
    Dlf p;
    p.options().fixed_step = 1e6;
    p.options().max_backtracks = 0;
    run(sm, longest(sm), p, { "stalled", SMP::ERROR_NO_1_TO_1_MAPPING, SMP::ERROR_FLOW_STALLED });
  }
  {
    // A folded start: the caller's map with two vertices swapped.
    SM sm; ASSERT_TRUE(read_sm("nefertiti", sm));
    const SM_halfedge bhd = longest(sm);
    UV_map start = sm.add_property_map<SM_vertex, Point_2>("v:start").first;
    ASSERT_EQ(SMP::parameterize(sm, Dlf::Initial_parameterizer(), bhd, start), SMP::OK);
    SM_vertex inner[2];
    int k = 0;
    for(SM_vertex v : vertices(sm))
      if(k < 2 && !is_border(v, sm)) inner[k++] = v;
    std::swap(start[inner[0]], start[inner[1]]);
    typedef SMP::Given_uv_parameterizer_3<SM, UV_map> Given;
    SMP::Discrete_lie_flow_parameterizer_3<SM, Given> p{ Given(start) };
    UV_map uv = sm.add_property_map<SM_vertex, Point_2>("v:uv_folded").first;
    const SMP::Error_code code = SMP::parameterize(sm, p, bhd, uv);
    expect_cgal_explains(code, "folded start");
    EXPECT_EQ(code, SMP::ERROR_NO_1_TO_1_MAPPING);
    EXPECT_EQ(int(p.report().status), int(SMP::ERROR_INITIAL_MAP_FOLDED));
  }
  {
    // A floating border in a mode that does not take it.
    SM sm; ASSERT_TRUE(read_sm("nefertiti", sm));
    Dlf p;
    p.options().mode = SMP::Discrete_lie_flow_mode::PAPER;
    p.options().disk.border = SMP::Discrete_lie_flow_border::FLOATING;
    run(sm, longest(sm), p, { "floating border, paper mode", SMP::ERROR_NO_1_TO_1_MAPPING, SMP::ERROR_WRONG_PARAMETER });
    EXPECT_NE(p.report().message.find("a floating border takes the certified mode"), std::string::npos) << p.report().message;
  }
  {
    // A vertex index map that is no numbering.
    SM sm; ASSERT_TRUE(read_sm("nefertiti", sm));
    auto uv = sm.add_property_map<SM_vertex, Point_2>("v:uv").first;
    auto vim = sm.add_property_map<SM_vertex, int>("v:index", 0).first;
    auto vpm = sm.add_property_map<SM_vertex, bool>("v:param", false).first;
    Dlf p;
    const SMP::Error_code code = p.parameterize(sm, longest(sm), uv, vim, vpm);
    expect_cgal_explains(code, "index map");
    EXPECT_EQ(int(p.report().status), int(SMP::ERROR_WRONG_PARAMETER));
  }
  {
    // The initial parameterizer's own codes pass through (CGAL's, unchanged).
    SM sm; ASSERT_TRUE(read_sm("nefertiti", sm));
    typedef SMP::Discrete_lie_flow_parameterizer_3<SM, SMP::Discrete_conformal_map_parameterizer_3<SM, Two_vertices> > Nonconvex;
    Nonconvex p;
    UV_map uv = sm.add_property_map<SM_vertex, Point_2>("v:uv_nc").first;
    const SMP::Error_code code = SMP::parameterize(sm, p, longest(sm), uv);
    expect_cgal_explains(code, "non-convex border for a fixed-border start");
    EXPECT_NE(code, SMP::OK);
  }
}

// CGAL's lscm example: lion cut by its seams is a disk with holes; from the
// caller's LSCM start (free border, not convex) the start is kept, each
// hole's virtual vertex placed inside the hole, the border floats, and the
// flow converges. (Sliding on LSCM's outline instead, lion3 and lion4 stop
// at D_area 2.9 and 3.2.)
typedef SM::Property_map<SM_halfedge, Point_2> Seam_uv;
typedef SM::Property_map<SM_edge, bool> Seam_edges;
typedef SM::Property_map<SM_vertex, bool> Seam_vertices;
typedef CGAL::Seam_mesh<SM, Seam_edges, Seam_vertices> Seam;

TEST(DropIn, LscmStartKeptOnLionSeams)
{
  const std::string examples = DLF_CGAL_EXAMPLES_DIR;
  if(examples.empty() || !std::ifstream(examples + "/data/lion.selection.txt")) {
    if(std::getenv("DLF_REQUIRE_ALL")) FAIL() << "CGAL's examples are not extracted (DLF_REQUIRE_ALL: may not skip)";
    GTEST_SKIP() << "CGAL's Surface_mesh_parameterization examples (libcgal-demo's examples.tar.gz) are not extracted";
  }
  // lion's seams leave a hole whose LSCM polygon crosses itself (LSCM's map
  // overlaps there): no fill of it is positive, the start falls back to the
  // circle, as the message says; lion3's and lion4's LSCM starts are kept.
  for(const std::string seams : { "lion", "lion3", "lion4" }) {
    SM sm;
    ASSERT_TRUE(read_sm("lion", sm));
    Seam_edges se = sm.add_property_map<SM_edge, bool>("e:on_seam", false).first;
    Seam_vertices sv = sm.add_property_map<SM_vertex, bool>("v:on_seam", false).first;
    Seam mesh(sm, se, sv);
    ASSERT_NE(mesh.add_seams((examples + "/data/" + seams + ".selection.txt").c_str()), SM_halfedge()) << seams;
    Seam_uv uv = sm.add_property_map<SM_halfedge, Point_2>("h:uv").first;
    const boost::graph_traits<Seam>::halfedge_descriptor bhd = CGAL::Polygon_mesh_processing::longest_border(mesh).first;
    SMP::Discrete_lie_flow_parameterizer_3<Seam, SMP::Two_vertices_parameterizer_3<Seam> > p;
    ASSERT_EQ(SMP::parameterize(mesh, p, bhd, uv), SMP::OK) << seams << ": " << p.report().message;
    const SMP::Discrete_lie_flow_report& r = p.report();
    EXPECT_GT(r.holes, 0u) << seams;
    if(seams == "lion") {
      EXPECT_NE(r.message.find("is not simple"), std::string::npos) << seams << ": " << r.message;
      EXPECT_NE(r.message.find("fallback: Tutte's embedding of the filled disk on the circle"), std::string::npos) << r.message;
    } else {
      EXPECT_NE(r.message.find("initial map: the initial parameterizer's map, each hole's virtual vertex inside the hole"),
                std::string::npos) << seams << ": " << r.message;
    }
    EXPECT_EQ(r.border, SMP::Discrete_lie_flow_border::FLOATING) << seams;
    EXPECT_TRUE(r.converged()) << seams << ": " << r.message;
    EXPECT_EQ(r.caller_inverted_faces, 0u) << seams;
    // Scored apart from the report: the caller's faces, the exact predicate.
    const SMP::Discrete_lie_flow_distortion d = SMP::discrete_lie_flow_distortion(mesh, uv);
    EXPECT_EQ(d.inverted_faces + d.degenerate_faces, 0u) << seams;
    EXPECT_LE(d.d_area, 2.01) << seams;
  }
}

// A disk with a hole from a caller's fold-free start: kept, the hole's
// virtual vertex placed inside it. A start that cannot be kept, and whose
// outer loop Tutte cannot fill (it crosses itself), falls back to the
// circle, and the message says so.
TEST(DropIn, HoleStartKeptOrCircleFallback)
{
  SM sm;
  ASSERT_TRUE(read_sm("nefertiti", sm));
  typedef SMP::Discrete_lie_flow_parameterizer_3<SM> Dlf;
  // The start: Tutte's map of the whole disk, then the faces around an
  // interior vertex away from the border removed: the hole's uv polygon is
  // star-shaped around that vertex's image.
  UV_map start = sm.add_property_map<SM_vertex, Point_2>("v:start").first;
  ASSERT_EQ(SMP::parameterize(sm, Dlf::Initial_parameterizer(), longest(sm), start), SMP::OK);
  SM_vertex centre;
  for(SM_vertex v : vertices(sm)) {
    bool inner = !is_border(v, sm);
    for(SM_vertex w : vertices_around_target(halfedge(v, sm), sm)) inner = inner && !is_border(w, sm);
    if(inner) { centre = v; break; }
  }
  ASSERT_NE(centre, SM_vertex());
  std::vector<boost::graph_traits<SM>::face_descriptor> fan;
  for(auto f : faces_around_target(halfedge(centre, sm), sm)) fan.push_back(f);
  for(auto f : fan) CGAL::Euler::remove_face(halfedge(f, sm), sm);
  const SM_halfedge bhd = longest(sm);
  typedef SMP::Given_uv_parameterizer_3<SM, UV_map> Given;
  {
    SMP::Discrete_lie_flow_parameterizer_3<SM, Given> p{ Given(start) };
    UV_map uv = sm.add_property_map<SM_vertex, Point_2>("v:uv").first;
    ASSERT_EQ(SMP::parameterize(sm, p, bhd, uv), SMP::OK) << p.report().message;
    EXPECT_EQ(p.report().holes, 1u);
    EXPECT_NE(p.report().message.find("the initial parameterizer's map, each hole's virtual vertex inside the hole"),
              std::string::npos) << p.report().message;
    EXPECT_TRUE(p.report().converged()) << p.report().message;
    EXPECT_EQ(p.report().border, SMP::Discrete_lie_flow_border::CIRCLE);
    EXPECT_EQ(score(sm, uv).inverted_faces, 0u);
    // The start the flow took is the caller's, vertex for vertex.
    std::size_t same = 0;
    auto vim = get(CGAL::dynamic_vertex_property_t<int>(), sm);
    SMP::internal::fill_index_map_of_cc(bhd, sm, vim);
    for(SM_vertex v : vertices(sm))
      if(p.report().initial_uv[std::size_t(get(vim, v))] == std::array<double, 2>{{ start[v].x(), start[v].y() }}) ++same;
    EXPECT_EQ(same, p.report().initial_uv.size());
    EXPECT_EQ(same, std::size_t(vertices(sm).size()));
  }
  {
    // Two consecutive outer vertices swapped: the border edge between them
    // turns round and its face folds, in the caller's start and in Tutte's
    // map inside the (self-crossing) outer loop alike.
    UV_map crossed = sm.add_property_map<SM_vertex, Point_2>("v:crossed").first;
    for(SM_vertex v : vertices(sm)) crossed[v] = start[v];
    std::swap(crossed[target(bhd, sm)], crossed[target(next(bhd, sm), sm)]);
    SMP::Discrete_lie_flow_parameterizer_3<SM, Given> p{ Given(crossed) };
    UV_map uv = sm.add_property_map<SM_vertex, Point_2>("v:uv2").first;
    ASSERT_EQ(SMP::parameterize(sm, p, bhd, uv), SMP::OK) << p.report().message;
    EXPECT_NE(p.report().message.find("was not kept: the initial map folds"), std::string::npos) << p.report().message;
    EXPECT_NE(p.report().message.find("fallback: Tutte's embedding of the filled disk on the circle"), std::string::npos)
      << p.report().message;
    EXPECT_TRUE(p.report().converged()) << p.report().message;
    EXPECT_EQ(score(sm, uv).inverted_faces, 0u);
  }
}

// A hole no single point sees whole (a U one cell wide in a grid, the
// grid's own positions as the start): the fan cannot be placed, the
// triangulation of the hole's polygon can, and the caller's start is kept.
TEST(DropIn, HoleNotStarShapedKeepsTheStart)
{
  const int N = 16;
  SM sm;
  UV_map start = sm.add_property_map<SM_vertex, Point_2>("v:start").first;
  std::vector<SM_vertex> grid((N + 1) * (N + 1));
  for(int j = 0; j <= N; ++j)
    for(int i = 0; i <= N; ++i) {
      // A bump in 3D: the targets differ from the grid's areas.
      const double z = 0.3 * std::exp(-((i - 4) * (i - 4) + (j - 11) * (j - 11)) / 8.0);
      grid[std::size_t(j * (N + 1) + i)] = sm.add_vertex(K::Point_3(i, j, z));
      start[grid[std::size_t(j * (N + 1) + i)]] = Point_2(i, j);
    }
  // The U: the bottom row 4..11 at height 4, the arms at columns 4 and 11 up to 11.
  auto in_hole = [](int i, int j) { return (j == 4 && i >= 4 && i <= 11) || ((i == 4 || i == 11) && j >= 4 && j <= 11); };
  for(int j = 0; j < N; ++j)
    for(int i = 0; i < N; ++i) {
      if(in_hole(i, j)) continue;
      const SM_vertex a = grid[std::size_t(j * (N + 1) + i)], b = grid[std::size_t(j * (N + 1) + i + 1)],
                      c = grid[std::size_t((j + 1) * (N + 1) + i + 1)], d = grid[std::size_t((j + 1) * (N + 1) + i)];
      ASSERT_NE(sm.add_face(a, b, c), SM::null_face());
      ASSERT_NE(sm.add_face(a, c, d), SM::null_face());
    }
  const SM_halfedge bhd = longest(sm);
  std::size_t outer = 0;
  for(SM_halfedge h : halfedges_around_face(bhd, sm)) { (void)h; ++outer; }
  ASSERT_EQ(outer, std::size_t(4 * N)) << "the grid's outer border";
  typedef SMP::Given_uv_parameterizer_3<SM, UV_map> Given;
  SMP::Discrete_lie_flow_parameterizer_3<SM, Given> p{ Given(start) };
  UV_map uv = sm.add_property_map<SM_vertex, Point_2>("v:uv").first;
  ASSERT_EQ(SMP::parameterize(sm, p, bhd, uv), SMP::OK) << p.report().message;
  const SMP::Discrete_lie_flow_report& r = p.report();
  EXPECT_EQ(r.holes, 1u);
  EXPECT_NE(r.message.find("initial map: the initial parameterizer's map, each hole's virtual vertex inside the hole"),
            std::string::npos) << r.message;
  EXPECT_TRUE(r.converged()) << r.message;
  const SMP::Discrete_lie_flow_distortion d = score(sm, uv);
  EXPECT_EQ(d.inverted_faces + d.degenerate_faces, 0u);
  EXPECT_LE(d.d_area, 2.01);
  // The start the flow took is the caller's, vertex for vertex.
  auto vim = get(CGAL::dynamic_vertex_property_t<int>(), sm);
  SMP::internal::fill_index_map_of_cc(bhd, sm, vim);
  std::size_t same = 0;
  for(SM_vertex v : vertices(sm))
    if(r.initial_uv[std::size_t(get(vim, v))] == std::array<double, 2>{{ start[v].x(), start[v].y() }}) ++same;
  EXPECT_EQ(same, std::size_t(vertices(sm).size()));

  // The triangulation itself: as many faces as the fan, closing the loop,
  // positive; a polygon that crosses itself is refused.
  const std::vector<D::Vec2> pts{{ {{ 0, 0 }}, {{ 3, 0 }}, {{ 3, 3 }}, {{ 2, 3 }}, {{ 2, 1 }}, {{ 1, 1 }}, {{ 1, 3 }}, {{ 0, 3 }},
                                   {{ 0, 0 }} }};
  const std::vector<int> loop{ 0, 1, 2, 3, 4, 5, 6, 7 };
  std::vector<D::Face> fill;
  D::Vec2 at;
  ASSERT_TRUE(D::triangulate_hole(pts, loop, 8, 1, fill, at));
  EXPECT_EQ(fill.size(), loop.size());
  std::vector<D::Vec2> with_c(pts);
  with_c[8] = at;
  EXPECT_TRUE(D::count_orientations_2(with_c, fill).all_positive());
  const std::vector<int> crossing{ 0, 2, 1, 7 }; // (0,0) (3,3) (3,0) (0,3): a figure eight
  EXPECT_FALSE(D::triangulate_hole(pts, crossing, 8, 1, fill, at));
}

} // namespace

} // namespace dlf_test_drop_in
