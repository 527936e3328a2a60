// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// `dlf sphere`: map a closed genus-0 mesh onto the unit sphere; write the
// sphere points in input vertex order with the input faces (all outputs or
// none), and the JSON report of doc/design.md.

#include "arguments.h"
#include "cli_error.h"
#include "commands.h"
#include "density_input.h"
#include "disk_pictures.h"
#include "metrics.h"
#include "mesh_input.h"
#include "output_files.h"
#include "progress.h"
#include "sphere_outcome.h"
#include "verdict.h"
#include "svg_common.h"
#include "svg_plots.h"
#include "svg_sphere.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_distortion.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_sphere_3.h>

#include <boost/program_options.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace dlf_cli {

namespace {

namespace po = boost::program_options;
namespace SMP = CGAL::Surface_mesh_parameterization;
using json = nlohmann::ordered_json;
typedef CGAL::Simple_cartesian<double> Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;

const char* sphere_help =
  "Usage: dlf sphere INPUT [-o OUT.obj] [--report R.json] [--svg VIEW.svg] [options]\n"
  "\n"
  "Maps a closed genus-0 triangle mesh onto the unit sphere, area-preserving,\n"
  "every triangle positively oriented (exact predicate). OUT.obj holds the\n"
  "sphere points as 'v' lines in input vertex order and the input faces.\n"
  "\n"
  "Examples:\n"
  "  dlf sphere build/data/meshes/cow.off -o cow_sphere.obj --report cow.json\n"
  "  dlf sphere bunny.off --tolerance 1e-3 --verbose\n"
  "  dlf sphere cow.off --svg cow_sphere.svg --plot-convergence cow_conv.svg\n"
  "      the sphere seen from +z and -z, coloured by area ratio; the convergence plot\n"
  "  dlf sphere sphere.off --roi-ball 0 0 1 0.8 --factor 4 --report roi.json\n"
  "      measure control: the faces whose centroid lies in the ball get 4 times their share\n"
  "  dlf sphere cow.off --mode paper --report paper.json --domain-mesh flipped.obj\n"
  "      the paper's flow (edge flips; may fold the input triangles) and its flipped triangulation\n"
  "\n"
  "Progress: one line per iteration (iteration, step, residual, d_area, elapsed), rewritten in\n"
  "place when stdout is a terminal, plain lines otherwise; -q silences it, -v adds details.\n";

// The options of `dlf sphere`, bound to the settings they fill.
void add_sphere_options(po::options_description& visible, Sphere_settings& s)
{
  visible.add_options()
    ("help,h", "this help")
    ("output,o", po::value<std::string>(&s.output)->value_name("OUT.obj"), "OBJ with the sphere points")
    ("report", po::value<std::string>(&s.report)->value_name("R.json"), "JSON report")
    ("csv", po::value<std::string>(&s.csv)->value_name("R.csv"),
     "the report as CSV: a header and one row, the JSON report's keys flattened (final.d_area, seconds.flow)")
    ("svg", po::value<std::string>(&s.svg)->value_name("VIEW.svg"),
     "draw the sphere from +z and from -z (orthographic), triangles coloured by area ratio (--svg-colour), "
     "the regions of interest shaded");
  add_svg_options(visible, s.svg_options);
  visible.add_options()
    ("plot-convergence", po::value<std::string>(&s.convergence_svg)->value_name("PLOT.svg"),
     "plot d_area - 2 and the area residual per iteration (log scale)")
    ("plot-histogram", po::value<std::string>(&s.histogram_svg)->value_name("PLOT.svg"),
     "histogram of the per-face log area ratios of the result")
    ("tolerance", po::value<double>(&s.options.tolerance), "stop when d_area - 2 <= this (default 0.01) ...")
    ("log-area-tolerance", po::value<double>(&s.options.sphere.log_area_tolerance),
     "... and the mean |log area ratio| <= this (default 0.02; 0: d_area alone decides)")
    ("share-tolerance", po::value<double>(&s.options.certified.share_tolerance),
     "... and, with a density, every region of it within this of its share of the sphere, relative "
     "(default 0.005; 0: no such test)")
    ("max-iterations", po::value<std::size_t>(&s.options.max_iterations), "iteration cap (default 500)")
    ("mu", po::value<double>(&s.options.mu), "fraction of the critical step, in (0, 1) (default 0.8)")
    ("history", "per-iteration history in the report")
    ("mode", po::value<std::string>(&s.mode)->value_name("M")->default_value("certified"),
     "certified: never folds the input triangles; paper: the paper's flow with edge flips, stabilised "
     "(plateau and stall tests, best iterate); literal: Algorithm 1 as printed (step mu * min critical step, "
     "stop when ||h_M - h_Omega||^2 < --threshold; a collapse ends the run)")
    ("coarse-to-fine-faces", po::value<std::size_t>(&s.options.sphere.coarse_to_fine_faces)->value_name("N")
       ->default_value(s.options.sphere.coarse_to_fine_faces),
     "certified mode, Tutte or mean-value start: a mesh of N faces or more is mapped coarse to fine (coarser "
     "meshes made by collapses mapped first, their map carried down; 0: never, the default)")
    ("threads", po::value<int>(&s.options.sphere.threads)->value_name("N"),
     "threads of the certified flow's vertex sweeps on meshes of 50,000 vertices or more "
     "(default 0: the hardware threads, at most 8); the result is the same whatever the number")
    ("fixed-step", po::value<double>(&s.options.fixed_step)->value_name("X"),
     "a fixed step X > 0 instead of the adaptive one; literal mode: a step that folds the flowing mesh "
     "ends the run as collapsed, other modes: as stalled")
    ("threshold", po::value<double>(&s.options.paper.residual_threshold)->value_name("X")
       ->default_value(s.options.paper.residual_threshold),
     "literal mode: stop when ||h_M - h_Omega||^2 < X, vertex area elements in units of their mean")
    ("start", po::value<std::string>(&s.start)->value_name("S")->default_value("tutte"),
     "the initial map: tutte (Tutte's embedding of the punctured mesh, lifted stereographically) or "
     "conformal (the cotangent-harmonic map instead, the paper's kind of start; refused if it folds) or "
     "mean-value (Tutte's embedding with Floater's mean-value weights: bijective, keeps straight edges straight)")
    ("init-map", po::value<std::string>(&s.init_map_file)->value_name("SPHERE.obj"),
     "start from this map instead: a mesh with the input's faces, its points scaled onto the unit sphere "
     "(e.g. an earlier dlf sphere output); refused if a face folds")
    ("domain-mesh", po::value<std::string>(&s.domain_mesh)->value_name("FLOW.obj"),
     "write the sphere points with the final flowing triangulation (the input's in certified mode)")
    ("literal-targets", "paper mode: lump the target areas once on the input triangles (Algorithm 1 read literally)")
    ("no-flips", "paper mode: no Delaunay edge flips")
    ("density", po::value<std::string>(&s.density.density_file)->value_name("FILE"),
     "measure control: a density > 0 per face, or per vertex, as for dlf disk")
    ("roi", po::value<std::vector<std::string> >()->composing()->value_name("FILE"),
     "a region of interest: a CGAL selection file; needs --factor")
    ("roi-ball", po::value<std::vector<std::string> >()->composing()->value_name("X Y Z R"),
     "a region of interest: the faces whose centroid lies in this ball; needs --factor")
    ("factor", po::value<std::vector<double> >()->composing()->value_name("F"),
     "density of the k-th region (> 0); overlapping regions multiply")
    ("band", po::value<double>(&s.density.band)->value_name("W"),
     "width (3D length) of a transition from each region's factor to 1 around it")
    ("quiet,q", "print nothing on success (no progress, no summary)")
    ("verbose,v", "progress with the step's details, never overwritten");
}

// The checks of the parsed command line, in the order of their messages.
void check_sphere_arguments(const po::variables_map& vm, const std::vector<po::option>& ordered, Sphere_settings& s)
{
  if(!(s.options.tolerance >= 0)) throw Cli_error("--tolerance must be >= 0");
  if(!(s.options.sphere.log_area_tolerance >= 0)) throw Cli_error("--log-area-tolerance must be >= 0");
  if(s.options.sphere.threads < 0) throw Cli_error("--threads must be 0 (automatic) or positive");
  if(!(s.options.certified.share_tolerance >= 0) || !std::isfinite(s.options.certified.share_tolerance))
    throw Cli_error("--share-tolerance must be a number >= 0");
  if(vm.count("mu") && !(s.options.mu > 0 && s.options.mu < 1)) throw Cli_error("--mu must be in (0, 1)");
  if(s.mode != "certified" && s.mode != "paper" && s.mode != "literal")
    throw Cli_error("invalid value '" + s.mode + "' for --mode (expected certified, paper or literal)");
  check_mode_options(vm, s.mode, s.options);
  if(s.start != "tutte" && s.start != "conformal" && s.start != "mean-value")
    throw Cli_error("invalid value '" + s.start + "' for --start (expected tutte, conformal or mean-value)");
  if(!s.init_map_file.empty()) {
    if(!vm["start"].defaulted()) throw Cli_error("--init-map and --start exclude each other");
    s.start = "given";
  }
  set_verbosity(vm, s.verbosity);
  read_region_arguments(vm, ordered, s.density);
  check_svg_options(vm, !s.svg.empty(), s.density.has_density(), s.svg_options);
}

// The flow's options from the checked settings.
void set_sphere_flow_options(const po::variables_map& vm, Sphere_settings& s)
{
  s.options.sphere.start = s.start == "conformal"    ? SMP::Discrete_lie_flow_sphere_start::CONFORMAL
                         : s.start == "mean-value" ? SMP::Discrete_lie_flow_sphere_start::MEAN_VALUE
                                                   : SMP::Discrete_lie_flow_sphere_start::TUTTE;
  s.options.mode = mode_of(s.mode);
  s.options.paper.lump_targets_on_flowing_faces = vm.count("literal-targets") == 0;
  s.options.paper.delaunay_flips = vm.count("no-flips") == 0;
  s.history_in_report = vm.count("history") > 0;
  s.options.record_history = s.history_in_report || !s.convergence_svg.empty();
}

} // namespace

bool parse_sphere_arguments(const std::vector<std::string>& args, Sphere_settings& s)
{
  po::options_description visible("Options");
  add_sphere_options(visible, s);
  std::vector<po::option> ordered;
  const po::variables_map vm = parse_command_line("sphere", glue_region_balls(args), visible, "input", &ordered);
  if(vm.count("help")) {
    std::cout << sphere_help << "\n" << visible;
    return false;
  }
  const std::vector<std::string> inputs = positional_arguments(vm, "input");
  if(inputs.size() != 1) throw Cli_error("dlf sphere needs exactly one INPUT mesh (see 'dlf sphere --help')");
  s.input = inputs[0];
  check_sphere_arguments(vm, ordered, s);
  set_sphere_flow_options(vm, s);
  return true;
}

namespace {

// The share of the sphere's (flat) area each region got.
void measure_regions_on_sphere(const Indexed_mesh& mesh, const std::vector<Vec3>& p, Density_setup& setup)
{
  std::vector<double> area(mesh.faces.size());
  double total = 0;
  for(std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const Triangle& t = mesh.faces[f];
    area[f] = SMP::discrete_lie_flow_sphere_signed_area(p[std::size_t(t[0])], p[std::size_t(t[1])], p[std::size_t(t[2])]);
    total += area[f];
  }
  for(Density_region& r : setup.regions) {
    double a = 0;
    for(int f : r.faces) a += area[std::size_t(f)];
    r.achieved = a / total;
  }
}

// The points of `--init-map`: a mesh file with the input's faces, in order
// (a map written by `dlf sphere -o` keeps them).
std::vector<Vec3> read_start_map(const std::string& path, const Indexed_mesh& input)
{
  const Indexed_mesh map = read_triangle_mesh(path);
  if(map.xyz.size() != input.xyz.size() || map.faces.size() != input.faces.size())
    throw Cli_error("'" + path + "': --init-map has " + std::to_string(map.xyz.size()) + " vertices and " +
                    std::to_string(map.faces.size()) + " faces for the input's " + std::to_string(input.xyz.size()) +
                    " and " + std::to_string(input.faces.size()) + " (expected the input's faces, in order)");
  for(std::size_t f = 0; f < map.faces.size(); ++f)
    if(map.faces[f] != input.faces[f])
      throw Cli_error("'" + path + "': --init-map face " + std::to_string(f) +
                      " is not the input's (expected the input's faces, in order)");
  return map.xyz;
}

} // namespace

bool Sphere_outcome::input_error() const
{
  const int code = int(status);
  // A folded --init-map is the caller's input too.
  const bool given_start_folded = code == SMP::ERROR_INITIAL_MAP_FOLDED &&
                                  report.sphere_start == SMP::Discrete_lie_flow_sphere_start::GIVEN;
  return code == SMP::ERROR_NOT_GENUS_0 || code == SMP::ERROR_NON_TRIANGULAR_MESH ||
         code == SMP::ERROR_DEGENERATE_INPUT || code == SMP::ERROR_EMPTY_MESH || code == SMP::ERROR_INVALID_DENSITY ||
         given_start_folded;
}

Sphere_outcome compute_sphere(const Indexed_mesh& input, Sphere_settings& s, const std::vector<double>& density_values)
{
  // A Surface_mesh in input order, so that vertex i is input vertex i.
  Mesh mesh;
  for(const Vec3& p : input.xyz) mesh.add_vertex(Kernel::Point_3(p[0], p[1], p[2]));
  for(std::size_t f = 0; f < input.faces.size(); ++f) {
    const Triangle& t = input.faces[f];
    if(mesh.add_face(Mesh::Vertex_index(t[0]), Mesh::Vertex_index(t[1]), Mesh::Vertex_index(t[2])) == Mesh::null_face())
      throw Cli_error(s.input + ": face " + std::to_string(f) + " makes the mesh non-manifold");
  }
  Sphere_outcome o;
  o.density = density_values.empty()
                ? make_density(input, s.density)
                : density_of_values(input, density_values, [&](std::size_t k) {
                    return k < density_values.size() ? "density[" + std::to_string(k) + "]" : std::string("density");
                  });
  s.options.face_density = o.density.face_density; // faces in input order, as the Surface_mesh keeps them

  const auto start = std::chrono::steady_clock::now();
  SMP::Discrete_lie_flow_sphere_parameterizer_3<Mesh> dlf(s.options);
  Mesh::Property_map<Mesh::Vertex_index, Kernel::Point_3> sphere =
    mesh.add_property_map<Mesh::Vertex_index, Kernel::Point_3>("v:dlf_sphere").first;
  if(!s.init_map.empty()) {
    if(s.init_map.size() != input.xyz.size())
      throw Cli_error("the initial map has " + std::to_string(s.init_map.size()) + " points for " +
                      std::to_string(input.xyz.size()) + " mesh vertices");
    Mesh::Property_map<Mesh::Vertex_index, Kernel::Point_3> start =
      mesh.add_property_map<Mesh::Vertex_index, Kernel::Point_3>("v:dlf_start").first;
    for(Mesh::Vertex_index v : mesh.vertices()) {
      const Vec3& q = s.init_map[std::size_t(v)];
      start[v] = Kernel::Point_3(q[0], q[1], q[2]);
    }
    dlf.set_initial_map(start);
  }
  o.status = dlf.parameterize(mesh, sphere);
  o.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  o.report = dlf.report();
  if(o.ok()) {
    for(Mesh::Vertex_index v : mesh.vertices()) o.points.push_back({{ sphere[v].x(), sphere[v].y(), sphere[v].z() }});
    measure_regions_on_sphere(input, o.points, o.density);
  }
  return o;
}

json sphere_report(const Sphere_settings& s, const Indexed_mesh& input, const Sphere_outcome& o, const Command_seconds& io)
{
  const SMP::Discrete_lie_flow_report& R = o.report;
  const Density_setup& density = o.density;
  const bool ok = o.ok();
  json j = run_report_head(o.status, R, s.input, input, io, o.seconds);
  j["options"] = { { "tolerance", s.options.tolerance }, { "log_area_tolerance", s.options.sphere.log_area_tolerance },
                   { "share_tolerance", s.options.certified.share_tolerance },
                   { "max_iterations", s.options.max_iterations },
                   { "mu", s.options.mu > 0 ? json(s.options.mu) : json(nullptr) }, // null: the default
                   { "literal_targets", !s.options.paper.lump_targets_on_flowing_faces },
                   { "delaunay_flips", s.options.paper.delaunay_flips },
                   { "fixed_step", s.options.fixed_step > 0 ? json(s.options.fixed_step) : json(nullptr) },
                   { "threshold", s.options.paper.residual_threshold } };
  // As `dlf disk`: "final" is measured on the input triangles; the flowing
  // triangulation (flipped in paper mode) has its own fields.
  j["mode"] = s.mode;
  j["start"] = SMP::discrete_lie_flow_sphere_start_name(R.sphere_start);
  j["caller_inverted_faces"] = ok ? json(R.caller_inverted_faces) : json(nullptr);
  j["flowing_inverted_faces"] = ok ? json(R.flowing_inverted_faces) : json(nullptr);
  j["flips"] = R.flips;
  j["flowing_non_delaunay_edges"] = ok && s.mode != "certified" ? json(R.flowing_non_delaunay_edges) : json(nullptr);
  j["collapse_faces"] = R.collapse_faces;
  j["initial_domain_d_area"] = R.initial_d_area;
  j["domain_d_area"] = R.final_d_area;
  j["final_residual"] = R.final_residual;
  if(density.source != "none") {
    json d;
    d["source"] = density.source;
    if(!s.density.density_file.empty()) d["file"] = s.density.density_file;
    if(!density.regions.empty()) d["band"] = s.density.band;
    d["min"] = *std::min_element(density.face_density.begin(), density.face_density.end());
    d["max"] = *std::max_element(density.face_density.begin(), density.face_density.end());
    d["share_error"] = R.final_share_error; // density_levels.h
    j["density"] = d;
  }
  if(!density.regions.empty()) j["regions"] = regions_json(density, ok);
  j["initial"] = ok ? metrics_to_json(R.initial_metrics) : json(nullptr);
  j["final"] = ok ? metrics_to_json(R.final_metrics) : json(nullptr);
  j["puncture_face"] = R.puncture_face;
  j["split_vertices_removed"] = R.split_vertices_removed;
  j["coarse_iterations"] = R.coarse_iterations;
  add_levels_json(j, R);
  j["rejected_by_exact_check"] = R.rejected_by_exact_check;
  if(s.history_in_report) {
    json h = json::array();
    for(const SMP::Discrete_lie_flow_iteration& it : R.history)
      h.push_back({ { "iteration", it.iteration }, { "step", it.step }, { "critical_step", it.critical_step },
                    { "d_area", it.d_area }, { "backtracks", it.backtracks }, { "flips", it.flips },
                    { "seconds", it.seconds } });
    j["history"] = h;
  }
  return j;
}

Cli_error sphere_failure(const Sphere_settings& s, const Sphere_outcome& o)
{
  // A mesh of another topology still has a map: say which command makes it.
  const std::string other = int(o.status) == SMP::ERROR_NOT_GENUS_0
                              ? "; 'dlf atlas' maps any mesh (several components, borders, any genus) into the plane"
                              : "";
  return Cli_error(s.input + ": " + SMP::discrete_lie_flow_error_name(o.status) + ": " + o.report.message + other,
                   o.input_error() ? EXIT_BAD_INPUT : EXIT_FLOW_ERROR);
}

namespace {

void declare_sphere_outputs(Output_files& outputs, const Sphere_settings& s)
{
  if(!s.output.empty()) outputs.declare(s.output, "-o");
  if(!s.report.empty()) outputs.declare(s.report, "--report");
  if(!s.csv.empty()) outputs.declare(s.csv, "--csv");
  if(!s.domain_mesh.empty()) outputs.declare(s.domain_mesh, "--domain-mesh");
  if(!s.svg.empty()) outputs.declare(s.svg, "--svg");
  if(!s.convergence_svg.empty()) outputs.declare(s.convergence_svg, "--plot-convergence");
  if(!s.histogram_svg.empty()) outputs.declare(s.histogram_svg, "--plot-histogram");
}

// The sphere points with the input's faces (-o) and with the flowing
// triangulation (--domain-mesh: flipped in paper and literal mode, the
// input's otherwise).
void write_sphere_meshes(Output_files& outputs, const Sphere_settings& s, const Indexed_mesh& input,
                         const Sphere_outcome& outcome)
{
  const SMP::Discrete_lie_flow_report& R = outcome.report;
  auto write_points = [&](std::ostream& o) {
    for(const Vec3& p : outcome.points) o << "v " << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  };
  if(!s.output.empty())
    outputs.write(s.output, [&](std::ostream& o) {
      o << "# dlf sphere " << s.input << ": d_area " << std::setprecision(10) << R.final_metrics.d_area << "\n"
        << std::setprecision(17);
      write_points(o);
      for(const Triangle& t : input.faces) o << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
    });
  if(!s.domain_mesh.empty())
    outputs.write(s.domain_mesh, [&](std::ostream& o) {
      o << "# dlf sphere " << s.input << ": mode " << s.mode << ", flowing triangulation\n" << std::setprecision(17);
      write_points(o);
      if(s.mode != "certified")
        for(const std::array<int, 3>& t : R.domain_faces) o << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
      else
        for(const Triangle& t : input.faces) o << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
    });
}

// --svg, --plot-histogram, --plot-convergence.
void write_sphere_pictures(Output_files& outputs, const Sphere_settings& s, const Indexed_mesh& input,
                           const Sphere_outcome& outcome)
{
  const SMP::Discrete_lie_flow_report& R = outcome.report;
  std::ostringstream caption;
  caption << "dlf sphere " << s.input << ": d_area " << std::setprecision(10) << R.final_metrics.d_area;
  if(!s.svg.empty())
    outputs.write(s.svg, [&](std::ostream& o) {
      write_svg_sphere(o, input, outcome.points, caption.str(), s.svg_options, outcome.density.face_density,
                       region_faces(outcome.density));
    });
  // The initial map is not kept by the library: the result only.
  if(!s.histogram_svg.empty())
    outputs.write(s.histogram_svg, [&](std::ostream& o) {
      write_log_ratio_histogram(o, std::vector<double>(), face_log_area_ratios(input, outcome.points, std::vector<double>()),
                                false, caption.str());
    });
  if(!s.convergence_svg.empty())
    outputs.write(s.convergence_svg, [&](std::ostream& o) {
      write_convergence_plot(o, R.history, R.initial_d_area, s.options.tolerance, caption.str());
    });
}

// The summary of a run that made a map.
void print_sphere_summary(std::ostream& out, const Sphere_settings& s, const Indexed_mesh& input,
                          const Sphere_outcome& outcome, const std::vector<std::string>& written)
{
  const SMP::Discrete_lie_flow_report& R = outcome.report;
  out << std::setprecision(8) << "dlf sphere " << s.input << ": " << input.xyz.size() << " vertices, "
      << input.faces.size() << " faces\n"
      << "  status " << run_status(outcome.status, R) << ": " << R.message << "\n";
  print_levels(out, R);
  out << "  iterations " << R.iterations << " (" << SMP::discrete_lie_flow_stop_reason_name(R.stop_reason) << ")\n"
      << "  d_area " << R.initial_metrics.d_area << " -> " << R.final_metrics.d_area << " (optimum 2)\n"
      << "  inverted faces " << R.final_metrics.inverted_faces << "\n";
  if(s.mode != "certified")
    out << "  mode " << s.mode << ": edge flips " << R.flips << ", d_area on the flowing triangulation "
        << R.final_d_area << ", input triangles folded " << R.caller_inverted_faces << "\n";
  out << std::setprecision(3) << "  seconds: initial map " << R.seconds_initial << ", flow " << R.seconds_flow
      << ", total " << outcome.seconds << "\n";
  print_regions(out, outcome.density, "sphere", true);
  for(const std::string& w : written) out << "  wrote " << w << "\n";
}

} // namespace

int sphere_command(const std::vector<std::string>& args)
{
  Sphere_settings s;
  if(!parse_sphere_arguments(args, s)) return EXIT_OK;
  Output_files outputs;
  declare_sphere_outputs(outputs, s);

  Command_seconds io;
  auto t0 = std::chrono::steady_clock::now();
  const Indexed_mesh input = read_triangle_mesh(s.input);
  if(!s.init_map_file.empty()) s.init_map = read_start_map(s.init_map_file, input);
  io.read = seconds_since(t0);
  t0 = std::chrono::steady_clock::now();
  const Sphere_outcome outcome =
    run_with_progress(s.verbosity, s.mode != "certified", s.options, [&] { return compute_sphere(input, s); });
  io.check = (std::max)(0., seconds_since(t0) - outcome.seconds);
  const bool ok = outcome.ok();

  t0 = std::chrono::steady_clock::now();
  if(ok) write_sphere_meshes(outputs, s, input, outcome);
  io.write = seconds_since(t0);
  t0 = std::chrono::steady_clock::now();
  if(ok) write_sphere_pictures(outputs, s, input, outcome);
  io.pictures = seconds_since(t0);
  // Input the command cannot use is refused without output, as `dlf disk`
  // does; a flow error still gets its report.
  if((!s.report.empty() || !s.csv.empty()) && !outcome.input_error())
    write_report_files(outputs, s.report, s.csv, sphere_report(s, input, outcome, io));
  outputs.commit();

  if(s.verbosity != Verbosity::QUIET && ok) print_sphere_summary(std::cout, s, input, outcome, outputs.committed());
  // A region that missed its share is not an error (the map is valid), but never silent.
  for(const Density_region& r : outcome.density.regions)
    if(ok && !(std::abs(r.relative_error()) <= region_share_tolerance))
      std::cerr << "dlf: warning: region " << r.name << " got " << r.achieved << " of the sphere's area, prescribed "
                << r.prescribed << "\n";
  if(!ok) throw sphere_failure(s, outcome);
  return exit_code_of_ok_run(outcome.report, false);
}

} // namespace dlf_cli
