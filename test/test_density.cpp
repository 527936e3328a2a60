// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Measure control (the paper's §5.5): densities and regions of interest on
// real disks of CGAL's data set. Shares, orientations and areas are
// recomputed here from the positions (exact orientation with CGAL's
// predicate); the library's report is used only for iteration counts and,
// comparing two runs, D_area.
//
// Density runs use `Density_tolerance` (D_area ≤ 2 + 5e-4) instead of the
// default 1e-2: with 1e-2 a region's share misses the prescribed one by up
// to 13% (doc/measure_control.md). The plain runs they are compared with use
// the same tolerance.

#include <gtest/gtest.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_density.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/density_levels.h>
#include <CGAL/subdivision_method_3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <set>
#include <string>
#include <vector>

// The tests compile in unity batches (DLF_UNITY_BUILD): each file keeps its
// names in a namespace of its own.
namespace dlf_test_density {

namespace SMP = CGAL::Surface_mesh_parameterization;

namespace {

typedef CGAL::Simple_cartesian<double> K;
typedef CGAL::Surface_mesh<K::Point_3> SM;
typedef boost::graph_traits<SM>::vertex_descriptor SM_vertex;
typedef boost::graph_traits<SM>::face_descriptor SM_face;
typedef boost::graph_traits<SM>::halfedge_descriptor SM_halfedge;
typedef SM::Property_map<SM_vertex, K::Point_2> UV_map;
typedef SM::Property_map<SM_face, double> Density_map;
typedef SMP::Discrete_lie_flow_parameterizer_3<SM> Dlf;
typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_2 Exact_point_2;

const double Density_tolerance = 5e-4;

struct Loaded
{
  SM sm;
  SM_halfedge bhd;
  double diagonal = 0;
};

void load(const std::string& name, Loaded& m)
{
  std::ifstream in(std::string(DLF_DATA_DIR) + "/meshes/" + name + ".off");
  ASSERT_TRUE(in && (in >> m.sm)) << name;
  m.bhd = boost::graph_traits<SM>::null_halfedge();
  for(SM_halfedge h : halfedges(m.sm))
    if(is_border(h, m.sm)) { m.bhd = h; break; }
  ASSERT_NE(m.bhd, boost::graph_traits<SM>::null_halfedge());
  CGAL::Bbox_3 b;
  for(SM_vertex v : vertices(m.sm)) b += m.sm.point(v).bbox();
  m.diagonal = std::sqrt(CGAL::square(b.xmax() - b.xmin()) + CGAL::square(b.ymax() - b.ymin()) +
                         CGAL::square(b.zmax() - b.zmin()));
}

std::vector<std::array<K::Point_2, 3> > domain_triangles(const SM& sm, UV_map uv)
{
  std::vector<std::array<K::Point_2, 3> > out;
  for(SM_face f : faces(sm)) {
    const SM_halfedge h = halfedge(f, sm);
    out.push_back({{ get(uv, source(h, sm)), get(uv, target(h, sm)), get(uv, target(next(h, sm), sm)) }});
  }
  return out;
}

/// Faces that are not oriented like the majority, or flat (exact predicate).
std::size_t inverted_or_flat(const SM& sm, UV_map uv)
{
  long positive = 0, negative = 0, zero = 0;
  for(const auto& t : domain_triangles(sm, uv)) {
    const CGAL::Orientation o = CGAL::orientation(Exact_point_2(t[0].x(), t[0].y()), Exact_point_2(t[1].x(), t[1].y()),
                                                  Exact_point_2(t[2].x(), t[2].y()));
    if(o == CGAL::POSITIVE) ++positive; else if(o == CGAL::NEGATIVE) ++negative; else ++zero;
  }
  return std::size_t((std::min)(positive, negative) + zero);
}

/// Shares of the region: achieved (domain area) and prescribed (ρ·area), in long double.
std::pair<double, double> shares(const SM& sm, const std::set<SM_face>& region, UV_map uv, Density_map rho)
{
  long double dom_in = 0, dom = 0, tgt_in = 0, tgt = 0;
  for(SM_face f : faces(sm)) {
    const SM_halfedge h = halfedge(f, sm);
    const K::Point_2 &a = get(uv, source(h, sm)), &b = get(uv, target(h, sm)), &c = get(uv, target(next(h, sm), sm));
    const long double u = std::fabs(((long double)b.x() - a.x()) * ((long double)c.y() - a.y()) -
                                    ((long double)b.y() - a.y()) * ((long double)c.x() - a.x())) / 2;
    const K::Point_3 &p = sm.point(source(h, sm)), &q = sm.point(target(h, sm)), &r = sm.point(target(next(h, sm), sm));
    const long double t = get(rho, f) * std::sqrt((long double)CGAL::squared_area(p, q, r));
    dom += u; tgt += t;
    if(region.count(f)) { dom_in += u; tgt_in += t; }
  }
  return std::make_pair(double(dom_in / dom), double(tgt_in / tgt));
}

struct Flow_run
{
  SMP::Error_code code = SMP::OK;
  std::size_t iterations = 0;
  double d_area = 0;
  std::string stop, message;
  std::vector<K::Point_2> uv;
};

/// One run of the default parameterizer (Tutte on a circle, certified flow).
template <class Setup>
Flow_run flow(Loaded& m, double tolerance, Setup setup)
{
  UV_map uv = m.sm.add_property_map<SM_vertex, K::Point_2>("v:uv").first;
  SMP::Discrete_lie_flow_options options;
  options.tolerance = tolerance;
  Dlf dlf(Dlf::Initial_parameterizer(), options);
  setup(dlf);
  Flow_run r;
  // The precise code (the report's); the entry point returns CGAL's nearest.
  const SMP::Error_code cgal = SMP::parameterize(m.sm, dlf, m.bhd, uv);
  r.code = dlf.report().status;
  EXPECT_EQ(cgal, SMP::discrete_lie_flow_cgal_error_code(r.code));
  r.iterations = dlf.report().iterations;
  r.d_area = dlf.report().final_d_area;
  r.stop = SMP::discrete_lie_flow_stop_reason_name(dlf.report().stop_reason);
  r.message = dlf.report().message;
  for(SM_vertex v : vertices(m.sm)) r.uv.push_back(get(uv, v));
  return r;
}

struct No_density { void operator()(Dlf&) const {} };

/// The README's promise for a density: every region, and the rest of the
/// surface, within 0.5% of its prescribed share (relative), once converged.
const double share_promise = 5e-3;

/// The larger relative error of a region's share and of its complement's:
/// `s.first` achieved, `s.second` prescribed.
double region_and_complement_error(const std::pair<double, double>& s)
{
  return (std::max)(std::abs(s.first - s.second) / s.second,
                    std::abs((1 - s.first) - (1 - s.second)) / (1 - s.second));
}

/// Region shares for factors 0.25 … 16 (the promise, with convergence) and
/// exact orientation. (Their cost against the plain run is the benchmark's:
/// benchmark/density.sh.)
void check_region_factors(const std::string& name, const std::vector<SM_face>& region_faces, Loaded& m, double band)
{
  const std::set<SM_face> region(region_faces.begin(), region_faces.end());
  ASSERT_GT(region.size(), 50u);
  ASSERT_LT(region.size(), num_faces(m.sm) / 4);
  const Flow_run plain = flow(m, Density_tolerance, No_density());
  ASSERT_EQ(plain.code, SMP::OK) << plain.message;
  Density_map rho = m.sm.add_property_map<SM_face, double>("f:rho", 1.).first;
  UV_map uv = m.sm.property_map<SM_vertex, K::Point_2>("v:uv").first;
  for(double factor : { 0.25, 0.5, 2., 4., 16. }) {
    SCOPED_TRACE(name + ", factor " + std::to_string(factor));
    SMP::set_region_density(m.sm, region_faces, factor, rho, band);
    const Flow_run r = flow(m, Density_tolerance, [&](Dlf& d) { d.set_face_density(rho); });
    ASSERT_EQ(r.code, SMP::OK) << r.message;
    EXPECT_EQ(inverted_or_flat(m.sm, uv), 0u);
    const std::pair<double, double> s = shares(m.sm, region, uv, rho);
    // The library's helper agrees with the recomputation.
    const std::pair<double, double> h = SMP::region_area_fractions(m.sm, region_faces, uv, rho);
    EXPECT_NEAR(h.first, s.first, 1e-12);
    EXPECT_NEAR(h.second, s.second, 1e-12);
    const double ratio = double(r.iterations) / double(plain.iterations);
    std::printf("  %-16s factor %5.2f: share %.5f prescribed, %.5f achieved (%+.3f%%), %zu iterations (%s), "
                "%.2f x plain (%zu)\n", name.c_str(), factor, s.second, s.first, 100 * (s.first - s.second) / s.second,
                r.iterations, r.stop.c_str(), ratio, plain.iterations);
    EXPECT_EQ(r.stop, "converged");
    EXPECT_LE(region_and_complement_error(s), share_promise);
  }
}

} // namespace

// A Euclidean ball around one of the three peaks (the peaks point to −y),
// a density jump at its border (no band).
TEST(DensityRegions, ThreePeaksBallSharesWithinTheTolerance)
{
  Loaded m;
  load("three_peaks", m);
  const std::vector<SM_face> region = SMP::faces_in_ball(m.sm, K::Point_3(-4.25, -7.132335, 12.742857), 0.15 * m.diagonal);
  check_region_factors("three_peaks", region, m, 0.);
}

// A geodesic (edge-path) ball around a vertex of the bumped sheet, with a
// transition band.
TEST(DensityRegions, MeshWithBorderGeodesicBallSharesWithinTheTolerance)
{
  Loaded m;
  load("mesh_with_border", m);
  const std::vector<SM_face> region = SMP::faces_in_geodesic_ball(m.sm, SM_vertex(54), 0.15 * m.diagonal);
  check_region_factors("mesh_with_border", region, m, 0.1 * m.diagonal);
}

// D_area lets a whole region drift on a finer mesh (nefertiti after one
// Loop subdivision, at the default tolerance 2.01: ×0.25 ends 25% over its
// share, ×2 10%); the share tolerance holds every region, and the report's
// share error is the region's relative error, recomputed here.
TEST(DensityRegions, ShareToleranceHoldsTheRegionsOfAFinerMesh)
{
  Loaded m;
  load("nefertiti", m);
  CGAL::Subdivision_method_3::Loop_subdivision(m.sm, CGAL::parameters::number_of_iterations(1));
  m.bhd = boost::graph_traits<SM>::null_halfedge();
  for(SM_halfedge h : halfedges(m.sm))
    if(is_border(h, m.sm)) { m.bhd = h; break; }
  const std::vector<SM_face> region_faces = SMP::faces_in_ball(m.sm, K::Point_3(-0.215988, -0.081660, 0.215680), 1.);
  const std::set<SM_face> region(region_faces.begin(), region_faces.end());
  ASSERT_GT(region.size(), 200u);
  Density_map rho = m.sm.add_property_map<SM_face, double>("f:rho", 1.).first;
  UV_map uv = m.sm.add_property_map<SM_vertex, K::Point_2>("v:uv").first;
  double worst_without = 0;
  for(double factor : { 0.25, 0.5, 2., 4. }) {
    SCOPED_TRACE("factor " + std::to_string(factor));
    SMP::set_region_density(m.sm, region_faces, factor, rho, 0.);
    for(double share_tolerance : { 0., 5e-3 }) {
      SMP::Discrete_lie_flow_options options;
      options.tolerance = 1e-2;
      options.certified.share_tolerance = share_tolerance;
      Dlf dlf(Dlf::Initial_parameterizer(), options);
      dlf.set_face_density(rho);
      ASSERT_EQ(SMP::parameterize(m.sm, dlf, m.bhd, uv), SMP::OK) << dlf.report().message;
      EXPECT_EQ(inverted_or_flat(m.sm, uv), 0u);
      const std::pair<double, double> s = shares(m.sm, region, uv, rho);
      const double error = region_and_complement_error(s);
      std::printf("  nefertiti+loop1 factor %4.2f share tolerance %g: %+.3f%%, %zu iterations (%s)\n", factor,
                  share_tolerance, 100 * (s.first - s.second) / s.second, dlf.report().iterations,
                  SMP::discrete_lie_flow_stop_reason_name(dlf.report().stop_reason));
      // One jump, one cut: the report's error is the region's.
      EXPECT_NEAR(dlf.report().final_share_error, error, 1e-9);
      if(share_tolerance == 0) { worst_without = (std::max)(worst_without, error); continue; }
      EXPECT_EQ(dlf.report().stop_reason, SMP::Discrete_lie_flow_stop_reason::CONVERGED);
      EXPECT_LE(error, share_promise);
    }
  }
  // Without the test on shares, the regions miss the 1% goal: the mesh
  // exercises what the tolerance is for.
  EXPECT_GT(worst_without, 0.05);
}

// The regions checked: none for a uniform density, whatever its scale, or
// for a region of a few faces; the region and its complement for a jump; the
// region still a cut when a band blends ρ between them; the tenths of the
// measure for a smooth density.
TEST(DensityRegions, ShareErrorCutsOnTheDensityValues)
{
  namespace D = CGAL::Surface_mesh_parameterization::internal::dlf;
  // A strip of 2n unit right triangles; face t has area 1/2.
  const auto strip = [](int n, std::vector<D::Vec3>& xyz, std::vector<D::Face>& faces) {
    for(int i = 0; i <= n; ++i) { xyz.push_back({{ double(i), 0, 0 }}); xyz.push_back({{ double(i), 1, 0 }}); }
    for(int i = 0; i < n; ++i) {
      faces.push_back({{ 2 * i, 2 * i + 2, 2 * i + 3 }});
      faces.push_back({{ 2 * i, 2 * i + 3, 2 * i + 1 }});
    }
  };
  std::vector<D::Vec3> xyz;
  std::vector<D::Face> faces;
  strip(100, xyz, faces);
  const std::size_t F = faces.size(), R = 40; // R region faces, more than min_faces
  std::vector<double> target(F, 0.5 * 3.), area(F, 1.);
  const D::Density_levels uniform(xyz, faces, target);
  EXPECT_TRUE(uniform.uniform());
  area[0] = 5;
  EXPECT_EQ(uniform.error(area), 0.);
  // Region: the first R faces at ρ = 4 (prescribed share 80 / 160 = 1/2).
  for(std::size_t t = 0; t < F; ++t) target[t] = t < R ? 0.5 * 4 : 0.5;
  const D::Density_levels jump(xyz, faces, target);
  ASSERT_EQ(jump.cuts(), 1u);
  EXPECT_NEAR(jump.error(target), 0., 1e-13);
  // The region gets 0.51 of the domain instead of 0.5: 2% relative.
  std::vector<double> off(F);
  for(std::size_t t = 0; t < F; ++t) off[t] = t < R ? 0.51 / R : 0.49 / (F - R);
  EXPECT_NEAR(jump.error(off), 0.02, 1e-12);
  // A region of fewer than min_faces faces is not held.
  std::vector<double> small(F, 0.5);
  for(std::size_t t = 0; t < D::Density_levels::min_faces - 1; ++t) small[t] = 0.5 * 4;
  EXPECT_TRUE(D::Density_levels(xyz, faces, small).uniform());
  // A band of 20 faces blending 4 → 1 keeps the region and the rest as cuts.
  for(std::size_t t = R; t < R + 20; ++t) target[t] = 0.5 * std::pow(4., 1 - double(t - R + 1) / 21);
  const D::Density_levels band(xyz, faces, target);
  EXPECT_GE(band.cuts(), 2u);
  EXPECT_NEAR(band.error(target), 0., 1e-13);
  std::vector<double> region_over(target);
  for(std::size_t t = 0; t < R; ++t) region_over[t] *= 1.1;
  EXPECT_GT(band.error(region_over), 0.01);
  // A smooth density on a finer strip (every face its own value): cut at
  // each tenth of the measure only.
  std::vector<D::Vec3> fine_xyz;
  std::vector<D::Face> fine_faces;
  strip(500, fine_xyz, fine_faces);
  std::vector<double> smooth_target(fine_faces.size());
  for(std::size_t t = 0; t < fine_faces.size(); ++t) smooth_target[t] = 0.5 * std::exp(2 * double(t) / double(fine_faces.size()));
  const D::Density_levels smooth(fine_xyz, fine_faces, smooth_target);
  EXPECT_GE(smooth.cuts(), 9u);
  EXPECT_LE(smooth.cuts(), 10u);
  EXPECT_NEAR(smooth.error(smooth_target), 0., 1e-13);
}

// ρ ≡ 1, given as a face map, a vertex map or the options' vector, is the
// area-preserving run, bit for bit.
TEST(DensityExactness, DensityOneIsTheAreaPreservingMap)
{
  Loaded m;
  load("nefertiti", m);
  const Flow_run plain = flow(m, Density_tolerance, No_density());
  ASSERT_EQ(plain.code, SMP::OK);
  Density_map one = m.sm.add_property_map<SM_face, double>("f:one", 1.).first;
  auto vertex_one = m.sm.add_property_map<SM_vertex, double>("v:one", 1.).first;
  const Flow_run by_face = flow(m, Density_tolerance, [&](Dlf& d) { d.set_face_density(one); });
  const Flow_run by_vertex = flow(m, Density_tolerance, [&](Dlf& d) { d.set_vertex_density(vertex_one); });
  const Flow_run by_vector = flow(m, Density_tolerance, [&](Dlf& d) { d.options().face_density.assign(num_faces(m.sm), 1.); });
  for(const Flow_run* r : { &by_face, &by_vertex, &by_vector }) {
    ASSERT_EQ(r->code, SMP::OK);
    EXPECT_EQ(r->iterations, plain.iterations);
    ASSERT_EQ(r->uv.size(), plain.uv.size());
    for(std::size_t i = 0; i < plain.uv.size(); ++i) {
      ASSERT_EQ(r->uv[i].x(), plain.uv[i].x()) << "vertex " << i;
      ASSERT_EQ(r->uv[i].y(), plain.uv[i].y()) << "vertex " << i;
    }
  }
}

// ρ and c·ρ prescribe the same shares, hence the same map: bit for bit when
// c is a power of two (the scaling is exact), to 1e-9 of the domain for any
// other c, with the same stop. (Before the relaxation sweeps the flow crept
// along motions D_area hardly sees, the last-bit differences of c·ρ grew in
// that tail and the stopped maps differed by 2e-3; it now converges in 11
// iterations and they differ by 1e-14.)
TEST(DensityExactness, ScaledDensityGivesTheSameMap)
{
  Loaded m;
  load("nefertiti", m);
  const std::vector<SM_face> region = SMP::faces_in_ball(m.sm, m.sm.point(SM_vertex(100)), 0.15 * m.diagonal);
  const std::set<SM_face> region_set(region.begin(), region.end());
  Density_map rho = m.sm.add_property_map<SM_face, double>("f:rho", 1.).first;
  Density_map scaled = m.sm.add_property_map<SM_face, double>("f:scaled", 1.).first;
  UV_map uv = m.sm.add_property_map<SM_vertex, K::Point_2>("v:uv").first;
  SMP::set_region_density(m.sm, region, 4., rho, 0.05 * m.diagonal);
  auto max_difference = [](const Flow_run& a, const Flow_run& b) {
    double extent = 0, difference = 0;
    for(std::size_t i = 0; i < a.uv.size(); ++i) {
      extent = (std::max)(extent, (std::max)(std::abs(a.uv[i].x()), std::abs(a.uv[i].y())));
      difference = (std::max)(difference, std::sqrt(CGAL::squared_distance(a.uv[i], b.uv[i])));
    }
    return difference / extent;
  };
  for(double c : { 1e3 / 3, 1e-7, std::ldexp(1., -20), std::ldexp(1., 30) }) {
    SCOPED_TRACE("c = " + std::to_string(c));
    int exponent;
    const bool exact = std::frexp(c, &exponent) == 0.5; // c is a power of two
    for(SM_face f : faces(m.sm)) put(scaled, f, c * get(rho, f));
    double d_area[2];
    std::pair<double, double> share[2];
    Flow_run full[2];
    for(int k = 0; k < 2; ++k) {
      Density_map map = k == 0 ? rho : scaled;
      full[k] = flow(m, Density_tolerance, [&](Dlf& d) { d.set_face_density(map); });
      ASSERT_EQ(full[k].code, SMP::OK);
      EXPECT_EQ(inverted_or_flat(m.sm, uv), 0u);
      share[k] = shares(m.sm, region_set, uv, rho);
      d_area[k] = full[k].d_area;
    }
    // The same stop, and the same map up to the rounding of c·ρ (bit for
    // bit when c is a power of two).
    EXPECT_EQ(full[0].iterations, full[1].iterations);
    EXPECT_LE(max_difference(full[0], full[1]), 1e-9);
    if(exact) EXPECT_EQ(max_difference(full[0], full[1]), 0.);
    EXPECT_NEAR(share[0].first, share[1].first, 1e-9 * share[0].first);
    EXPECT_NEAR(d_area[0], d_area[1], 1e-12);
    std::printf("  c = %-10g: maps differ by %.1e at the stop (%zu, %zu iterations); shares %.8f, %.8f\n", c,
                max_difference(full[0], full[1]), full[0].iterations, full[1].iterations, share[0].first,
                share[1].first);
  }
}

// Zero, negative, NaN, infinite or wrongly sized densities: a clear error
// naming the face, and no flow.
TEST(DensityErrors, InvalidDensitiesAreRefusedNamingTheFace)
{
  Loaded m;
  load("nefertiti", m);
  Density_map rho = m.sm.add_property_map<SM_face, double>("f:rho", 1.).first;
  const SM_face bad(17);
  std::string corners;
  for(SM_vertex v : vertices_around_face(halfedge(bad, m.sm), m.sm)) corners += " " + std::to_string(v.idx());
  for(double value : { 0., -1., std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity() }) {
    SCOPED_TRACE("density " + std::to_string(value));
    put(rho, bad, value);
    const Flow_run r = flow(m, Density_tolerance, [&](Dlf& d) { d.set_face_density(rho); });
    EXPECT_EQ(int(r.code), int(SMP::ERROR_INVALID_DENSITY));
    EXPECT_NE(r.message.find("face (vertices" + corners + ")"), std::string::npos) << r.message;
    EXPECT_EQ(r.iterations, 0u);
    // The same through the options' vector (faces(mesh) order).
    const Flow_run v = flow(m, Density_tolerance, [&](Dlf& d) {
      d.options().face_density.assign(num_faces(m.sm), 1.);
      d.options().face_density[bad.idx()] = value;
    });
    EXPECT_EQ(int(v.code), int(SMP::ERROR_INVALID_DENSITY));
    EXPECT_NE(v.message.find("face (vertices" + corners + ")"), std::string::npos) << v.message;
  }
  for(std::size_t size : { num_faces(m.sm) - 1, num_faces(m.sm) + 1, num_vertices(m.sm) }) {
    const Flow_run r = flow(m, Density_tolerance, [&](Dlf& d) { d.options().face_density.assign(size, 1.); });
    EXPECT_EQ(int(r.code), int(SMP::ERROR_INVALID_DENSITY)) << size << " values";
    EXPECT_NE(r.message.find(std::to_string(size) + " values for " + std::to_string(num_faces(m.sm)) + " faces"),
              std::string::npos) << r.message;
  }
}

// Every vertex value is checked, not only the faces' means.
TEST(DensityErrors, InvalidVertexDensityIsRefused)
{
  Loaded m;
  load("nefertiti", m);
  auto rho = m.sm.add_property_map<SM_vertex, double>("v:rho", 1.).first;
  put(rho, SM_vertex(42), 0.);
  const Flow_run r = flow(m, Density_tolerance, [&](Dlf& d) { d.set_vertex_density(rho); });
  EXPECT_EQ(int(r.code), int(SMP::ERROR_INVALID_DENSITY));
  EXPECT_NE(r.message.find("42"), std::string::npos) << r.message;
}

} // namespace dlf_test_density
