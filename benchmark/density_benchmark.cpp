// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Benchmark of measure control: what a density costs. For each case (a disk
// mesh of CGAL's data set and a Euclidean ball on it), the area-preserving run
// and one run per factor of the ball's faces (density `factor` inside, 1
// outside), all with the certified flow from Tutte's map on a circle at the
// same tolerance. A cell holds the whole call's median wall time over the
// plain run's, the iterations, and the region's achieved share of the domain
// area against the prescribed one. The goals: every share within 1%
// (relative), 0 inverted faces (counted here with CGAL's exact orientation
// on the uv the call wrote), converged, and at most twice the plain run's
// time.
//
// Sections: "main" (the cases measured against the goals), "band" (the same
// cases with a transition band around the ball, its width a fraction of the
// radius) and "refined" (Loop-subdivided copies of the coarse cases). Only
// the main section is counted towards the goals.
//
// Output: a summary on stdout, --json (all numbers) and --markdown (the
// tables, written into doc/density_benchmark.md by benchmark/density.sh).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/measure.h>

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_density.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <boost/program_options.hpp>
#include <nlohmann/json.hpp>

#include "benchmark_utilities.h"

#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#ifndef DLF_DATA_DIR
#define DLF_DATA_DIR "build/data"
#endif

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace fs = std::filesystem;
namespace po = boost::program_options;
using json = nlohmann::ordered_json;
using namespace dlf_benchmark;

typedef CGAL::Simple_cartesian<double> K;
typedef CGAL::Surface_mesh<K::Point_3> SM;
typedef boost::graph_traits<SM>::face_descriptor face_descriptor;
typedef SM::Property_map<SM::Vertex_index, K::Point_2> UV_map;
typedef SM::Property_map<SM::Face_index, double> Density_map;
typedef SMP::Discrete_lie_flow_parameterizer_3<SM> Dlf;

static const double goal_share = 0.01; // relative error of a region's share
static const double goal_cost = 2;     // time over the plain run's

/// A mesh spec and a ball: "name.off[+loopK]@x,y,z,r".
struct Case
{
  std::string spec;
  K::Point_3 center;
  double radius = 0;
};

static bool parse_case(const std::string& text, Case& c, std::string& why)
{
  const std::size_t at = text.find('@');
  const std::vector<std::string> xyzr = split(at == std::string::npos ? "" : text.substr(at + 1));
  if(xyzr.size() != 4) { why = "'" + text + "': expected name.off@x,y,z,r"; return false; }
  c.spec = text.substr(0, at);
  c.center = K::Point_3(std::atof(xyzr[0].c_str()), std::atof(xyzr[1].c_str()), std::atof(xyzr[2].c_str()));
  c.radius = std::atof(xyzr[3].c_str());
  if(!(c.radius > 0)) { why = "'" + text + "': the radius must be positive"; return false; }
  return true;
}

struct Run
{
  int status = -1;
  double seconds = 0, cpu_seconds = 0;
  std::size_t iterations = 0;
  std::string stop;
  double d_area = 0, achieved = 0, prescribed = 0;
  std::size_t inverted = 0;
};

/// `repeats` calls of parameterize() from scratch; the times are medians, the
/// rest is the last call's (the flow is deterministic).
static Run run(SM& mesh, SM::Halfedge_index bhd, const std::vector<face_descriptor>& region, Density_map* density,
               double tolerance, int repeats)
{
  UV_map uv = mesh.add_property_map<SM::Vertex_index, K::Point_2>("v:bench_uv").first;
  std::vector<double> walls, cpus;
  Run r;
  for(int k = 0; k < repeats; ++k) {
    SMP::Discrete_lie_flow_options options;
    options.tolerance = tolerance;
    Dlf dlf(Dlf::Initial_parameterizer(), options);
    if(density) dlf.set_face_density(*density);
    const double c0 = cpu_now();
    const Clock::time_point t0 = Clock::now();
    SMP::parameterize(mesh, dlf, bhd, uv);
    r.status = int(dlf.report().status); // the precise code (the call returns CGAL's nearest)
    walls.push_back(seconds_since(t0));
    cpus.push_back(cpu_now() - c0);
    r.iterations = dlf.report().iterations;
    r.stop = SMP::discrete_lie_flow_stop_reason_name(dlf.report().stop_reason);
    r.d_area = dlf.report().final_d_area;
    if(r.status != SMP::OK) break;
  }
  r.seconds = median(walls);
  r.cpu_seconds = median(cpus);
  if(r.status == SMP::OK) {
    typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
    for(face_descriptor f : faces(mesh)) {
      const SM::Halfedge_index h = halfedge(f, mesh);
      const K::Point_2 &a = uv[source(h, mesh)], &b = uv[target(h, mesh)], &c = uv[target(next(h, mesh), mesh)];
      if(CGAL::orientation(Epick::Point_2(a.x(), a.y()), Epick::Point_2(b.x(), b.y()), Epick::Point_2(c.x(), c.y()))
         != CGAL::POSITIVE)
        ++r.inverted;
    }
    if(density) {
      const std::pair<double, double> share = SMP::region_area_fractions(mesh, region, uv, *density);
      r.achieved = share.first;
      r.prescribed = share.second;
    }
  }
  mesh.remove_property_map(uv);
  return r;
}

static json run_json(const Run& r, double plain_seconds, bool with_share)
{
  json j;
  j["status"] = r.status == SMP::OK ? "ok" : SMP::discrete_lie_flow_error_message(SMP::Error_code(r.status));
  j["seconds"] = r.seconds;
  j["cpu_seconds"] = r.cpu_seconds;
  j["iterations"] = r.iterations;
  j["stop_reason"] = r.stop;
  j["final_d_area"] = r.d_area;
  j["inverted_faces"] = r.inverted;
  if(with_share) {
    const double error = r.prescribed > 0 ? (r.achieved - r.prescribed) / r.prescribed : 0;
    const double cost = plain_seconds > 0 ? r.seconds / plain_seconds : 0;
    j["prescribed_share"] = r.prescribed;
    j["achieved_share"] = r.achieved;
    j["share_error"] = error;
    j["cost"] = cost;
    j["meets_share"] = r.status == SMP::OK && std::abs(error) <= goal_share && r.inverted == 0 && r.stop == "converged";
    j["meets_cost"] = cost <= goal_cost;
  }
  return j;
}

/// One case at one band width (a fraction of the radius): the plain run, then
/// every factor.
static json run_case(const Case& c, const fs::path& mesh_dir, const std::vector<double>& factors, double band,
                     double tolerance, int repeats)
{
  json j;
  j["mesh"] = c.spec;
  j["ball"] = { c.center.x(), c.center.y(), c.center.z(), c.radius };
  j["band_over_radius"] = band;
  Mesh_spec spec;
  std::string why;
  SM mesh;
  if(!parse_mesh_spec(c.spec, spec, why)) { j["error"] = why; return j; }
  try {
    if(!PMP::IO::read_polygon_mesh((mesh_dir / spec.file).string(), mesh) || faces(mesh).empty()) {
      j["error"] = "cannot read " + spec.file;
      return j;
    }
  } catch(const std::exception& e) {
    j["error"] = "cannot read " + spec.file + ": " + e.what();
    return j;
  }
  subdivide(mesh, spec);
  const SM::Halfedge_index bhd = PMP::longest_border(mesh).first;
  if(bhd == SM::null_halfedge()) { j["error"] = c.spec + " has no border"; return j; }
  const std::vector<face_descriptor> region = SMP::faces_in_ball(mesh, c.center, c.radius);
  j["faces"] = num_faces(mesh);
  j["region_faces"] = region.size();
  if(region.empty()) { j["error"] = "no face in the ball"; return j; }

  run(mesh, bhd, region, nullptr, tolerance, 1); // untimed: the first call of a process pays for warming up
  const Run plain = run(mesh, bhd, region, nullptr, tolerance, repeats);
  j["plain"] = run_json(plain, 0, false);
  Density_map rho = mesh.add_property_map<SM::Face_index, double>("f:bench_density", 1.).first;
  json runs = json::array();
  for(double factor : factors) {
    SMP::set_region_density(mesh, region, factor, rho, band * c.radius);
    json r = run_json(run(mesh, bhd, region, &rho, tolerance, repeats), plain.seconds, true);
    r["factor"] = factor;
    runs.push_back(r);
    std::cout << "  " << c.spec << " band " << band << " x" << factor << ": " << r["iterations"] << " it., "
              << fmt(r["cost"].get<double>(), 2) << "x, share " << fmt(100 * r["share_error"].get<double>(), 2) << "%"
              << std::endl;
  }
  mesh.remove_property_map(rho);
  j["runs"] = runs;
  return j;
}

static std::string cell(const json& r)
{
  const bool ok = r["meets_share"].get<bool>() && r["meets_cost"].get<bool>();
  std::string s = fmt(r["cost"].get<double>(), 2) + "× (" + std::to_string(r["iterations"].get<std::size_t>()) + ") " +
                  (r["share_error"].get<double>() >= 0 ? "+" : "") + fmt(100 * r["share_error"].get<double>(), 2) + "%";
  if(r["stop_reason"] != "converged") s += ", " + r["stop_reason"].get<std::string>();
  if(r["inverted_faces"].get<std::size_t>() > 0) s += ", " + std::to_string(r["inverted_faces"].get<std::size_t>()) + " inverted";
  return ok ? s : "**" + s + "**";
}

static void table(std::ostream& out, const json& section, const std::vector<double>& factors, bool with_band)
{
  out << "| mesh (faces; in the ball)" << (with_band ? " | band / r" : "") << " | plain: s (it.)";
  for(double f : factors) out << " | ×" << fmt_time(f);
  out << " |\n|---" << (with_band ? "|---" : "") << "|---";
  for(std::size_t k = 0; k < factors.size(); ++k) out << "|---";
  out << "|\n";
  for(const json& c : section) {
    out << "| " << c["mesh"].get<std::string>();
    if(c.contains("error")) { out << " | " << c["error"].get<std::string>() << " |\n"; continue; }
    out << " (" << c["faces"] << "; " << c["region_faces"] << ")";
    if(with_band) out << " | " << fmt_time(c["band_over_radius"].get<double>());
    out << " | " << fmt(c["plain"]["seconds"].get<double>(), 4) << " (" << c["plain"]["iterations"] << ")";
    for(const json& r : c["runs"]) out << " | " << cell(r);
    out << " |\n";
  }
}

int main(int argc, char** argv)
{
  std::string data_dir, main_arg, refined_arg, bands_arg, factors_arg, json_out, md_out;
  double tolerance = 5e-4;
  int repeats = 7;
  po::options_description desc(
    "density_benchmark: the cost of measure control (a ball's faces scaled by each factor) against the area-preserving "
    "run, certified mode, Tutte on a circle.\nA case is NAME@x,y,z,r (NAME a file in <data-dir>/meshes, "
    "optionally +loopK or +midK); cases are separated by ';'.\nOptions");
  desc.add_options()
    ("help,h", "this help")
    ("data-dir", po::value<std::string>(&data_dir)->default_value(DLF_DATA_DIR), "CGAL's data set (meshes in <dir>/meshes)")
    ("cases", po::value<std::string>(&main_arg)->default_value(
       "nefertiti.off@-0.215988,-0.081660,0.215680,1;three_peaks.off@-4.25,-7.132335,12.742857,4.5;"
       "mushroom.off@0.016,-0.016,0.232,0.3;lion-head.off@-0.076,-0.126,0.5,0.157"),
     "the main section, counted towards the goals")
    ("bands", po::value<std::string>(&bands_arg)->default_value("0.3,0.6"),
     "band widths (fractions of the radius) of the band section, run on the main cases (empty: none)")
    ("refined", po::value<std::string>(&refined_arg)->default_value(
       "nefertiti.off+loop1@-0.215988,-0.081660,0.215680,1;nefertiti.off+loop2@-0.215988,-0.081660,0.215680,1;"
       "mushroom.off+loop1@0.016,-0.016,0.232,0.3;mushroom.off+loop2@0.016,-0.016,0.232,0.3"),
     "the refined section (empty: none)")
    ("factors", po::value<std::string>(&factors_arg)->default_value("0.25,0.5,2,4,16"), "the factors")
    ("tolerance", po::value<double>(&tolerance)->default_value(5e-4), "stop when D_area - 2 <= this (every run)")
    ("repeats", po::value<int>(&repeats)->default_value(7), "calls per run; times are medians")
    ("json", po::value<std::string>(&json_out)->default_value("density_benchmark.json"), "JSON output")
    ("markdown", po::value<std::string>(&md_out)->default_value("density_benchmark.md"), "Markdown tables output");
  po::variables_map vm;
  const int status = parse_options("density_benchmark", desc, argc, argv, vm);
  if(status >= 0) return status;
  if(repeats < 1 || !(tolerance > 0)) { std::cerr << "density_benchmark: --repeats >= 1 and --tolerance > 0\n"; return 2; }
  const fs::path mesh_dir = mesh_directory("density_benchmark", data_dir);
  if(mesh_dir.empty()) return 1;

  std::vector<double> factors, bands;
  for(const std::string& s : split(factors_arg)) factors.push_back(std::atof(s.c_str()));
  for(const std::string& s : split(bands_arg)) bands.push_back(std::atof(s.c_str()));
  for(double f : factors) if(!(f > 0)) { std::cerr << "density_benchmark: factors must be positive\n"; return 2; }
  for(double b : bands) if(!(b > 0)) { std::cerr << "density_benchmark: band widths must be positive\n"; return 2; }
  std::vector<Case> main_cases, refined_cases;
  for(const auto& [arg, cases] : { std::make_pair(&main_arg, &main_cases), std::make_pair(&refined_arg, &refined_cases) })
    for(const std::string& text : split(*arg, ';')) {
      Case c;
      std::string why;
      if(!parse_case(text, c, why)) { std::cerr << "density_benchmark: " << why << "\n"; return 2; }
      cases->push_back(c);
    }

  json doc;
  doc["tolerance"] = tolerance;
  doc["repeats"] = repeats;
  doc["goals"] = { { "share_error", goal_share }, { "cost", goal_cost } };
  const char* limit = std::getenv("OMP_THREAD_LIMIT");
  doc["omp_thread_limit"] = limit ? limit : "unset";
  doc["load_before"] = loadavg();
  json main_section = json::array(), band_section = json::array(), refined_section = json::array();
  for(const Case& c : main_cases) main_section.push_back(run_case(c, mesh_dir, factors, 0, tolerance, repeats));
  for(double b : bands)
    for(const Case& c : main_cases) band_section.push_back(run_case(c, mesh_dir, factors, b, tolerance, repeats));
  for(const Case& c : refined_cases) refined_section.push_back(run_case(c, mesh_dir, factors, 0, tolerance, repeats));
  doc["load_after"] = loadavg();

  std::size_t cells = 0, share_ok = 0, cost_ok = 0;
  for(const json& c : main_section)
    if(c.contains("runs"))
      for(const json& r : c["runs"]) {
        ++cells;
        share_ok += r["meets_share"].get<bool>();
        cost_ok += r["meets_cost"].get<bool>();
      }
  doc["summary"] = { { "cells", cells }, { "meet_share", share_ok }, { "meet_cost", cost_ok } };
  doc["main"] = main_section;
  doc["band"] = band_section;
  doc["refined"] = refined_section;

  std::ofstream js(json_out);
  js << doc.dump(1) << "\n";
  std::ofstream md(md_out);
  md << "Tolerance " << tolerance << " (every run, the plain one too), median wall time of " << repeats
     << " calls, OMP_THREAD_LIMIT=" << doc["omp_thread_limit"].get<std::string>() << ", load " << doc["load_before"].get<std::string>()
     << " before and " << doc["load_after"].get<std::string>() << " after.\n\n"
     << "A cell: time over the plain run's (iterations) and the region's share error; **bold** when a goal is missed "
     << "(share within " << 100 * goal_share << "%, converged, 0 inverted faces, time ≤ " << goal_cost << "×).\n\n"
     << "### Main (counted)\n\n"
     << share_ok << " of " << cells << " cells meet the share goal, " << cost_ok << " of " << cells << " the cost goal.\n\n";
  table(md, main_section, factors, false);
  if(!band_section.empty()) {
    md << "\n### With a transition band (not counted)\n\n";
    table(md, band_section, factors, true);
  }
  if(!refined_section.empty()) {
    md << "\n### Refined copies of the coarse cases (not counted)\n\n";
    table(md, refined_section, factors, false);
  }
  std::cout << share_ok << "/" << cells << " cells meet the share goal, " << cost_ok << "/" << cells << " the cost goal\n";
  return js && md ? 0 : 1;
}
