// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The paper's comparison tables on CGAL's data set (doc/paper_experiments.md):
//
// - Tables 3, 4 and 6, Figs. 17-18: DLF on the circle (default, paper and
//   literal mode) against a semi-discrete optimal transport map (ot_disk.h), all
//   from the same initial map (the library's default Tutte map): time,
//   D_area, symmetric Dirichlet, ARAP, folds, the transport cost of each map
//   from the start, and the Beltrami coefficients of ψ = φ_DLF ∘ φ_OT⁻¹;
// - Table 5: the spherical DLF (default, paper and literal mode) on the closed
//   genus-0 meshes: time, Area_total and D_area.
//
// `--check` instead runs the checks of the optimal-transport solver (the
// Hessian against finite differences of the cell areas, converged areas
// against the targets, the areas' sum against π).

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/measure.h>

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_distortion.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_sphere_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <boost/program_options.hpp>
#include <nlohmann/json.hpp>

#include "benchmark_utilities.h"
#include "ot_disk.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#ifndef DLF_DATA_DIR
#define DLF_DATA_DIR "build/data"
#endif

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace D = CGAL::Surface_mesh_parameterization::internal::dlf;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace fs = std::filesystem;
namespace po = boost::program_options;
using json = nlohmann::ordered_json;
using namespace dlf_benchmark;

typedef CGAL::Simple_cartesian<double> K;
typedef CGAL::Surface_mesh<K::Point_3> SM;
typedef boost::graph_traits<SM>::halfedge_descriptor halfedge_descriptor;
typedef boost::graph_traits<SM>::vertex_descriptor vertex_descriptor;
typedef boost::graph_traits<SM>::face_descriptor face_descriptor;
typedef SM::Property_map<vertex_descriptor, K::Point_2> UV_map;
typedef SM::Property_map<vertex_descriptor, K::Point_3> Sphere_map;
typedef SMP::Discrete_lie_flow_parameterizer_3<SM> Dlf_circle;

// ---------------------------------------------------------------------------
// Meshes
// ---------------------------------------------------------------------------

/// A mesh in index form: vertex i is `SM::Vertex_index(i)`.
struct Indexed
{
  std::vector<D::Vec3> xyz;
  std::vector<D::Face> faces;
};

static Indexed indexed(const SM& mesh)
{
  Indexed m;
  for(vertex_descriptor v : vertices(mesh)) {
    const K::Point_3& p = mesh.point(v);
    m.xyz.push_back({{ p.x(), p.y(), p.z() }});
  }
  for(face_descriptor f : faces(mesh)) {
    D::Face t{{ -1, -1, -1 }};
    int k = 0;
    for(vertex_descriptor v : vertices_around_face(halfedge(f, mesh), mesh)) if(k < 3) t[std::size_t(k++)] = int(v.idx());
    m.faces.push_back(t);
  }
  return m;
}

/// Reads `spec`; "" when it is a triangulated topological disk (one
/// component, one border, Euler characteristic 1), else why not.
static std::string load(const std::string& spec, const fs::path& dir, SM& mesh, bool disk)
{
  Mesh_spec parsed;
  std::string why;
  // A file name with a '+' of its own ("poly2x^2+y^2-0.062500.off") is a file.
  if(fs::is_regular_file(dir / spec)) parsed.file = spec;
  else if(!parse_mesh_spec(spec, parsed, why)) return why;
  const std::string path = (dir / parsed.file).string();
  try {
    if(!CGAL::IO::read_polygon_mesh(path, mesh) || faces(mesh).empty()) {
      mesh.clear();
      if(!PMP::IO::read_polygon_mesh(path, mesh)) return "cannot read " + parsed.file;
    }
  } catch(const std::exception& e) {
    return "cannot read " + parsed.file + ": " + e.what();
  }
  subdivide(mesh, parsed);
  if(!CGAL::is_triangle_mesh(mesh)) return "not a triangle mesh";
  mesh.collect_garbage();
  SM::Property_map<face_descriptor, std::size_t> cc = mesh.add_property_map<face_descriptor, std::size_t>("f:cc", 0).first;
  const std::size_t components = PMP::connected_components(mesh, cc);
  mesh.remove_property_map(cc);
  if(components != 1) return std::to_string(components) + " components";
  const long chi = long(num_vertices(mesh)) - long(num_edges(mesh)) + long(num_faces(mesh));
  std::vector<halfedge_descriptor> borders;
  PMP::extract_boundary_cycles(mesh, std::back_inserter(borders));
  if(disk && (borders.size() != 1 || chi != 1)) return "not a disk (" + std::to_string(borders.size()) + " borders)";
  if(!disk && (!borders.empty() || chi != 2)) return "not a closed genus-0 mesh";
  return "";
}

static std::vector<D::Vec2> uv_of(const SM& mesh, UV_map uv)
{
  std::vector<D::Vec2> out;
  for(vertex_descriptor v : vertices(mesh)) out.push_back({{ uv[v].x(), uv[v].y() }});
  return out;
}

/// Moves a circle-bordered map onto the unit disk: the circle through three
/// border vertices a third of the border apart (the border's vertices are
/// not evenly spread, so their mean is not the centre).
static void to_unit_disk(std::vector<D::Vec2>& uv, const std::vector<int>& border)
{
  const std::size_t n = border.size();
  const D::Vec2 &a = uv[std::size_t(border[0])], &b = uv[std::size_t(border[n / 3])], &c = uv[std::size_t(border[2 * n / 3])];
  const double bx = b[0] - a[0], by = b[1] - a[1], cx = c[0] - a[0], cy = c[1] - a[1];
  const double d = 2 * (bx * cy - by * cx);
  const double ux = (cy * (bx * bx + by * by) - by * (cx * cx + cy * cy)) / d;
  const double uy = (bx * (cx * cx + cy * cy) - cx * (bx * bx + by * by)) / d;
  const double r = std::hypot(ux, uy), ox = a[0] + ux, oy = a[1] + uy;
  for(D::Vec2& p : uv) p = {{ (p[0] - ox) / r, (p[1] - oy) / r }};
}

/// The vertex masses of the OT peer: the input area (times the face's
/// density, when one is given) lumped at vertices (a third of each incident
/// triangle), scaled to sum to π.
static std::vector<double> lumped_masses(const Indexed& m, const std::vector<double>& density = std::vector<double>())
{
  std::vector<double> nu(m.xyz.size(), 0.);
  double total = 0;
  for(std::size_t f = 0; f < m.faces.size(); ++f) {
    const D::Face& t = m.faces[f];
    const double a = (density.empty() ? 1. : density[f]) *
                     D::triangle_area_3(m.xyz[std::size_t(t[0])], m.xyz[std::size_t(t[1])], m.xyz[std::size_t(t[2])]);
    for(int k = 0; k < 3; ++k) nu[std::size_t(t[k])] += a / 3;
    total += a;
  }
  for(double& x : nu) x *= M_PI / total;
  return nu;
}

static json metrics_json(const SMP::Discrete_lie_flow_distortion& d)
{
  return json{ { "d_area", d.d_area }, { "symmetric_dirichlet", d.symmetric_dirichlet }, { "arap", d.arap },
               { "wasserstein_table1", d.wasserstein_table1 }, { "area_total", d.area_total },
               { "beltrami_mean", d.beltrami_mean }, { "beltrami_weighted_mean", d.beltrami_weighted_mean },
               { "beltrami_max", d.beltrami_max }, { "inverted_faces", d.inverted_faces },
               { "degenerate_faces", d.degenerate_faces } };
}

static json difference_json(const SMP::Discrete_lie_flow_map_difference& d)
{
  return json{ { "transport_cost", d.transport_cost }, { "beltrami_mean", d.beltrami_mean },
               { "beltrami_weighted_mean", d.beltrami_weighted_mean }, { "beltrami_max", d.beltrami_max },
               { "faces_not_compared", d.faces_not_compared } };
}

// Bins of the |μ| histograms (Figs. 17-18).
static const std::vector<double> mu_bins = { 0, 0.02, 0.05, 0.1, 0.2, 0.5, 1 };

static std::vector<std::size_t> beltrami_histogram(const std::vector<D::Vec2>& a, const std::vector<D::Vec2>& b,
                                                   const std::vector<D::Face>& faces)
{
  std::vector<std::size_t> h(mu_bins.size() + 1, 0); // last: not compared
  for(const D::Face& t : faces) {
    const double mu = D::affine_beltrami(a[std::size_t(t[0])], a[std::size_t(t[1])], a[std::size_t(t[2])],
                                         b[std::size_t(t[0])], b[std::size_t(t[1])], b[std::size_t(t[2])]);
    if(mu < 0) { ++h.back(); continue; }
    std::size_t k = 0;
    while(k + 1 < mu_bins.size() && mu >= mu_bins[k + 1]) ++k;
    ++h[k];
  }
  return h;
}

// ---------------------------------------------------------------------------
// Disk: DLF against optimal transport
// ---------------------------------------------------------------------------

/// The flows beside each peer: the default (certified) mode, the stabilised
/// paper flow and Algorithm 1 as printed (`literal`).
struct Paper_tables_mode
{
  const char* key;
  const char* label;
  SMP::Discrete_lie_flow_mode mode;
};
static const Paper_tables_mode paper_tables_modes[] = {
  { "dlf", "default", SMP::Discrete_lie_flow_mode::CERTIFIED },
  { "dlf_paper", "paper", SMP::Discrete_lie_flow_mode::PAPER },
  { "dlf_literal", "literal", SMP::Discrete_lie_flow_mode::LITERAL },
};

struct Dlf_run
{
  bool ok = false;
  std::string status;
  std::size_t iterations = 0;
  double seconds = 0;
  std::vector<D::Vec2> uv;
};

static Dlf_run run_dlf(const SM& input, halfedge_descriptor bhd, SMP::Discrete_lie_flow_mode mode,
                       const std::vector<double>& face_density = std::vector<double>())
{
  SM m = input;
  UV_map uvmap = m.add_property_map<vertex_descriptor, K::Point_2>("v:uv", K::Point_2(0, 0)).first;
  SMP::Discrete_lie_flow_options opt;
  opt.mode = mode;
  opt.face_density = face_density;
  Dlf_circle p(Dlf_circle::Initial_parameterizer(), opt);
  Dlf_run r;
  const Clock::time_point t0 = Clock::now();
  const SMP::Error_code err = SMP::parameterize(m, p, bhd, uvmap);
  r.seconds = seconds_since(t0);
  r.ok = err == SMP::OK;
  r.status = r.ok ? (p.report().converged() ? "converged" : SMP::discrete_lie_flow_stop_reason_name(p.report().stop_reason))
                  : SMP::discrete_lie_flow_error_name(p.report().status);
  r.iterations = p.report().iterations;
  if(r.ok) r.uv = uv_of(m, uvmap);
  return r;
}

/// The library's default initial map (Tutte on the circle) moved onto the
/// unit disk: the start that DLF and the OT peer share.
static bool unit_disk_start(const SM& mesh, halfedge_descriptor bhd, const std::vector<int>& border, std::vector<D::Vec2>& uv0)
{
  SM m0 = mesh;
  UV_map uv0map = m0.add_property_map<vertex_descriptor, K::Point_2>("v:uv", K::Point_2(0, 0)).first;
  Dlf_circle::Initial_parameterizer tutte;
  if(SMP::parameterize(m0, tutte, bhd, uv0map) != SMP::OK) return false;
  uv0 = uv_of(m0, uv0map);
  to_unit_disk(uv0, border);
  return true;
}

static json disk_case(const std::string& spec, const SM& mesh, double tolerance)
{
  json j;
  j["mesh"] = spec;
  j["vertices"] = num_vertices(mesh);
  j["faces"] = num_faces(mesh);
  const Indexed idx = indexed(mesh);
  const halfedge_descriptor bhd = PMP::longest_border(mesh).first;
  std::vector<int> border;
  for(halfedge_descriptor h : halfedges_around_face(bhd, mesh)) border.push_back(int(target(h, mesh).idx()));

  // The common start: the library's default initial map (Tutte on the circle).
  Clock::time_point t0 = Clock::now();
  std::vector<D::Vec2> uv0;
  if(!unit_disk_start(mesh, bhd, border, uv0)) { j["error"] = "initial map failed"; return j; }
  j["initial_seconds"] = seconds_since(t0);
  j["initial"] = metrics_json(SMP::discrete_lie_flow_distortion(idx.xyz, uv0, idx.faces));

  // Optimal transport from the start's points with the lumped areas.
  t0 = Clock::now();
  std::vector<ot::P> points(uv0.begin(), uv0.end());
  const ot::Result R = ot::solve(points, lumped_masses(idx), tolerance);
  const double ot_seconds = seconds_since(t0);
  if(R.centroid.size() != uv0.size()) { j["error"] = "optimal transport: " + R.message; return j; }
  std::vector<D::Vec2> uv_ot(R.centroid.begin(), R.centroid.end());
  j["ot"] = { { "converged", R.converged }, { "message", R.message }, { "newton_iterations", R.newton_iterations },
              { "halvings", R.halvings }, { "gradient_relative", R.gradient_relative }, { "seconds", ot_seconds },
              { "seconds_with_initial", ot_seconds + j["initial_seconds"].get<double>() },
              { "semi_discrete_w2", R.w2 }, { "gradient_history", R.gradient_history },
              { "metrics", metrics_json(SMP::discrete_lie_flow_distortion(idx.xyz, uv_ot, idx.faces)) },
              { "from_start", difference_json(SMP::discrete_lie_flow_map_difference(idx.xyz, uv0, uv_ot, idx.faces)) } };

  for(const Paper_tables_mode& mode : paper_tables_modes) {
    Dlf_run r = run_dlf(mesh, bhd, mode.mode);
    json d = { { "status", r.status }, { "iterations", r.iterations }, { "seconds", r.seconds } };
    if(r.ok) {
      to_unit_disk(r.uv, border);
      d["metrics"] = metrics_json(SMP::discrete_lie_flow_distortion(idx.xyz, r.uv, idx.faces));
      d["from_start"] = difference_json(SMP::discrete_lie_flow_map_difference(idx.xyz, uv0, r.uv, idx.faces));
      d["against_ot"] = difference_json(SMP::discrete_lie_flow_map_difference(idx.xyz, uv_ot, r.uv, idx.faces));
      d["beltrami_histogram"] = beltrami_histogram(uv_ot, r.uv, idx.faces);
    }
    j[mode.key] = d;
  }
  return j;
}

// ---------------------------------------------------------------------------
// Figs. 17-18, measure-controlled: a region scaled by a factor
// ---------------------------------------------------------------------------

/// The faces whose centroid lies in the ball around the vertices' centroid
/// of radius `fraction` times the bounding-box diagonal (the region of
/// benchmark/fig15_16.sh).
static std::vector<bool> ball_region(const Indexed& m, double fraction)
{
  D::Vec3 c{{ 0, 0, 0 }}, lo = m.xyz[0], hi = m.xyz[0];
  for(const D::Vec3& p : m.xyz)
    for(std::size_t k = 0; k < 3; ++k) {
      c[k] += p[k] / double(m.xyz.size());
      lo[k] = (std::min)(lo[k], p[k]);
      hi[k] = (std::max)(hi[k], p[k]);
    }
  const double r = fraction * std::sqrt(D::dot(D::sub(hi, lo), D::sub(hi, lo)));
  std::vector<bool> in(m.faces.size());
  for(std::size_t f = 0; f < m.faces.size(); ++f) {
    double d2 = 0;
    for(std::size_t k = 0; k < 3; ++k) {
      double x = 0;
      for(int i = 0; i < 3; ++i) x += m.xyz[std::size_t(m.faces[f][i])][k] / 3;
      d2 += (x - c[k]) * (x - c[k]);
    }
    in[f] = d2 <= r * r;
  }
  return in;
}

/// The region's share of the map's total signed area.
static double region_share(const std::vector<D::Vec2>& uv, const std::vector<D::Face>& faces, const std::vector<bool>& in)
{
  double region = 0, total = 0;
  for(std::size_t f = 0; f < faces.size(); ++f) {
    const double a = D::signed_area_2(uv[std::size_t(faces[f][0])], uv[std::size_t(faces[f][1])], uv[std::size_t(faces[f][2])]);
    total += a;
    if(in[f]) region += a;
  }
  return region / total;
}

/// Table 6's metric as printed: the plain sum over the vertices of the
/// squared distance between two maps (no area weights, no square root).
static double sum_of_squares(const std::vector<D::Vec2>& a, const std::vector<D::Vec2>& b)
{
  double s = 0;
  for(std::size_t i = 0; i < a.size(); ++i) s += (a[i][0] - b[i][0]) * (a[i][0] - b[i][0]) + (a[i][1] - b[i][1]) * (a[i][1] - b[i][1]);
  return s;
}

/// The paper's Figs. 17-18 proper: a region scaled by each factor, mapped by
/// DLF (both modes, the density on the region) and by the OT peer (the
/// density in its source masses), from the same start; the regions' shares
/// and the Beltrami coefficients of ψ = φ_DLF ∘ φ_OT⁻¹.
static json measure_case(const std::string& spec, const SM& mesh, const std::vector<double>& factors, double tolerance)
{
  json j;
  j["mesh"] = spec;
  j["faces"] = num_faces(mesh);
  const Indexed idx = indexed(mesh);
  const halfedge_descriptor bhd = PMP::longest_border(mesh).first;
  std::vector<int> border;
  for(halfedge_descriptor h : halfedges_around_face(bhd, mesh)) border.push_back(int(target(h, mesh).idx()));
  std::vector<D::Vec2> uv0;
  if(!unit_disk_start(mesh, bhd, border, uv0)) { j["error"] = "initial map failed"; return j; }
  const std::vector<bool> region = ball_region(idx, 0.15);
  j["region_faces"] = std::count(region.begin(), region.end(), true);
  j["rows"] = json::array();
  for(double factor : factors) {
    std::vector<double> rho(idx.faces.size(), 1.);
    double in = 0, all = 0;
    for(std::size_t f = 0; f < rho.size(); ++f) {
      if(region[f]) rho[f] = factor;
      const D::Face& t = idx.faces[f];
      const double a = rho[f] * D::triangle_area_3(idx.xyz[std::size_t(t[0])], idx.xyz[std::size_t(t[1])], idx.xyz[std::size_t(t[2])]);
      all += a;
      if(region[f]) in += a;
    }
    json row = { { "factor", factor }, { "prescribed_share", in / all } };
    const ot::Result R = ot::solve(std::vector<ot::P>(uv0.begin(), uv0.end()), lumped_masses(idx, rho), tolerance);
    if(R.centroid.size() != uv0.size()) { row["error"] = "optimal transport: " + R.message; j["rows"].push_back(row); continue; }
    const std::vector<D::Vec2> uv_ot(R.centroid.begin(), R.centroid.end());
    row["ot"] = { { "converged", R.converged }, { "newton_iterations", R.newton_iterations },
                  { "gradient_relative", R.gradient_relative }, { "share", region_share(uv_ot, idx.faces, region) },
                  { "folds", SMP::discrete_lie_flow_distortion(idx.xyz, uv_ot, idx.faces).inverted_faces },
                  { "sum_of_squares", sum_of_squares(uv0, uv_ot) } };
    for(const Paper_tables_mode& mode : paper_tables_modes) {
      Dlf_run r = run_dlf(mesh, bhd, mode.mode, rho);
      json d = { { "status", r.status }, { "iterations", r.iterations } };
      if(r.ok) {
        to_unit_disk(r.uv, border);
        const SMP::Discrete_lie_flow_distortion m = SMP::discrete_lie_flow_distortion(idx.xyz, r.uv, idx.faces);
        d["share"] = region_share(r.uv, idx.faces, region);
        d["sum_of_squares"] = sum_of_squares(uv0, r.uv);
        d["folds"] = m.inverted_faces + m.degenerate_faces;
        d["against_ot"] = difference_json(SMP::discrete_lie_flow_map_difference(idx.xyz, uv_ot, r.uv, idx.faces));
        d["beltrami_histogram"] = beltrami_histogram(uv_ot, r.uv, idx.faces);
      }
      row[mode.key] = d;
    }
    j["rows"].push_back(row);
  }
  return j;
}

// ---------------------------------------------------------------------------
// Sphere: Table 5
// ---------------------------------------------------------------------------

static json sphere_case(const std::string& spec, const SM& mesh)
{
  json j;
  j["mesh"] = spec;
  j["vertices"] = num_vertices(mesh);
  j["faces"] = num_faces(mesh);
  for(const Paper_tables_mode& mode : paper_tables_modes) {
    SM m = mesh;
    Sphere_map smap = m.add_property_map<vertex_descriptor, K::Point_3>("v:sphere", K::Point_3(0, 0, 0)).first;
    SMP::Discrete_lie_flow_options opt;
    opt.mode = mode.mode;
    SMP::Discrete_lie_flow_sphere_parameterizer_3<SM> p(opt);
    const Clock::time_point t0 = Clock::now();
    const SMP::Error_code err = p.parameterize(m, smap);
    json d = { { "seconds", seconds_since(t0) }, { "iterations", p.report().iterations } };
    d["status"] = err != SMP::OK ? std::string(SMP::discrete_lie_flow_error_name(err))
                : p.report().converged() ? std::string("converged")
                                         : std::string(SMP::discrete_lie_flow_stop_reason_name(p.report().stop_reason));
    if(err == SMP::OK) {
      d["metrics"] = metrics_json(SMP::discrete_lie_flow_sphere_distortion(m, smap));
      const SMP::Discrete_lie_flow_distortion init = p.report().initial_metrics;
      d["initial"] = metrics_json(init);
    }
    j[mode.key] = d;
  }
  return j;
}

// ---------------------------------------------------------------------------
// Checks of the optimal-transport solver
// ---------------------------------------------------------------------------

static int run_checks(const std::vector<std::pair<std::string, SM> >& meshes, double tolerance)
{
  int failures = 0;
  const auto expect = [&](bool ok, const std::string& what) {
    std::cout << (ok ? "  ok    " : "  FAIL  ") << what << "\n";
    if(!ok) ++failures;
  };
  // 1. The Hessian of the cell areas against central differences, at heights
  //    away from zero, on random points (some on the circle).
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(-1, 1);
  std::vector<ot::P> pts;
  while(pts.size() < 40) {
    const ot::P p{{ U(rng), U(rng) }};
    if(p[0] * p[0] + p[1] * p[1] < 1) pts.push_back(p);
  }
  for(int k = 0; k < 8; ++k) pts.push_back({{ std::cos(0.8 * k + 0.1), std::sin(0.8 * k + 0.1) }});
  std::vector<double> h(pts.size());
  for(std::size_t i = 0; i < pts.size(); ++i) h[i] = -0.5 * (pts[i][0] * pts[i][0] + pts[i][1] * pts[i][1]) + 0.01 * U(rng);
  const ot::Evaluation ev = ot::evaluate(pts, h);
  double sum = 0;
  std::size_t empty = 0;
  for(const auto& c : ev.cells) { sum += c.area; if(c.area == 0) ++empty; }
  expect(std::abs(sum - M_PI) < 1e-12, "cell areas sum to pi (" + fmt(std::abs(sum - M_PI)) + " off; " +
                                         std::to_string(empty) + " empty cells)");
  double worst = 0;
  const double eps = 1e-6;
  for(std::size_t j = 0; j < pts.size(); ++j) {
    std::vector<double> hp = h, hm = h;
    hp[j] += eps;
    hm[j] -= eps;
    const ot::Evaluation ep = ot::evaluate(pts, hp), em = ot::evaluate(pts, hm);
    for(std::size_t i = 0; i < pts.size(); ++i) {
      const double fd = (ep.cells[i].area - em.cells[i].area) / (2 * eps);
      double an = 0;
      for(const auto& e : ev.cells[i].edges) {
        const double w = e.second / std::hypot(pts[std::size_t(e.first)][0] - pts[i][0], pts[std::size_t(e.first)][1] - pts[i][1]);
        if(std::size_t(e.first) == j) an -= w;
        if(i == j) an += w;
      }
      worst = (std::max)(worst, std::abs(fd - an));
    }
  }
  expect(worst < 1e-6, "Hessian matches central differences of the areas (max error " + fmt(worst) + ")");
  // 2. Converged areas equal the targets, on random masses and on meshes.
  std::vector<double> nu(pts.size());
  double total = 0;
  for(double& x : nu) { x = 0.5 + U(rng) * U(rng) + 0.5; total += x; }
  for(double& x : nu) x *= M_PI / total;
  const ot::Result R = ot::solve(pts, nu, tolerance);
  double err = R.cell_area.size() == pts.size() ? 0 : 1;
  for(std::size_t i = 0; i < R.cell_area.size(); ++i) err = (std::max)(err, std::abs(R.cell_area[i] - nu[i]) / nu[i]);
  expect(R.converged && err < 1e-7, "random masses: converged in " + std::to_string(R.newton_iterations) +
                                      " Newton steps, max relative cell-area error " + fmt(err));
  for(const auto& named : meshes) {
    const SM& mesh = named.second;
    const Indexed idx = indexed(mesh);
    const halfedge_descriptor bhd = PMP::longest_border(mesh).first;
    std::vector<int> border;
    for(halfedge_descriptor hh : halfedges_around_face(bhd, mesh)) border.push_back(int(target(hh, mesh).idx()));
    SM m0 = mesh;
    UV_map uvmap = m0.add_property_map<vertex_descriptor, K::Point_2>("v:uv", K::Point_2(0, 0)).first;
    Dlf_circle::Initial_parameterizer tutte;
    if(SMP::parameterize(m0, tutte, bhd, uvmap) != SMP::OK) { expect(false, named.first + ": initial map"); continue; }
    std::vector<D::Vec2> uv0 = uv_of(m0, uvmap);
    to_unit_disk(uv0, border);
    const std::vector<double> masses = lumped_masses(idx);
    const ot::Result M = ot::solve(std::vector<ot::P>(uv0.begin(), uv0.end()), masses, tolerance);
    double e = M.cell_area.size() == masses.size() ? 0 : 1, s = 0;
    for(std::size_t i = 0; i < M.cell_area.size(); ++i) { e = (std::max)(e, std::abs(M.cell_area[i] - masses[i]) / masses[i]); s += M.cell_area[i]; }
    expect(M.converged && e < 1e-5 && std::abs(s - M_PI) < 1e-10,
           named.first + ": converged (" + fmt(M.gradient_relative) + " relative gradient), max relative cell-area error " + fmt(e));
  }
  std::cout << (failures ? "checks FAILED\n" : "all checks passed\n");
  return failures ? 1 : 0;
}

// ---------------------------------------------------------------------------
// Tables
// ---------------------------------------------------------------------------

static std::string sci(double x) { return fmt(x, 3); }

static void write_markdown(std::ostream& md, const json& doc)
{
  md << "Machine: load average " << doc["load_average"].get<std::string>() << " at the start (2 cores shared with other jobs: "
     << "times are indicative, ratios within a row are measured in the same run). OT tolerance: relative gradient "
     << sci(doc["ot_tolerance"].get<double>()) << ".\n\n";

  md << "### Tables 3 and 4: DLF (circle) against optimal transport, from the same Tutte start\n\n"
     << "DLF in three modes: the default (certified), the stabilised paper flow (paper) and Algorithm 1 as printed (literal).\n\n"
     << "| mesh | faces | vertices | OT Newton | OT rel. gradient | OT s | DLF s | DLF paper s | DLF literal s | OT D_area | DLF D_area | DLF paper D_area | DLF literal D_area | OT folds | DLF folds | DLF paper folds | DLF literal folds |\n"
     << "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  const auto folds = [](const json& m) { return std::to_string(m["inverted_faces"].get<std::size_t>() + m["degenerate_faces"].get<std::size_t>()); };
  const auto dval = [](const json& run, const char* key) { return run.contains("metrics") ? fmt(run["metrics"][key].get<double>(), 4) : std::string("—"); };
  for(const json& c : doc["disk"]) {
    if(c.contains("error")) { md << "| " << c["mesh"].get<std::string>() << " | " << c["error"].get<std::string>() << " |\n"; continue; }
    const json& o = c["ot"];
    md << "| " << c["mesh"].get<std::string>() << " | " << c["faces"] << " | " << c["vertices"] << " | "
       << o["newton_iterations"] << (o["converged"].get<bool>() ? "" : " (" + o["message"].get<std::string>() + ")") << " | "
       << sci(o["gradient_relative"].get<double>()) << " | " << fmt_time(o["seconds"].get<double>()) << " | ";
    for(const Paper_tables_mode& pm : paper_tables_modes) md << fmt_time(c[pm.key]["seconds"].get<double>()) << " | ";
    md << fmt(o["metrics"]["d_area"].get<double>(), 4) << " | ";
    for(const Paper_tables_mode& pm : paper_tables_modes) md << dval(c[pm.key], "d_area") << " | ";
    md << folds(o["metrics"]) << " |";
    for(const Paper_tables_mode& pm : paper_tables_modes)
      md << " " << (c[pm.key].contains("metrics") ? folds(c[pm.key]["metrics"]) : "—") << " |";
    md << "\n";
  }
  md << "\nDLF times are the whole `parameterize()` call (initial map + flow); OT times are the Newton solve "
        "after the same initial map. DLF status (iterations), default, paper, literal: ";
  for(const json& c : doc["disk"]) if(!c.contains("error")) {
    md << c["mesh"].get<std::string>();
    for(const Paper_tables_mode& pm : paper_tables_modes)
      md << " " << c[pm.key]["status"].get<std::string>() << " (" << c[pm.key]["iterations"] << ")";
    md << "; ";
  }
  md << "\n\n#### Energies (Table 4's columns, and the added metrics)\n\n"
     << "| mesh | method | D_area | SD | ARAP | Table 1 W | mean \\|μ\\| |\n|---|---|---:|---:|---:|---:|---:|\n";
  for(const json& c : doc["disk"]) {
    if(c.contains("error")) continue;
    for(const auto& name : { std::make_pair("initial", "Tutte start"), std::make_pair("ot", "OT"),
                             std::make_pair("dlf", "DLF"), std::make_pair("dlf_paper", "DLF paper"),
                             std::make_pair("dlf_literal", "DLF literal") }) {
      const json& run = std::string(name.first) == "initial" ? json{ { "metrics", c["initial"] } } : c[name.first];
      if(!run.contains("metrics")) continue;
      const json& m = run["metrics"];
      md << "| " << c["mesh"].get<std::string>() << " | " << name.second << " | " << fmt(m["d_area"].get<double>(), 4) << " | "
         << sci(m["symmetric_dirichlet"].get<double>()) << " | " << fmt(m["arap"].get<double>(), 3) << " | "
         << sci(m["wasserstein_table1"].get<double>()) << " | " << fmt(m["beltrami_mean"].get<double>(), 3) << " |\n";
    }
  }

  md << "\n### Table 6: transport cost from the start, DLF against OT\n\n"
     << "Cost: `√(Σ_i m_i |φ(v_i) − φ_0(v_i)|²)` on the unit disk, `m_i` the lumped area shares, `φ_0` the Tutte start.\n\n"
     << "| mesh | DLF | OT | difference | DLF paper | difference | DLF literal | difference | OT semi-discrete W2 | DLF − OT vertex distance |\n"
     << "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for(const json& c : doc["disk"]) {
    if(c.contains("error")) continue;
    const double o = c["ot"]["from_start"]["transport_cost"].get<double>();
    md << "| " << c["mesh"].get<std::string>();
    const auto cost_cells = [&](const json& run) {
      if(!run.contains("from_start")) { md << " | — | "; return; }
      const double x = run["from_start"]["transport_cost"].get<double>();
      md << " | " << fmt(x, 5) << " | ";
      if(&run == &c["dlf"]) md << fmt(o, 5) << " | ";
      md << fmt(100 * (x - o) / o, 2) << "%";
    };
    cost_cells(c["dlf"]);
    cost_cells(c["dlf_paper"]);
    cost_cells(c["dlf_literal"]);
    md << " | " << fmt(c["ot"]["semi_discrete_w2"].get<double>(), 5) << " | "
       << (c["dlf"].contains("against_ot") ? fmt(c["dlf"]["against_ot"]["transport_cost"].get<double>(), 5) : "—") << " |\n";
  }

  md << "\n### Figs. 17-18: Beltrami coefficient of ψ = φ_DLF ∘ φ_OT⁻¹ (per face)\n\n"
     << "| mesh | DLF mode | mean \\|μ\\| | area-weighted | max |";
  for(std::size_t k = 0; k < mu_bins.size(); ++k)
    md << " " << (k + 1 < mu_bins.size() ? "[" + fmt(mu_bins[k], 2) + ", " + fmt(mu_bins[k + 1], 2) + ")" : "≥ 1") << " |";
  md << " not compared |\n|---|---|---:|---:|---:|";
  for(std::size_t k = 0; k <= mu_bins.size(); ++k) md << "---:|";
  md << "\n";
  for(const json& c : doc["disk"]) {
    if(c.contains("error")) continue;
    for(const Paper_tables_mode& pm : paper_tables_modes) {
      const char* mode = pm.key;
      const json& run = c[mode];
      if(!run.contains("against_ot")) continue;
      const json& a = run["against_ot"];
      md << "| " << c["mesh"].get<std::string>() << " | " << pm.label << " | "
         << fmt(a["beltrami_mean"].get<double>(), 4) << " | " << fmt(a["beltrami_weighted_mean"].get<double>(), 4) << " | "
         << fmt(a["beltrami_max"].get<double>(), 3) << " |";
      const double F = c["faces"].get<double>();
      for(const json& n : run["beltrami_histogram"]) md << " " << fmt(100 * n.get<double>() / F, 1) << "% |";
      md << "\n";
    }
  }

  md << "\n### Figs. 17-18, measure-controlled: a region scaled by a factor, DLF against OT\n\n"
     << "The region: the faces whose centroid lies within 0.15 × the bounding-box diagonal of the vertices' centroid "
        "(as in `benchmark/fig15_16.sh`), its density multiplied by the factor; DLF takes the density as its targets, "
        "the OT peer in its source masses. Shares are of the map's total area; the OT share is that of the centroid "
        "triangles. |μ| of ψ = φ_DLF ∘ φ_OT⁻¹ per face.\n\n"
     << "| mesh | factor | DLF mode | prescribed share | OT share | DLF share | DLF status (iterations) | OT Newton | DLF folds | OT folds | mean \\|μ\\| | area-weighted | max |";
  for(std::size_t k = 0; k < mu_bins.size(); ++k)
    md << " " << (k + 1 < mu_bins.size() ? "[" + fmt(mu_bins[k], 2) + ", " + fmt(mu_bins[k + 1], 2) + ")" : "≥ 1") << " |";
  md << " not compared |\n|---|---:|---|---:|---:|---:|---|---:|---:|---:|---:|---:|---:|";
  for(std::size_t k = 0; k <= mu_bins.size(); ++k) md << "---:|";
  md << "\n";
  for(const json& c : doc["measure"]) {
    if(c.contains("error")) { md << "| " << c["mesh"].get<std::string>() << " | " << c["error"].get<std::string>() << " |\n"; continue; }
    const double F = c["faces"].get<double>();
    for(const json& row : c["rows"]) {
      if(row.contains("error")) {
        md << "| " << c["mesh"].get<std::string>() << " | " << fmt(row["factor"].get<double>(), 2) << " | " << row["error"].get<std::string>() << " |\n";
        continue;
      }
      const json& o = row["ot"];
      for(const Paper_tables_mode& pm : paper_tables_modes) {
      const char* mode = pm.key;
        const json& r = row[mode];
        md << "| " << c["mesh"].get<std::string>() << " | " << fmt(row["factor"].get<double>(), 2) << " | "
           << pm.label << " | " << fmt(row["prescribed_share"].get<double>(), 4) << " | "
           << fmt(o["share"].get<double>(), 4) << " | " << (r.contains("share") ? fmt(r["share"].get<double>(), 4) : "—") << " | "
           << r["status"].get<std::string>() << " (" << r["iterations"] << ") | " << o["newton_iterations"]
           << (o["converged"].get<bool>() ? "" : " (not converged)") << " | "
           << (r.contains("folds") ? std::to_string(r["folds"].get<std::size_t>()) : "—") << " | " << o["folds"] << " |";
        if(!r.contains("against_ot")) { md << "\n"; continue; }
        const json& a = r["against_ot"];
        md << " " << fmt(a["beltrami_mean"].get<double>(), 4) << " | " << fmt(a["beltrami_weighted_mean"].get<double>(), 4) << " | "
           << fmt(a["beltrami_max"].get<double>(), 3) << " |";
        for(const json& n : r["beltrami_histogram"]) md << " " << fmt(100 * n.get<double>() / F, 1) << "% |";
        md << "\n";
      }
    }
  }

  md << "\n### Table 6 as printed: the sum of squared distances from the start, per factor\n\n"
     << "`Σ_i |φ(v_i) − φ_0(v_i)|²` over the vertices (no weights, no square root; unit disk), `φ_0` the Tutte start, "
        "the region and factors of the table above. Difference: (DLF − OT) / OT.\n\n"
     << "| mesh | factor | OT | DLF | difference | DLF paper | difference | DLF literal | difference |\n"
     << "|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for(const json& c : doc["measure"]) {
    if(c.contains("error")) continue;
    for(const json& row : c["rows"]) {
      if(row.contains("error") || !row["ot"].contains("sum_of_squares")) continue;
      const double o = row["ot"]["sum_of_squares"].get<double>();
      md << "| " << c["mesh"].get<std::string>() << " | " << fmt(row["factor"].get<double>(), 2) << " | " << fmt(o, 5) << " |";
      for(const Paper_tables_mode& pm : paper_tables_modes) {
        const json& r = row[pm.key];
        if(!r.contains("sum_of_squares")) { md << " — | — |"; continue; }
        const double x = r["sum_of_squares"].get<double>();
        md << " " << fmt(x, 5) << " | " << fmt(100 * (x - o) / o, 2) << "% |";
      }
      md << "\n";
    }
  }

  md << "\n### Table 5: the spherical DLF on CGAL's closed genus-0 meshes\n\n"
     << "| mesh | faces | vertices | mode | status (iterations) | time s | Area_total | D_area | start Area_total | start D_area | folds |\n"
     << "|---|---:|---:|---|---|---:|---:|---:|---:|---:|---:|\n";
  for(const json& c : doc["sphere"]) {
    if(c.contains("error")) { md << "| " << c["mesh"].get<std::string>() << " | " << c["error"].get<std::string>() << " |\n"; continue; }
    for(const Paper_tables_mode& pm : paper_tables_modes) {
      const char* mode = pm.key;
      const json& r = c[mode];
      md << "| " << c["mesh"].get<std::string>() << " | " << c["faces"] << " | " << c["vertices"] << " | "
         << pm.label << " | " << r["status"].get<std::string>() << " ("
         << r["iterations"] << ") | " << fmt_time(r["seconds"].get<double>()) << " | ";
      if(r.contains("metrics"))
        md << fmt(r["metrics"]["area_total"].get<double>(), 4) << " | " << fmt(r["metrics"]["d_area"].get<double>(), 4) << " | "
           << fmt(r["initial"]["area_total"].get<double>(), 4) << " | " << fmt(r["initial"]["d_area"].get<double>(), 4) << " | "
           << folds(r["metrics"]) << " |\n";
      else md << "— | — | — | — | — |\n";
    }
  }
}

int main(int argc, char** argv)
{
  std::string data_dir, disk_arg, sphere_arg, measure_arg, factors_arg, json_out, md_out;
  double tolerance = 1e-8;
  po::options_description desc(
    "paper_tables: the paper's Tables 3-6 and Figs. 17-18 on CGAL's data set: DLF against a semi-discrete "
    "optimal transport map on the disk, and the spherical DLF's Area_total.\nOptions");
  desc.add_options()
    ("help", "this help")
    ("data-dir", po::value<std::string>(&data_dir)->default_value(DLF_DATA_DIR), "CGAL's data set (meshes in <dir>/meshes)")
    ("meshes", po::value<std::string>(&disk_arg)->default_value(
       "patch-23.off,patch-13.off,patch-21.off,blob.off,nefertiti.off,patch-20.off,patch-30.off,mesh_with_border.off,"
       "patch-01.off,plane.off,three_peaks.off,mushroom.off,"
       "lion-head.off,mannequin-devil.off,lion-head.off+loop1,mannequin-devil.off+loop2"), "disk meshes (NAME+loopK: K Loop subdivisions)")
    ("sphere-meshes", po::value<std::string>(&sphere_arg)->default_value(
       "armadillo.off,bear.off,bunny00.off,cow.off,homer.off,fandisk.off,camel.off,triceratops.off"), "closed genus-0 meshes")
    ("measure-meshes", po::value<std::string>(&measure_arg)->default_value("nefertiti.off,mushroom.off,lion-head.off"),
     "disk meshes of the measure-controlled Figs. 17-18 (a region scaled by each factor)")
    ("factors", po::value<std::string>(&factors_arg)->default_value("0.5,1,2,4"), "the region's density factors (Figs. 17-18)")
    ("ot-tolerance", po::value<double>(&tolerance)->default_value(tolerance), "OT stop: ‖|W(h)| − ν‖₂ ≤ tolerance · ‖ν‖₂")
    ("check", "check the OT solver (Hessian, converged areas) on random points and the disk meshes, then exit")
    ("json", po::value<std::string>(&json_out)->default_value("paper_tables.json"), "JSON output")
    ("markdown", po::value<std::string>(&md_out)->default_value("paper_tables.md"), "Markdown tables output");
  po::variables_map vm;
  const int parsed = parse_options("paper_tables", desc, argc, argv, vm);
  if(parsed >= 0) return parsed;
  const fs::path dir = mesh_directory("paper_tables", data_dir);
  if(dir.empty()) return 2;

  json doc;
  doc["load_average"] = loadavg();
  doc["ot_tolerance"] = tolerance;
  std::vector<std::pair<std::string, SM> > disks;
  for(const std::string& spec : split(disk_arg)) {
    SM mesh;
    const std::string why = load(spec, dir, mesh, true);
    if(!why.empty()) { std::cerr << "paper_tables: skipping " << spec << ": " << why << "\n"; continue; }
    disks.emplace_back(spec, std::move(mesh));
  }
  if(vm.count("check")) return run_checks(disks, tolerance);

  doc["disk"] = json::array();
  for(const auto& d : disks) {
    std::cerr << "disk " << d.first << "\n";
    doc["disk"].push_back(disk_case(d.first, d.second, tolerance));
  }
  std::vector<double> factors;
  for(const std::string& f : split(factors_arg)) {
    char* end = nullptr;
    const double x = std::strtod(f.c_str(), &end);
    if(f.empty() || *end != '\0' || !(x > 0) || !std::isfinite(x)) { std::cerr << "paper_tables: --factors: '" << f << "' is not a positive number\n"; return 2; }
    factors.push_back(x);
  }
  doc["measure"] = json::array();
  for(const std::string& spec : split(measure_arg)) {
    SM mesh;
    const std::string why = load(spec, dir, mesh, true);
    std::cerr << "measure-controlled " << spec << "\n";
    if(!why.empty()) { doc["measure"].push_back({ { "mesh", spec }, { "error", why } }); continue; }
    doc["measure"].push_back(measure_case(spec, mesh, factors, tolerance));
  }
  doc["sphere"] = json::array();
  for(const std::string& spec : split(sphere_arg)) {
    SM mesh;
    const std::string why = load(spec, dir, mesh, false);
    std::cerr << "sphere " << spec << "\n";
    if(!why.empty()) { doc["sphere"].push_back({ { "mesh", spec }, { "error", why } }); continue; }
    doc["sphere"].push_back(sphere_case(spec, mesh));
  }
  std::ofstream(json_out) << doc.dump(1) << "\n";
  std::ofstream md(md_out);
  write_markdown(md, doc);
  std::cout << "wrote " << json_out << " and " << md_out << "\n";
  return 0;
}
