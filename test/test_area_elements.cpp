// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The area elements of a run stored as properties of a Surface_mesh (disk
// and sphere): read back from the mesh, checked against lumped areas
// recomputed here from the map and the input, against the report, and
// against the totals (the domain's area on both sides).

#include <gtest/gtest.h>

#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_distortion.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_sphere_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <string>
#include <vector>

// The tests compile in unity batches (DLF_UNITY_BUILD): each file keeps its
// names in a namespace of its own.
namespace dlf_test_area_elements {

namespace {

namespace SMP = CGAL::Surface_mesh_parameterization;
typedef CGAL::Simple_cartesian<double> K;
typedef CGAL::Surface_mesh<K::Point_3> SM;
typedef SM::Vertex_index Vertex;
typedef SM::Face_index Face;

SM read(const std::string& name)
{
  SM sm;
  EXPECT_TRUE(CGAL::Polygon_mesh_processing::IO::read_polygon_mesh(std::string(DLF_DATA_DIR) + "/meshes/" + name, sm)) << name;
  return sm;
}

/// The face's three vertices.
std::array<Vertex, 3> corners(const SM& sm, Face f)
{
  const SM::Halfedge_index h = sm.halfedge(f);
  return {{ sm.source(h), sm.target(h), sm.target(sm.next(h)) }};
}

double area_3(const K::Point_3& a, const K::Point_3& b, const K::Point_3& c)
{
  return std::sqrt(CGAL::squared_area(a, b, c));
}

/// Lumped vertex areas ⅓ Σ area(f) of per-face areas.
std::map<Vertex, double> lumped(const SM& sm, const std::map<Face, double>& area)
{
  std::map<Vertex, double> out;
  for(Face f : sm.faces())
    for(Vertex v : corners(sm, f)) out[v] += area.at(f) / 3;
  return out;
}

/// Checks the stored properties against `domain` (per-face domain areas)
/// and the input areas times the density property; returns the total.
void expect_properties(const SM& sm, const std::map<Face, double>& domain, double expected_density_total)
{
  const auto target = sm.property_map<Vertex, double>("v:dlf_target_area");
  const auto dom = sm.property_map<Vertex, double>("v:dlf_domain_area");
  const auto density = sm.property_map<Face, double>("f:dlf_density");
  ASSERT_TRUE(target.second && dom.second && density.second) << "the properties are missing";
  std::map<Face, double> weighted;
  double U = 0, W = 0, density_total = 0;
  for(Face f : sm.faces()) {
    const std::array<Vertex, 3> c = corners(sm, f);
    weighted[f] = density.first[f] * area_3(sm.point(c[0]), sm.point(c[1]), sm.point(c[2]));
    U += domain.at(f);
    W += weighted[f];
    density_total += density.first[f];
  }
  EXPECT_NEAR(density_total, expected_density_total, 1e-9 * expected_density_total);
  const std::map<Vertex, double> lu = lumped(sm, domain), lw = lumped(sm, weighted);
  double sum_target = 0, sum_domain = 0, err_target = 0, err_domain = 0;
  for(Vertex v : sm.vertices()) {
    sum_target += target.first[v];
    sum_domain += dom.first[v];
    err_domain = (std::max)(err_domain, std::abs(dom.first[v] - lu.at(v)));
    err_target = (std::max)(err_target, std::abs(target.first[v] - lw.at(v) * U / W));
  }
  EXPECT_NEAR(sum_domain, U, 1e-12 * U) << "the domain areas do not sum to the domain's area";
  EXPECT_NEAR(sum_target, U, 1e-12 * U) << "the target areas do not sum to the domain's area";
  EXPECT_LE(err_domain, 1e-12 * U);
  EXPECT_LE(err_target, 1e-12 * U);
}

TEST(Area_elements, DiskPropertiesOnSurfaceMesh)
{
  SM sm = read("mushroom.off");
  const SM::Halfedge_index bhd = CGAL::Polygon_mesh_processing::longest_border(sm).first;
  auto uv = sm.add_property_map<Vertex, K::Point_2>("v:uv").first;
  // A density of 3 on the faces above the median height, 1 below: the stored
  // density must be the one given, face by face.
  auto rho = sm.add_property_map<Face, double>("f:rho", 1.).first;
  std::vector<double> heights;
  for(Vertex v : sm.vertices()) heights.push_back(sm.point(v).z());
  std::nth_element(heights.begin(), heights.begin() + long(heights.size() / 2), heights.end());
  const double median = heights[heights.size() / 2];
  double expected_total = 0;
  for(Face f : sm.faces()) {
    const std::array<Vertex, 3> c = corners(sm, f);
    rho[f] = (sm.point(c[0]).z() + sm.point(c[1]).z() + sm.point(c[2]).z()) / 3 > median ? 3. : 1.;
    expected_total += rho[f];
  }
  SMP::Discrete_lie_flow_parameterizer_3<SM> dlf;
  dlf.set_face_density(rho);
  ASSERT_EQ(SMP::parameterize(sm, dlf, bhd, uv), SMP::OK) << dlf.report().message;
  std::map<Face, double> domain;
  for(Face f : sm.faces()) {
    const std::array<Vertex, 3> c = corners(sm, f);
    domain[f] = std::abs(CGAL::area(uv[c[0]], uv[c[1]], uv[c[2]]));
  }
  expect_properties(sm, domain, expected_total);
  // The report holds the same values (by vertex index of the call).
  double report_total = 0;
  for(double a : dlf.report().target_area) report_total += a;
  double mesh_total = 0;
  for(Vertex v : sm.vertices()) mesh_total += sm.property_map<Vertex, double>("v:dlf_target_area").first[v];
  EXPECT_NEAR(report_total, mesh_total, 1e-12 * mesh_total);
  // The public distortion function scores the map as the flow reports it:
  // density-weighted with the density, not without.
  EXPECT_NEAR(SMP::discrete_lie_flow_distortion(sm, uv, rho).d_area, dlf.report().final_d_area, 1e-9);
  EXPECT_NEAR(SMP::discrete_lie_flow_distortion(sm, uv, rho).d_area, dlf.report().final_metrics.d_area, 1e-12);
  EXPECT_GT(SMP::discrete_lie_flow_distortion(sm, uv).d_area, dlf.report().final_d_area + 0.1);
}

TEST(Area_elements, SpherePropertiesOnSurfaceMesh)
{
  SM sm = read("blobby.off");
  auto sphere = sm.add_property_map<Vertex, K::Point_3>("v:sphere", K::Point_3(0, 0, 0)).first;
  SMP::Discrete_lie_flow_sphere_parameterizer_3<SM> dlf;
  ASSERT_EQ(dlf.parameterize(sm, sphere), SMP::OK) << dlf.report().message;
  std::map<Face, double> domain;
  for(Face f : sm.faces()) {
    const std::array<Vertex, 3> c = corners(sm, f);
    domain[f] = area_3(sphere[c[0]], sphere[c[1]], sphere[c[2]]);
  }
  expect_properties(sm, domain, double(sm.number_of_faces()));
  EXPECT_NEAR(SMP::discrete_lie_flow_sphere_distortion(sm, sphere).d_area, dlf.report().final_metrics.d_area, 1e-12);
  // A const mesh gets no properties, but the report and area_elements() have them.
  SM copy = read("blobby.off");
  const SM& const_copy = copy;
  auto sphere2 = copy.add_property_map<Vertex, K::Point_3>("v:sphere", K::Point_3(0, 0, 0)).first;
  ASSERT_EQ(dlf.parameterize(const_copy, sphere2), SMP::OK);
  EXPECT_FALSE((copy.property_map<Vertex, double>("v:dlf_target_area").second));
  auto t = copy.add_property_map<Vertex, double>("v:t", 0.).first, d = copy.add_property_map<Vertex, double>("v:d", 0.).first;
  dlf.area_elements(const_copy, t, d);
  // The same run twice: the same values up to the solver's thread-dependent rounding.
  const auto target = sm.property_map<Vertex, double>("v:dlf_target_area").first;
  const auto domain_area = sm.property_map<Vertex, double>("v:dlf_domain_area").first;
  for(Vertex v : copy.vertices()) {
    EXPECT_NEAR(t[v], target[v], 1e-9 * target[v]);
    EXPECT_NEAR(d[v], domain_area[v], 1e-9 * target[v]);
  }
}

} // namespace

} // namespace dlf_test_area_elements
