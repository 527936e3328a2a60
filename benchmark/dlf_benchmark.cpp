// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Benchmark of the Discrete Lie Flow parameterizer against CGAL's own
// parameterizers, in one run, on the disk meshes of CGAL's data set and on
// Loop-subdivided copies of the two largest.
//
// Every method goes through CGAL::Surface_mesh_parameterization::parameterize()
// and is timed on that call alone (median of --repeats runs on fresh copies
// below --repeat-below faces, one run above). Every uv map is scored by the
// same function, discrete_lie_flow_distortion() (doc/design.md, "Metrics"), on
// the caller's triangles; the paper mode is scored on its flowing
// triangulation as well (report().domain_faces).
//
// Also: the paper's Table 2 experiment (paper mode, fixed steps against the
// adaptive one) and the per-iteration cost of the certified mode.
//
// Output: a summary on stdout, --json (all numbers) and --markdown (the
// tables, spliced into doc/benchmark.md by benchmark/run.sh).

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/subdivision_method_3.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Symmetric_barycentric_mapping_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/square_border_corners.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_distortion.h>

#include <CGAL/Surface_mesh_parameterization/ARAP_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Barycentric_mapping_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Circular_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_authalic_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Iterative_authalic_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/LSCM_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Mean_value_coordinates_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Square_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/internal/Containers_filler.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <boost/program_options.hpp>
#include <nlohmann/json.hpp>

#include "benchmark_utilities.h"

#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <streambuf>
#include <string>
#include <vector>

#ifndef DLF_DATA_DIR
#define DLF_DATA_DIR "build/data"
#endif

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace D = CGAL::Surface_mesh_parameterization::internal::dlf;
namespace fs = std::filesystem;
namespace po = boost::program_options;
using json = nlohmann::ordered_json;
using namespace dlf_benchmark;

typedef CGAL::Simple_cartesian<double> K;
typedef CGAL::Surface_mesh<K::Point_3> SM;
typedef boost::graph_traits<SM>::halfedge_descriptor halfedge_descriptor;
typedef boost::graph_traits<SM>::vertex_descriptor vertex_descriptor;
typedef SM::Property_map<SM::Vertex_index, K::Point_2> UV_map;

// DLF starts from its default initial map (Tutte, solved as the symmetric
// interior system) on the circle, or on the square with the corners of
// choose_square_border_corners() (CGAL's default corners give degenerate ears).
typedef SMP::Discrete_lie_flow_parameterizer_3<SM> Dlf_circle;
typedef SMP::Square_border_arc_length_parameterizer_3<SM> Square_border;
typedef SMP::Symmetric_barycentric_mapping_parameterizer_3<SM, Square_border> Tutte_square;
typedef SMP::Discrete_lie_flow_parameterizer_3<SM, Tutte_square> Dlf_square;

// ---------------------------------------------------------------------------
// Small utilities
// ---------------------------------------------------------------------------

/// Swallows what CGAL 5.5.1's Iterative_authalic_parameterizer_3 prints (DEBUG_L0 is hard-coded to 1).
struct Null_buffer : std::streambuf
{
  int overflow(int c) override { return traits_type::not_eof(c); }
  std::streamsize xsputn(const char*, std::streamsize n) override { return n; }
};
struct Silence_cout
{
  Null_buffer sink;
  std::streambuf* old;
  Silence_cout() : old(std::cout.rdbuf(&sink)) {}
  ~Silence_cout() { std::cout.rdbuf(old); }
};

// ---------------------------------------------------------------------------
// Methods
// ---------------------------------------------------------------------------

enum Method
{
  DLF_CERTIFIED_CIRCLE, DLF_CERTIFIED_SQUARE, DLF_PAPER_CIRCLE, DLF_PAPER_SQUARE,
  ITER_AUTHALIC_CIRCLE, DISCRETE_AUTHALIC_CIRCLE, ARAP, MVC_CIRCLE, LSCM, METHOD_COUNT
};
static const char* method_name(int m)
{
  static const char* names[] = { "dlf_certified_circle", "dlf_certified_square", "dlf_paper_circle", "dlf_paper_square",
                                 "iter_authalic_circle", "discrete_authalic_circle", "arap", "mvc_circle", "lscm" };
  return names[m];
}
static bool is_dlf(int m) { return m <= DLF_PAPER_SQUARE; }
static bool is_paper(int m) { return m == DLF_PAPER_CIRCLE || m == DLF_PAPER_SQUARE; }
static bool is_slow_cgal(int m) { return m == ITER_AUTHALIC_CIRCLE || m == ARAP; }

// ---------------------------------------------------------------------------
// Meshes
// ---------------------------------------------------------------------------

struct Mesh_case
{
  std::string name; // as in the baseline: "lion-head.off", "lion-head.off+loop1"
  SM mesh;
  halfedge_descriptor bhd;
  // Indexing of CGAL's parameterize(): the same function, on the same mesh,
  // so the indices match the VertexIndexMap the parameterizers see.
  std::vector<vertex_descriptor> vertex_of;
  std::vector<D::Vec3> xyz;
  std::vector<D::Face> faces;
  boost::optional<std::array<vertex_descriptor, 4> > square_corners;
};

static bool load_case(const std::string& spec, const fs::path& dir, Mesh_case& c, std::string& error)
{
  c.name = spec;
  Mesh_spec parsed;
  if(!parse_mesh_spec(spec, parsed, error)) return false;
  const fs::path path = dir / parsed.file;
  if(!CGAL::IO::read_polygon_mesh(path.string(), c.mesh) || faces(c.mesh).empty()) {
    error = "cannot read " + path.string();
    return false;
  }
  subdivide(c.mesh, parsed);
  c.bhd = CGAL::Polygon_mesh_processing::longest_border(c.mesh).first;
  if(c.bhd == boost::graph_traits<SM>::null_halfedge()) { error = spec + " has no border"; return false; }
  SM::Property_map<SM::Vertex_index, int> vimap = c.mesh.add_property_map<SM::Vertex_index, int>("v:bench_index", -1).first;
  SMP::internal::fill_index_map_of_cc(c.bhd, c.mesh, vimap);
  std::size_t n = 0;
  for(vertex_descriptor v : vertices(c.mesh)) if(get(vimap, v) >= 0) ++n;
  c.vertex_of.assign(n, vertex_descriptor());
  c.xyz.assign(n, D::Vec3());
  for(vertex_descriptor v : vertices(c.mesh)) {
    const int i = get(vimap, v);
    if(i < 0) continue;
    c.vertex_of[std::size_t(i)] = v;
    const K::Point_3& p = c.mesh.point(v);
    c.xyz[std::size_t(i)] = {{ p.x(), p.y(), p.z() }};
  }
  for(SM::Face_index f : faces(c.mesh)) {
    D::Face t;
    int k = 0;
    bool inside = true;
    for(vertex_descriptor v : vertices_around_face(c.mesh.halfedge(f), c.mesh)) {
      if(k < 3) t[k] = get(vimap, v);
      inside = inside && get(vimap, v) >= 0;
      ++k;
    }
    if(k == 3 && inside) c.faces.push_back(t);
  }
  c.mesh.remove_property_map(vimap);
  c.square_corners = SMP::choose_square_border_corners(c.mesh, c.bhd);
  return true;
}

// ---------------------------------------------------------------------------
// One run of one method
// ---------------------------------------------------------------------------

struct Run
{
  int status = -1;
  double seconds = 0, cpu_seconds = 0;
  std::vector<D::Vec2> uv;
  bool has_report = false;
  SMP::Discrete_lie_flow_report report;
};

static Run run_once(int method, const Mesh_case& c, const SMP::Discrete_lie_flow_options& base_options)
{
  SM m = c.mesh; // fresh copy: same vertex and halfedge indices
  UV_map uvmap = m.add_property_map<SM::Vertex_index, K::Point_2>("v:uv", K::Point_2(0, 0)).first;
  Run r;
  SMP::Discrete_lie_flow_options opt = base_options;
  if(is_paper(method)) opt.mode = SMP::Discrete_lie_flow_mode::PAPER;
  else if(is_dlf(method)) opt.mode = SMP::Discrete_lie_flow_mode::CERTIFIED;

  Clock::time_point t0;
  double c0 = 0;
  SMP::Error_code err = SMP::ERROR_WRONG_PARAMETER;
  switch(method) {
  case DLF_CERTIFIED_CIRCLE: case DLF_PAPER_CIRCLE: {
    Dlf_circle p(Dlf_circle::Initial_parameterizer(), opt);
    c0 = cpu_now();
    t0 = Clock::now();
    err = SMP::parameterize(m, p, c.bhd, uvmap);
    r.seconds = seconds_since(t0);
    r.cpu_seconds = cpu_now() - c0;
    r.report = p.report();
    r.has_report = true;
    break;
  }
  case DLF_CERTIFIED_SQUARE: case DLF_PAPER_SQUARE: {
    if(!c.square_corners) { r.status = SMP::ERROR_BORDER_TOO_SHORT; return r; }
    const auto& q = *c.square_corners;
    Dlf_square p(Tutte_square(Square_border(q[0], q[1], q[2], q[3])), opt);
    c0 = cpu_now();
    t0 = Clock::now();
    err = SMP::parameterize(m, p, c.bhd, uvmap);
    r.seconds = seconds_since(t0);
    r.cpu_seconds = cpu_now() - c0;
    r.report = p.report();
    r.has_report = true;
    break;
  }
  case ITER_AUTHALIC_CIRCLE: {
    // CGAL default: 15 iterations, circle, BiCGSTAB + ILUT. Not copyable in
    // 5.5.1, so parameterize() gets it by reference (explicit template argument).
    typedef SMP::Iterative_authalic_parameterizer_3<SM> Iterative_authalic;
    Iterative_authalic p;
    Silence_cout quiet;
    c0 = cpu_now();
    t0 = Clock::now();
    err = SMP::parameterize<SM, Iterative_authalic&>(m, p, c.bhd, uvmap);
    r.seconds = seconds_since(t0);
    r.cpu_seconds = cpu_now() - c0;
    break;
  }
  case DISCRETE_AUTHALIC_CIRCLE: {
    SMP::Discrete_authalic_parameterizer_3<SM> p;
    Silence_cout quiet;
    c0 = cpu_now();
    t0 = Clock::now();
    err = SMP::parameterize(m, p, c.bhd, uvmap);
    r.seconds = seconds_since(t0);
    r.cpu_seconds = cpu_now() - c0;
    break;
  }
  case ARAP: {
    SMP::ARAP_parameterizer_3<SM> p; // λ = 1000, MVC + circle initialisation, free border
    Silence_cout quiet;
    c0 = cpu_now();
    t0 = Clock::now();
    err = SMP::parameterize(m, p, c.bhd, uvmap);
    r.seconds = seconds_since(t0);
    r.cpu_seconds = cpu_now() - c0;
    break;
  }
  case LSCM: {
    SMP::LSCM_parameterizer_3<SM> p; // free border, two vertices pinned (CGAL's default)
    Silence_cout quiet;
    c0 = cpu_now();
    t0 = Clock::now();
    err = SMP::parameterize(m, p, c.bhd, uvmap);
    r.seconds = seconds_since(t0);
    r.cpu_seconds = cpu_now() - c0;
    break;
  }
  case MVC_CIRCLE: {
    SMP::Mean_value_coordinates_parameterizer_3<SM> p;
    Silence_cout quiet;
    c0 = cpu_now();
    t0 = Clock::now();
    err = SMP::parameterize(m, p, c.bhd, uvmap);
    r.seconds = seconds_since(t0);
    r.cpu_seconds = cpu_now() - c0;
    break;
  }
  }
  // DLF's precise code is its report's (its call returns CGAL's nearest).
  r.status = r.has_report ? int(r.report.status) : int(err);
  r.uv.resize(c.vertex_of.size());
  for(std::size_t i = 0; i < c.vertex_of.size(); ++i) {
    const K::Point_2& p = get(uvmap, c.vertex_of[i]);
    r.uv[i] = {{ p.x(), p.y() }};
  }
  return r;
}

/// Median of `repeats` runs (the run whose time is the median is kept).
static Run run_timed(int method, const Mesh_case& c, const SMP::Discrete_lie_flow_options& opt, int repeats,
                     std::vector<double>& all_seconds, std::vector<double>& all_cpu)
{
  std::vector<Run> runs;
  for(int k = 0; k < repeats; ++k) {
    runs.push_back(run_once(method, c, opt));
    all_seconds.push_back(runs.back().seconds);
    all_cpu.push_back(runs.back().cpu_seconds);
    if(runs.back().status != SMP::OK) break;
  }
  std::vector<std::size_t> order(runs.size());
  for(std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return runs[a].seconds < runs[b].seconds; });
  return std::move(runs[order[order.size() / 2]]);
}

static json metrics_json(const SMP::Discrete_lie_flow_distortion& d, std::size_t F)
{
  json j;
  j["d_area"] = d.d_area;
  j["arap"] = d.arap;
  j["symmetric_dirichlet"] = d.symmetric_dirichlet;
  j["sd_per_face"] = d.symmetric_dirichlet / double(F);
  j["log_area_mean_abs"] = d.log_area_mean_abs;
  j["log_area_max_abs"] = d.log_area_max_abs;
  j["inverted_faces"] = d.inverted_faces;
  j["degenerate_faces"] = d.degenerate_faces;
  j["folds"] = d.inverted_faces + d.degenerate_faces;
  j["min_angle_degrees"] = d.min_angle_degrees;
  j["faces_below_1_degree"] = d.faces_below_1_degree;
  return j;
}

static json run_method(int method, const Mesh_case& c, const SMP::Discrete_lie_flow_options& opt, int repeats)
{
  json j;
  std::vector<double> all, all_cpu;
  Run r = run_timed(method, c, opt, repeats, all, all_cpu);
  j["status"] = SMP::discrete_lie_flow_error_name(r.status);
  j["seconds"] = r.seconds;
  j["cpu_seconds"] = median(all_cpu);
  j["seconds_all"] = all;
  j["cpu_seconds_all"] = all_cpu;
  if(r.has_report) {
    const SMP::Discrete_lie_flow_report& R = r.report;
    j["iterations"] = R.iterations;
    j["stop_reason"] = SMP::discrete_lie_flow_stop_reason_name(R.stop_reason);
    j["message"] = R.message;
    j["seconds_initial"] = R.seconds_initial;
    j["seconds_flow"] = R.seconds_flow;
    j["seconds_assembly"] = R.seconds_assembly;
    j["seconds_solve"] = R.seconds_solve;
    j["seconds_step"] = R.seconds_step;
    j["factorizations"] = R.factorizations;
    j["symbolic_analyses"] = R.symbolic_analyses;
    j["initial_d_area"] = R.initial_d_area;
    j["report_final_d_area"] = R.final_d_area;
    j["report_caller_inverted_faces"] = R.caller_inverted_faces;
    j["report_flowing_inverted_faces"] = R.flowing_inverted_faces;
    j["edge_flips"] = R.flips;
    j["rejected_by_exact_check"] = R.rejected_by_exact_check;
  }
  if(r.status != SMP::OK) return j;
  j["caller"] = metrics_json(SMP::discrete_lie_flow_distortion(c.xyz, r.uv, c.faces), c.faces.size());
  if(r.has_report && is_paper(method)) {
    std::vector<D::Face> dom(r.report.domain_faces.begin(), r.report.domain_faces.end());
    j["flowing"] = metrics_json(SMP::discrete_lie_flow_distortion(c.xyz, r.uv, dom), dom.size());
    // The metric counts a face as degenerate when its domain triangle or its
    // 3D triangle has zero area; on the flowing triangulation a flip can join
    // three collinear 3D vertices (e.g. along a straight border), which is no
    // fold of the domain. Tell the two apart.
    std::size_t zero_domain = 0, zero_3d = 0;
    for(const D::Face& t : dom) {
      if(D::exact_orientation_2(r.uv[t[0]], r.uv[t[1]], r.uv[t[2]]) == CGAL::COLLINEAR) ++zero_domain;
      if(D::triangle_area_3(c.xyz[t[0]], c.xyz[t[1]], c.xyz[t[2]]) == 0) ++zero_3d;
    }
    j["flowing"]["degenerate_domain_faces"] = zero_domain;
    j["flowing"]["zero_area_3d_faces"] = zero_3d;
  }
  return j;
}

// ---------------------------------------------------------------------------
// Markdown tables
// ---------------------------------------------------------------------------

static std::string mesh_label(const json& m)
{
  return std::string(m["mesh"]) + " (" + std::to_string(int(m["F"])) + ")";
}

/// A cell for `method` on mesh `m`, from `get(method_json)`; handles skipped and failed runs.
static std::string cell(const json& m, const std::string& method, const std::function<std::string(const json&)>& get)
{
  if(!m["methods"].contains(method)) return "-";
  const json& r = m["methods"][method];
  if(r.contains("skipped")) return "skip";
  if(r["status"] != "ok") return "FAIL " + std::string(r["status"]);
  return get(r);
}

static void table(std::ostream& out, const json& results, const std::vector<std::string>& methods,
                  const std::function<std::string(const json&)>& get)
{
  out << "| mesh (F) |";
  for(const std::string& m : methods) out << " " << m << " |";
  out << "\n|---|";
  for(std::size_t k = 0; k < methods.size(); ++k) out << "---:|";
  out << "\n";
  for(const json& m : results) {
    out << "| " << mesh_label(m) << " |";
    for(const std::string& meth : methods) out << " " << cell(m, meth, get) << " |";
    out << "\n";
  }
  out << "\n";
}

static std::string folds_of(const json& metrics)
{
  const std::size_t inv = metrics["inverted_faces"], deg = metrics["degenerate_faces"];
  std::string s = std::to_string(inv);
  if(deg > 0) s += " (+" + std::to_string(deg) + " degen.)";
  return s;
}

// ---------------------------------------------------------------------------
// main
// ---------------------------------------------------------------------------

int main(int argc, char** argv)
{
  const std::string default_meshes =
    "patch-23.off,patch-13.off,patch-21.off,blob.off,nefertiti.off,patch-20.off,patch-30.off,mesh_with_border.off,"
    "patch-01.off,plane.off,poly2x^2+y^2-0.062500.off,cylinder.off,three_peaks.off,mushroom.off,"
    "cylinder_locally_refined.off,lion-head.off,mannequin-devil.off,"
    "lion-head.off+loop1,mannequin-devil.off+loop1,lion-head.off+loop2,mannequin-devil.off+loop2";
  std::string all_methods;
  for(int m = 0; m < METHOD_COUNT; ++m) all_methods += std::string(m ? "," : "") + method_name(m);

  std::string data_dir, meshes_arg, methods_arg, table2_arg, table2_steps_arg, json_out, md_out;
  double table2_tolerance = 0.05;
  std::size_t slow_limit = 120000, repeat_below = 50000, table2_cap = 2000;
  int repeats = 3;
  po::options_description desc(
    "dlf_benchmark: DLF (certified and paper mode, circle and square) against CGAL's parameterizers, in one run.\n"
    "Mesh names: files in <data-dir>/meshes; NAME+loopK / NAME+midK means K steps of Loop / midpoint subdivision.\nOptions");
  desc.add_options()
    ("help,h", "this help")
    ("data-dir", po::value<std::string>(&data_dir)->default_value(DLF_DATA_DIR), "CGAL's data set (meshes in <dir>/meshes)")
    ("meshes", po::value<std::string>(&meshes_arg)->default_value(default_meshes), "comma-separated mesh list")
    ("methods", po::value<std::string>(&methods_arg)->default_value(all_methods), "comma-separated method list")
    ("slow-face-limit", po::value<std::size_t>(&slow_limit)->default_value(slow_limit),
     "skip iter_authalic_circle and arap above this face count (both take > 300 s at 267K faces)")
    ("repeats", po::value<int>(&repeats)->default_value(repeats), "runs per (mesh, method) below --repeat-below faces (median kept)")
    ("repeat-below", po::value<std::size_t>(&repeat_below)->default_value(repeat_below), "face count from which a single run is made")
    ("table2", po::value<std::string>(&table2_arg)->default_value("nefertiti.off,three_peaks.off,mushroom.off,lion-head.off"),
     "meshes of the fixed-step experiment (paper's Table 2); empty: skip it")
    ("table2-steps", po::value<std::string>(&table2_steps_arg)->default_value("1,0.1,0.01,0.001,0.0001"),
     "fixed steps of the fixed-step experiment (the adaptive step is always run too)")
    ("table2-cap", po::value<std::size_t>(&table2_cap)->default_value(table2_cap), "iteration cap of the fixed-step experiment")
    ("table2-tolerance", po::value<double>(&table2_tolerance)->default_value(table2_tolerance),
     "the fixed-step experiment counts iterations until D_area - 2 <= this, on the flowing triangulation")
    ("json", po::value<std::string>(&json_out)->default_value("benchmark.json"), "JSON output")
    ("markdown", po::value<std::string>(&md_out)->default_value("benchmark_tables.md"), "Markdown tables output");
  po::variables_map vm;
  const int status = parse_options("dlf_benchmark", desc, argc, argv, vm);
  if(status >= 0) return status;

  std::vector<int> methods;
  for(const std::string& s : split(methods_arg)) {
    int found = -1;
    for(int m = 0; m < METHOD_COUNT; ++m) if(s == method_name(m)) found = m;
    if(found < 0) { std::cerr << "dlf_benchmark: unknown method " << s << " (known: " << all_methods << ")\n"; return 2; }
    methods.push_back(found);
  }
  const fs::path mesh_dir = mesh_directory("dlf_benchmark", data_dir);
  if(mesh_dir.empty()) return 1;
  const fs::path json_path = fs::absolute(json_out), md_path = fs::absolute(md_out);

  // Run every CGAL call from a scratch directory: Iterative_authalic_parameterizer_3
  // (CGAL 5.5.1) writes ./last_solve.off on every iteration.
  char tmpl[] = "/tmp/dlf_benchmark_XXXXXX";
  if(!mkdtemp(tmpl)) { std::cerr << "dlf_benchmark: cannot create a scratch directory\n"; return 1; }
  const fs::path scratch(tmpl);
  const fs::path start_dir = fs::current_path();
  fs::current_path(scratch);

  json doc;
  doc["command"] = [&] { std::string s; for(int i = 0; i < argc; ++i) s += (i ? " " : "") + std::string(argv[i]); return s; }();
  doc["settings"] = { { "slow_face_limit", slow_limit }, { "repeats", repeats }, { "repeat_below", repeat_below },
                      { "table2_cap", table2_cap }, { "table2_tolerance", table2_tolerance }, { "timing", "wall time of parameterize(), median of repeats below repeat_below faces" },
#ifdef CGAL_DLF_USE_CHOLMOD
                      { "dlf_solver", "CHOLMOD supernodal LLT" },
#else
                      { "dlf_solver", "Eigen SimplicialLDLT" },
#endif
                      { "cgal_version", CGAL_VERSION_STR } };
  for(const char* var : { "OMP_THREAD_LIMIT", "OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS" })
    doc["settings"][var] = std::getenv(var) ? std::getenv(var) : "unset";
  doc["loadavg_start"] = loadavg();
  const Clock::time_point t_all = Clock::now();

  SMP::Discrete_lie_flow_options defaults; // the library's defaults
  json results = json::array();
  for(const std::string& spec : split(meshes_arg)) {
    Mesh_case c;
    std::string error;
    const Clock::time_point tl = Clock::now();
    if(!load_case(spec, mesh_dir, c, error)) { std::cerr << "dlf_benchmark: " << error << "\n"; return 1; }
    const std::size_t F = c.faces.size();
    json m;
    m["mesh"] = spec;
    m["V"] = c.xyz.size();
    m["F"] = F;
    m["load_seconds"] = seconds_since(tl);
    m["methods"] = json::object();
    const int reps = F < repeat_below ? repeats : 1;
    std::cerr << "== " << spec << " (V " << c.xyz.size() << ", F " << F << ", " << reps << " run" << (reps > 1 ? "s" : "") << ")\n";
    for(int meth : methods) {
      json r;
      if(is_slow_cgal(meth) && F > slow_limit) {
        r["skipped"] = "F > " + std::to_string(slow_limit) + " (over 300 s at 267K faces in the baseline)";
      } else {
        r = run_method(meth, c, defaults, reps);
      }
      std::cerr << "  " << std::left << std::setw(26) << method_name(meth) << std::right;
      if(r.contains("skipped")) std::cerr << "skipped (" << std::string(r["skipped"]) << ")\n";
      else {
        std::cerr << std::string(r["status"]) << "  " << fmt_time(r["seconds"]) << " s (cpu " << fmt_time(r["cpu_seconds"]) << ")";
        if(r.contains("iterations")) std::cerr << "  it " << r["iterations"] << " (" << std::string(r["stop_reason"]) << ")";
        if(r.contains("caller")) std::cerr << "  d_area " << fmt(r["caller"]["d_area"], 4) << "  folds " << r["caller"]["folds"];
        if(r.contains("flowing")) std::cerr << "  flowing d_area " << fmt(r["flowing"]["d_area"], 4) << " inv " << r["flowing"]["inverted_faces"] << " flat3d " << r["flowing"]["zero_area_3d_faces"];
        std::cerr << "\n";
      }
      m["methods"][method_name(meth)] = r;
    }
    // Ratios against CGAL's iterative authalic (same run).
    const json& M = m["methods"];
    for(const char* dlf : { "dlf_certified_circle", "dlf_certified_square" }) {
      if(M.contains(dlf) && M.contains("iter_authalic_circle") && !M["iter_authalic_circle"].contains("skipped") &&
         M[dlf].contains("seconds") && M["iter_authalic_circle"]["status"] == "ok" && M[dlf]["status"] == "ok")
      {
        m["ratio_" + std::string(dlf) + "_over_iter_authalic"] = double(M[dlf]["seconds"]) / double(M["iter_authalic_circle"]["seconds"]);
        m["cpu_ratio_" + std::string(dlf) + "_over_iter_authalic"] =
          double(M[dlf]["cpu_seconds"]) / double(M["iter_authalic_circle"]["cpu_seconds"]);
      }
    }
    results.push_back(m);
    // Keep a partial JSON on disk as we go.
    doc["meshes"] = results;
    std::ofstream(json_path) << std::setw(1) << doc << "\n";
  }

  // --- The paper's Table 2: fixed steps against the adaptive step (paper mode, circle).
  json table2 = json::array();
  std::vector<double> steps;
  std::vector<std::string> step_keys;
  for(const std::string& s : split(table2_steps_arg)) { steps.push_back(std::atof(s.c_str())); step_keys.push_back(s); }
  steps.push_back(0.);
  step_keys.push_back("adaptive");
  for(const std::string& spec : split(table2_arg)) {
    Mesh_case c;
    std::string error;
    if(!load_case(spec, mesh_dir, c, error)) { std::cerr << "dlf_benchmark: " << error << "\n"; return 1; }
    json row;
    row["mesh"] = spec;
    row["F"] = c.faces.size();
    std::cerr << "== Table 2: " << spec << "\n";
    for(std::size_t k = 0; k < steps.size(); ++k) {
      SMP::Discrete_lie_flow_options opt;
      opt.fixed_step = steps[k];
      opt.max_iterations = table2_cap;
      opt.tolerance = table2_tolerance;
      opt.plateau_tolerance = 0; // run to convergence, collapse or the cap, as the paper does
      // The stall detector (same limiting triangle while λ < 1e-3) would stop
      // any fixed step below 1e-3 after stall_window iterations: off for
      // fixed steps, so that "stalled" there means a step that would fold.
      if(steps[k] > 0) opt.stall_window = table2_cap + 1;
      json r = run_method(DLF_PAPER_CIRCLE, c, opt, 1);
      const std::string& key = step_keys[k];
      row["steps"][key] = r;
      std::cerr << "  step " << std::setw(8) << key << "  " << std::string(r["status"]) << "  it " << r["iterations"]
                << " (" << std::string(r["stop_reason"]) << ")  " << fmt_time(r["seconds"]) << " s";
      if(r.contains("flowing")) std::cerr << "  flowing d_area " << fmt(r["flowing"]["d_area"], 4);
      std::cerr << "\n";
    }
    table2.push_back(row);
  }
  doc["meshes"] = results;
  doc["table2"] = table2;
  doc["total_seconds"] = seconds_since(t_all);
  doc["loadavg_end"] = loadavg();
  fs::current_path(start_dir);
  std::error_code ec;
  fs::remove_all(scratch, ec);
  {
    std::ofstream out(json_path);
    out << std::setw(1) << doc << "\n";
    if(!out) { std::cerr << "dlf_benchmark: cannot write " << json_path << "\n"; return 1; }
  }

  // --- Markdown
  std::ostringstream md;
  std::vector<std::string> mnames;
  for(int meth : methods) mnames.push_back(method_name(meth));
  auto has = [&](const std::string& s) { return std::find(mnames.begin(), mnames.end(), s) != mnames.end(); };

  md << "Generated by `" << std::string(doc["command"]) << "` in " << fmt(doc["total_seconds"], 0) << " s; "
     << "load average " << std::string(doc["loadavg_start"]) << " at the start, " << std::string(doc["loadavg_end"]) << " at the end. "
     << "DLF linear solver: " << std::string(doc["settings"]["dlf_solver"]) << "; OMP_THREAD_LIMIT="
     << std::string(doc["settings"]["OMP_THREAD_LIMIT"]) << ", OMP_NUM_THREADS=" << std::string(doc["settings"]["OMP_NUM_THREADS"]) << ", OPENBLAS_NUM_THREADS=" << std::string(doc["settings"]["OPENBLAS_NUM_THREADS"])
     << ". CGAL " << CGAL_VERSION_STR << ".\n\n";

  if(has("dlf_certified_circle")) {
    md << "#### Headline: DLF certified (default settings) against CGAL's iterative authalic (circle, 15 iterations)\n\n"
       << "Time is the wall time of `parameterize()` (DLF: initial map + flow). "
          "\"folds\" = inverted (+ degenerate) triangles of the caller's connectivity, exact predicate. "
          "ratio = DLF certified wall time / iterative authalic wall time, same run (the target is ≤ 0.2 from 10K faces); "
          "cpu ratio = the same with the CPU time of the process, less sensitive to the machine's other jobs.\n\n"
       << "| mesh (F) | DLF circle s | it | d_area | folds | DLF square s | it | d_area | folds | iter. authalic s | d_area | folds "
          "| ratio circle | ratio square | cpu ratio circle | cpu ratio square |\n"
       << "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for(const json& m : results) {
      md << "| " << mesh_label(m) << " |";
      for(const char* meth : { "dlf_certified_circle", "dlf_certified_square" }) {
        md << " " << cell(m, meth, [](const json& r) { return fmt_time(r["seconds"]); }) << " |"
           << " " << cell(m, meth, [](const json& r) { return std::to_string(int(r["iterations"])); }) << " |"
           << " " << cell(m, meth, [](const json& r) { return fmt(r["caller"]["d_area"], 4); }) << " |"
           << " " << cell(m, meth, [](const json& r) { return folds_of(r["caller"]); }) << " |";
      }
      md << " " << cell(m, "iter_authalic_circle", [](const json& r) { return fmt_time(r["seconds"]); }) << " |"
         << " " << cell(m, "iter_authalic_circle", [](const json& r) { return fmt(r["caller"]["d_area"], 4); }) << " |"
         << " " << cell(m, "iter_authalic_circle", [](const json& r) { return folds_of(r["caller"]); }) << " |";
      for(const char* k : { "ratio_dlf_certified_circle_over_iter_authalic", "ratio_dlf_certified_square_over_iter_authalic",
                            "cpu_ratio_dlf_certified_circle_over_iter_authalic", "cpu_ratio_dlf_certified_square_over_iter_authalic" })
        md << " " << (m.contains(k) ? fmt(m[k], 3) : std::string("-")) << " |";
      md << "\n";
    }
    md << "\n";
  }

  md << "#### Wall time of parameterize() in seconds\n\n";
  table(md, results, mnames, [](const json& r) { return fmt_time(r["seconds"]); });
  md << "#### CPU time of parameterize() in seconds (process, all threads)\n\n";
  table(md, results, mnames, [](const json& r) { return fmt_time(r["cpu_seconds"]); });
  md << "#### D_area on the caller's connectivity (optimum 2)\n\n";
  table(md, results, mnames, [](const json& r) { return fmt(r["caller"]["d_area"], 4); });
  md << "#### Inverted triangles on the caller's connectivity (+ degenerate)\n\n";
  table(md, results, mnames, [](const json& r) { return folds_of(r["caller"]); });
  md << "#### ARAP energy, on the caller's connectivity\n\n";
  table(md, results, mnames, [](const json& r) { return fmt(r["caller"]["arap"], 3); });
  md << "#### Symmetric Dirichlet / F (optimum 4), on the caller's connectivity\n\n";
  table(md, results, mnames, [](const json& r) { return fmt(r["caller"]["sd_per_face"], 3); });
  md << "#### Mean |log(area ratio)|, on the caller's connectivity\n\n";
  table(md, results, mnames, [](const json& r) { return fmt(r["caller"]["log_area_mean_abs"], 3); });
  md << "#### Minimum angle (degrees) / faces under 1°, on the caller's connectivity\n\n";
  table(md, results, mnames, [](const json& r) {
    return fmt(r["caller"]["min_angle_degrees"], 2) + " / " + std::to_string(std::size_t(r["caller"]["faces_below_1_degree"]));
  });

  std::vector<std::string> dlf_names;
  for(const std::string& s : mnames) if(s.rfind("dlf_", 0) == 0) dlf_names.push_back(s);
  if(!dlf_names.empty()) {
    md << "#### DLF iterations (stop reason)\n\n";
    table(md, results, dlf_names, [](const json& r) {
      return std::to_string(int(r["iterations"])) + " (" + std::string(r["stop_reason"]) + ")";
    });
  }
  std::vector<std::string> paper_names;
  for(const std::string& s : mnames) if(s.rfind("dlf_paper", 0) == 0) paper_names.push_back(s);
  if(!paper_names.empty()) {
    md << "#### Paper mode on its flowing triangulation: D_area / inverted triangles / edge flips\n\n"
       << "\"+k flat 3D\": k flowing triangles join three collinear surface vertices (a flip across a straight "
          "border); their domain triangles are not degenerate, the metric leaves them out of its sums.\n\n";
    table(md, results, paper_names, [](const json& r) {
      const json& f = r["flowing"];
      std::string s = fmt(f["d_area"], 4) + " / " + std::to_string(std::size_t(f["inverted_faces"]));
      if(std::size_t(f["degenerate_domain_faces"]) > 0) s += " (+" + std::to_string(std::size_t(f["degenerate_domain_faces"])) + " degen.)";
      if(std::size_t(f["zero_area_3d_faces"]) > 0) s += " (+" + std::to_string(std::size_t(f["zero_area_3d_faces"])) + " flat 3D)";
      return s + " / " + std::to_string(std::size_t(r["edge_flips"]));
    });
  }

  // Per-iteration cost of the certified mode.
  if(has("dlf_certified_circle")) {
    md << "#### Certified mode (circle): per-iteration cost\n\n"
       << "seconds_flow / iterations, and its split (assembly of the preconditioner, factorisation + solves, "
          "step search + exact certification); \"init\" is the initial map (Tutte, the library's default start), not part of the flow.\n\n"
       << "| mesh (F) | it | init s | flow s | flow s / it | assembly / it | solve / it | step / it | µs / it / face |\n"
       << "|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    std::vector<std::pair<double, double> > pts; // (log F, log s/it) for F ≥ 10K
    for(const json& m : results) {
      if(!m["methods"].contains("dlf_certified_circle")) continue;
      const json& r = m["methods"]["dlf_certified_circle"];
      if(r.contains("skipped") || r["status"] != "ok" || int(r["iterations"]) == 0) continue;
      const double it = r["iterations"], F = m["F"];
      const double per = double(r["seconds_flow"]) / it;
      md << "| " << mesh_label(m) << " | " << int(it) << " | " << fmt_time(r["seconds_initial"]) << " | "
         << fmt_time(r["seconds_flow"]) << " | " << fmt_time(per) << " | " << fmt_time(double(r["seconds_assembly"]) / it)
         << " | " << fmt_time(double(r["seconds_solve"]) / it) << " | " << fmt_time(double(r["seconds_step"]) / it)
         << " | " << fmt(per / F * 1e6, 2) << " |\n";
      if(F >= 10000) pts.push_back({ std::log(F), std::log(per) });
    }
    if(pts.size() >= 2) {
      double mx = 0, my = 0;
      for(auto& p : pts) { mx += p.first; my += p.second; }
      mx /= double(pts.size()); my /= double(pts.size());
      double sxy = 0, sxx = 0;
      for(auto& p : pts) { sxy += (p.first - mx) * (p.second - my); sxx += (p.first - mx) * (p.first - mx); }
      doc["certified_per_iteration_exponent"] = sxy / sxx;
      md << "\nLeast-squares fit over the meshes with F ≥ 10K: flow seconds per iteration ∝ F^" << fmt(sxy / sxx, 2) << ".\n";
    }
    md << "\n";
  }

  if(!table2.empty()) {
    md << "#### The paper's Table 2: paper mode (circle), fixed steps against the adaptive step\n\n"
       << "Iterations to D_area ≤ " << fmt(2 + table2_tolerance, 2) << " on the flowing triangulation; "
       << "\"c@k\" = collapsed at iteration k (the fixed step would fold a flowing triangle: stop reason `stalled`); "
       << "\">" << table2_cap << "\" = iteration cap; \"stalled@k\" = the adaptive flow's stall detector stopped it "
       << "after k iterations; plateau detection off, stall detection off for the fixed steps. In brackets: the best D_area reached, then the seconds.\n\n| mesh (F) |";
    for(const std::string& key : step_keys) md << " " << key << " |";
    md << "\n|---|";
    for(std::size_t k = 0; k < step_keys.size(); ++k) md << "---:|";
    md << "\n";
    for(const json& row : table2) {
      md << "| " << std::string(row["mesh"]) << " (" << std::size_t(row["F"]) << ") |";
      for(const std::string& key : step_keys) {
        if(!row["steps"].contains(key)) { md << " - |"; continue; }
        const json& r = row["steps"][key];
        std::string s;
        const std::string why = r.contains("stop_reason") ? std::string(r["stop_reason"]) : std::string("?");
        const int it = r.contains("iterations") ? int(r["iterations"]) : 0;
        if(r["status"] == "ERROR_FLOW_STALLED") s = "c@1"; // the very first step would fold
        else if(r["status"] != "ok") s = "FAIL " + std::string(r["status"]);
        else if(why == "converged") s = std::to_string(it);
        else if(why == "stalled" && key != "adaptive") s = "c@" + std::to_string(it + 1);
        else if(why == "iteration_cap") s = ">" + std::to_string(it);
        else s = why + "@" + std::to_string(it);
        if(r.contains("flowing")) s += " [" + fmt(r["flowing"]["d_area"], 3) + ", " + fmt_time(r["seconds"]) + " s]";
        md << " " << s << " |";
      }
      md << "\n";
    }
    md << "\n";
  }

  {
    std::ofstream out(md_path);
    out << md.str();
    if(!out) { std::cerr << "dlf_benchmark: cannot write " << md_path << "\n"; return 1; }
  }
  // Keep the fit in the JSON too.
  std::ofstream(json_path) << std::setw(1) << doc << "\n";
  std::cout << md.str();
  return 0;
}
