// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// `dlf volume`: map a tetrahedral mesh of a ball (Medit .mesh) into the unit
// ball, volume-preserving or density-prescribed, every tet positive by the
// exact predicate; write the ball's points with the input tets (all outputs
// or none), a JSON report and a picture of the border.

#include "arguments.h"
#include "cli_error.h"
#include "commands.h"
#include "output_files.h"
#include "svg_common.h"

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_volume_3.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_medit.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_tet_mesh.h>

#include <boost/program_options.hpp>
#include <nlohmann/json.hpp>

#include <unistd.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <sstream>

namespace dlf_cli {

namespace {

namespace po = boost::program_options;
namespace SMP = CGAL::Surface_mesh_parameterization;
using json = nlohmann::ordered_json;

const char* volume_help =
  "Usage: dlf volume MESH.mesh [-o OUT.mesh] [--report R.json] [--svg VIEW.svg] [options]\n"
  "\n"
  "Maps a tetrahedral mesh of a topological ball (Medit .mesh, as CGAL's Mesh_3\n"
  "writes it; 'dlf tetrahedralize' makes one from a closed surface) into the unit\n"
  "ball: every tetrahedron gets its share of the volume (or density x share),\n"
  "every tetrahedron positively oriented by the exact predicate, the border on\n"
  "the unit sphere. OUT.mesh holds the ball's points in input vertex order (the\n"
  "vertices of no tetrahedron dropped), the input tetrahedra and the border.\n"
  "\n"
  "Examples:\n"
  "  dlf tetrahedralize build/data/meshes/bunny00.off -o bunny.mesh --tets 20000\n"
  "  dlf volume bunny.mesh -o bunny_ball.mesh --report bunny.json --svg bunny.svg\n"
  "  dlf volume bunny.mesh --roi-ball 0 0 0 0.03 --factor 4 --report roi.json\n"
  "      measure control: the tetrahedra whose centroid lies in the ball get 4 times their share\n"
  "  dlf volume bunny.mesh --mode paper --report paper.json\n"
  "      the paper's flow (Poisson step of the vertex volumes, P1 stiffness), same start and certification\n"
  "\n"
  "Exit codes: 0 converged; 3 a valid, fold-free map short of the tolerance;\n"
  "2 the flow failed (no certified start); 1 bad input.\n";

struct Roi
{
  std::array<double, 4> ball;
  double factor = 1;
};

/// Writes the border triangles of the ball seen from +z and −z, coloured by
/// the log volume ratio of the tet each one bounds.
void write_svg_ball(std::ostream& out, const std::vector<Vec3>& x, const SMP::Discrete_lie_flow_ball_border& border,
                    const std::vector<double>& ratio, const std::string& caption)
{
  const double radius = 200, margin = 20, top = 40;
  const double cy = top + 20 + radius;
  const double cx[2] = { margin + radius, 3 * margin + 3 * radius };
  write_svg_header(out, 4 * margin + 4 * radius + 120, cy + radius + 30, caption);
  const char* names[2] = { "border seen from +z", "border seen from -z" };
  for(int k = 0; k < 2; ++k)
    out << "<circle cx=\"" << cx[k] << "\" cy=\"" << cy << "\" r=\"" << radius
        << "\" fill=\"#eee\" stroke=\"#444\"/><text x=\"" << cx[k] << "\" y=\"" << top + 8
        << "\" text-anchor=\"middle\">" << names[k] << "</text>\n";
  out << "<g stroke-linejoin=\"round\" stroke-width=\"0.3\">\n";
  char buf[64];
  for(std::size_t f = 0; f < border.faces.size(); ++f) {
    const auto& t = border.faces[f];
    const Vec3 &a = x[std::size_t(t[0])], &b = x[std::size_t(t[1])], &c = x[std::size_t(t[2])];
    const double nz = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    const int view = nz >= 0 ? 0 : 1;
    const double mirror = view == 0 ? 1 : -1;
    const std::string& colour = colour_of_log_ratio(std::log(ratio[std::size_t(border.face_tet[f])]));
    out << "<polygon points=\"";
    for(int k = 0; k < 3; ++k) {
      std::snprintf(buf, sizeof buf, "%.2f,%.2f%s", cx[view] + mirror * x[std::size_t(t[std::size_t(k)])][0] * radius,
                    cy - x[std::size_t(t[std::size_t(k)])][1] * radius, k < 2 ? " " : "");
      out << buf;
    }
    out << "\" fill=\"" << colour << "\" stroke=\"" << colour << "\"/>\n";
  }
  out << "</g>\n";
  write_colour_bar(out, 4 * margin + 4 * radius + 10, top + 40, 240, false, false);
  out << "</svg>\n";
}

const char* stop_name(SMP::Discrete_lie_flow_stop_reason r)
{
  switch(r) {
  case SMP::Discrete_lie_flow_stop_reason::CONVERGED: return "converged";
  case SMP::Discrete_lie_flow_stop_reason::PLATEAU: return "plateau";
  case SMP::Discrete_lie_flow_stop_reason::STALLED: return "stalled";
  case SMP::Discrete_lie_flow_stop_reason::ITERATION_CAP: return "iteration_cap";
  case SMP::Discrete_lie_flow_stop_reason::INTERRUPTED: return "interrupted";
  case SMP::Discrete_lie_flow_stop_reason::COLLAPSED: return "collapsed";
  default: return "not_run";
  }
}

/// The command line of `dlf volume`.
struct Volume_arguments
{
  std::string input, output, report_path, csv_path, svg_path, density_file, border_start = "tutte", mode = "certified";
  SMP::Discrete_lie_flow_volume_options options;
  bool quiet = false, verbose = false, has_roi = false;
  Roi roi;
};

/// The options of `dlf volume`, bound to the fields of `a`.
void add_volume_options(po::options_description& visible, Volume_arguments& a)
{
  visible.add_options()
    ("help,h", "this help")
    ("output,o", po::value<std::string>(&a.output)->value_name("OUT.mesh"), "Medit .mesh with the ball's points")
    ("report", po::value<std::string>(&a.report_path)->value_name("R.json"), "JSON report")
    ("csv", po::value<std::string>(&a.csv_path)->value_name("R.csv"),
     "the report as CSV: a header and one row, the JSON report's keys flattened (final.d_vol, seconds.flow)")
    ("svg", po::value<std::string>(&a.svg_path)->value_name("VIEW.svg"),
     "the ball's border from +z and -z, each triangle coloured by the log volume ratio of its tetrahedron")
    ("mode", po::value<std::string>(&a.mode)->value_name("certified|paper"),
     "the flow from the certified start: certified (default; Gauss-Newton descent of D_vol) or paper (the paper's "
     "Poisson step of the vertex volumes' mismatch with the P1 stiffness of the current tetrahedra, mu times the "
     "critical step; every step certified by the exact predicate too; the conjugate-gradient options do not apply)")
    ("no-collapse-guard", "paper mode: the paper's step as written, without the collapse guard (a tet below its "
     "target that the velocities would flatten gets its volume rate projected to zero)")
    ("tolerance", po::value<double>(&a.options.tolerance), "stop when D_vol - 2 <= this (default 0.01) ...")
    ("share-tolerance", po::value<double>(&a.options.share_tolerance),
     "... and, with a density, the tetrahedra of every density value within this of their share, relative "
     "(default 0.005; 0: no such test)")
    ("max-iterations", po::value<std::size_t>(&a.options.max_iterations), "iteration cap (default 1000)")
    ("mu", po::value<double>(&a.options.mu), "fraction of the critical step, in (0, 1) (default 0.8)")
    ("cg-iterations", po::value<std::size_t>(&a.options.cg_max_iterations),
     "conjugate-gradient cap of each Gauss-Newton solve (default 60)")
    ("cholesky-every", po::value<std::size_t>(&a.options.cholesky_every)->value_name("K"),
     "precondition the conjugate gradients by a sparse Cholesky factorisation of the Gauss-Newton matrix, "
     "refreshed every K iterations (default 0: the 3x3 blocks of every vertex)")
    ("coarse-aggregate", po::value<std::size_t>(&a.options.coarse_aggregate)->value_name("K"),
     "the conjugate gradients' coarse level: aggregates of K vertices, each moving by one translation "
     "(default 64; 0: the 3x3 blocks alone)")
    ("fixed-cg-tolerance", "solve every Gauss-Newton system to a relative residual of 1e-3 (up to the cap) "
     "instead of following the Eisenstat-Walker forcing term")
    ("threads", po::value<int>(&a.options.threads)->value_name("N"),
     "threads of the flow (default 0: automatic, one below 150,000 tetrahedra, else the hardware threads, "
     "at most 8); the result does not depend on it")
    ("untangle-iterations", po::value<std::size_t>(&a.options.untangle_max_iterations)->value_name("N"),
     "iteration cap of the start's untangling, its stages and regions together (default 12000; at most 10000 per region of a stage)")
    ("border-start", po::value<std::string>(&a.border_start)->value_name("tutte|conformal"),
     "the start of the border's spherical map (default tutte)")
    ("border-max-iterations", po::value<std::size_t>(&a.options.border.max_iterations)->value_name("N"),
     "iteration cap of the border's spherical flow (default 500; 0: its start alone)")
    ("density", po::value<std::string>(&a.density_file)->value_name("FILE"),
     "measure control: one density > 0 per tetrahedron, in file order")
    ("roi-ball", po::value<std::vector<double> >()->multitoken()->value_name("X Y Z R"),
     "a region of interest: the tetrahedra whose centroid lies in this ball (input coordinates); needs --factor")
    ("factor", po::value<double>()->value_name("F"), "density of the region (> 0)")
    ("star-shaped", "keep every border triangle positive seen from the centre during the flow: with the "
     "positive tetrahedra a certificate of bijectivity, at a higher D_vol on meshes with protrusions "
     "(by default only the tetrahedra constrain the flow; the report counts such border triangles)")
    ("history", "per-iteration history in the report")
    ("quiet,q", "print nothing on success")
    ("verbose,v", "one progress line per iteration");
}

/// Parses and checks the command line into `a`; false after `--help`.
bool parse_volume_arguments(const std::vector<std::string>& args, Volume_arguments& a)
{
  po::options_description visible("Options");
  add_volume_options(visible, a);
  const po::variables_map vm = parse_command_line("volume", args, visible, "input");
  if(vm.count("help")) {
    std::cout << volume_help << "\n" << visible;
    return false;
  }
  const std::vector<std::string> inputs = positional_arguments(vm, "input");
  if(inputs.size() != 1) throw Cli_error("expected one input .mesh (see 'dlf volume --help')");
  a.input = inputs[0];
  a.quiet = vm.count("quiet") != 0;
  a.verbose = vm.count("verbose") != 0;
  if(a.quiet && a.verbose) throw Cli_error("--quiet and --verbose exclude each other");
  if(!(a.options.mu > 0 && a.options.mu < 1)) throw Cli_error("--mu must lie in (0, 1)");
  if(!(a.options.tolerance > 0)) throw Cli_error("--tolerance must be positive");
  a.has_roi = vm.count("roi-ball") != 0;
  if(a.has_roi != (vm.count("factor") != 0)) throw Cli_error("--roi-ball and --factor go together");
  if(a.has_roi) {
    const std::vector<double> b = vm["roi-ball"].as<std::vector<double> >();
    if(b.size() != 4 || !(b[3] > 0)) throw Cli_error("--roi-ball takes X Y Z R with R > 0");
    a.roi.ball = {{ b[0], b[1], b[2], b[3] }};
    a.roi.factor = vm["factor"].as<double>();
    if(!(a.roi.factor > 0) || !std::isfinite(a.roi.factor)) throw Cli_error("--factor must be positive");
  }
  if(a.has_roi && !a.density_file.empty()) throw Cli_error("--density and --roi-ball exclude each other");
  a.options.record_history = vm.count("history") != 0;
  a.options.star_shaped_border = vm.count("star-shaped") != 0;
  a.options.paper_collapse_guard = vm.count("no-collapse-guard") == 0;
  a.options.cg_forcing = vm.count("fixed-cg-tolerance") == 0;
  if(a.options.threads < 0) throw Cli_error("--threads must be 0 (automatic) or positive");
  if(a.mode == "paper") a.options.mode = SMP::Discrete_lie_flow_mode::PAPER;
  else if(a.mode != "certified") throw Cli_error("--mode takes certified or paper");
  if(a.border_start == "conformal") a.options.border.sphere.start = SMP::Discrete_lie_flow_sphere_start::CONFORMAL;
  else if(a.border_start != "tutte") throw Cli_error("--border-start takes tutte or conformal");
  return true;
}

/// Reads the input mesh (its unused vertices dropped: their number is
/// returned) and the density file into `a.options`.
std::size_t read_volume_input(Volume_arguments& a, SMP::Discrete_lie_flow_tet_mesh& mesh)
{
  {
    std::ifstream in(a.input);
    if(!in) throw Cli_error("cannot open '" + a.input + "'");
    std::string error;
    if(!SMP::read_medit_tet_mesh(in, mesh, error)) throw Cli_error(a.input + ": " + error);
  }
  std::vector<int> kept;
  const std::size_t dropped = SMP::drop_unused_tet_mesh_vertices(mesh, kept);
  if(!a.density_file.empty()) {
    std::ifstream in(a.density_file);
    if(!in) throw Cli_error("cannot open '" + a.density_file + "'");
    double v;
    std::string tok;
    while(in >> tok) {
      char* end = nullptr;
      v = std::strtod(tok.c_str(), &end);
      if(end == tok.c_str() || *end != '\0' || !(v > 0) || !std::isfinite(v))
        throw Cli_error(a.density_file + ": value " + std::to_string(a.options.tet_density.size() + 1) + " ('" + tok +
                        "') is not a finite positive density");
      a.options.tet_density.push_back(v);
    }
    if(a.options.tet_density.size() != mesh.tets.size())
      throw Cli_error(a.density_file + ": " + std::to_string(a.options.tet_density.size()) + " densities for " +
                      std::to_string(mesh.tets.size()) + " tetrahedra");
  }
  return dropped;
}

/// With `--roi-ball`: the density of the tets whose centroid lies in the
/// ball, into `a.options`; per tet, whether it does (empty without).
std::vector<char> apply_roi_density(Volume_arguments& a, const SMP::Discrete_lie_flow_tet_mesh& mesh)
{
  std::vector<char> in_roi;
  if(!a.has_roi) return in_roi;
  a.options.tet_density.assign(mesh.tets.size(), 1.);
  in_roi.assign(mesh.tets.size(), 0);
  std::size_t count = 0;
  for(std::size_t t = 0; t < mesh.tets.size(); ++t) {
    Vec3 c = {{ 0, 0, 0 }};
    for(int v : mesh.tets[t])
      for(int k = 0; k < 3; ++k) c[std::size_t(k)] += mesh.points[std::size_t(v)][std::size_t(k)] / 4;
    const double d2 = (c[0] - a.roi.ball[0]) * (c[0] - a.roi.ball[0]) + (c[1] - a.roi.ball[1]) * (c[1] - a.roi.ball[1]) +
                      (c[2] - a.roi.ball[2]) * (c[2] - a.roi.ball[2]);
    if(d2 <= a.roi.ball[3] * a.roi.ball[3]) { in_roi[t] = 1; a.options.tet_density[t] = a.roi.factor; ++count; }
  }
  if(count == 0) throw Cli_error("--roi-ball holds the centroid of no tetrahedron");
  if(count == mesh.tets.size()) throw Cli_error("--roi-ball holds every tetrahedron: the factor changes nothing");
  return in_roi;
}

/// The progress lines: in place on a terminal, else every 10th iteration
/// (every one with `verbose`).
std::function<bool(const SMP::Discrete_lie_flow_volume_iteration&)> volume_progress(bool verbose)
{
  const bool in_place = !verbose && isatty(fileno(stdout));
  return [in_place, verbose](const SMP::Discrete_lie_flow_volume_iteration& I) {
    if(!in_place && !verbose && I.iteration % 10 != 0) return true;
    std::printf("%s%s %4zu  step %.3g  %s %.6g  cg %zu  %.1f s%s", in_place ? "\r" : "",
                I.untangling ? "untangle" : "flow", I.iteration, I.step, I.untangling ? "energy" : "d_vol", I.d_vol,
                I.cg_iterations, I.seconds, in_place ? "   " : "\n");
    if(I.untangling && !in_place) std::printf("    eps %.3g, %zu negative tets\n", I.epsilon, I.negative_tets);
    std::fflush(stdout);
    return true;
  };
}

/// The region's share of the volume, prescribed and achieved.
struct Roi_share
{
  double target = 0, achieved = 0;
};

/// The region's share, recomputed from the written points `x`.
Roi_share roi_share(const Volume_arguments& a, const SMP::Discrete_lie_flow_tet_mesh& mesh,
                    const std::vector<char>& in_roi, const std::vector<Vec3>& x)
{
  Roi_share r;
  if(!a.has_roi) return r;
  double T = 0, U = 0;
  for(std::size_t t = 0; t < mesh.tets.size(); ++t) {
    const std::array<int, 4>& k = mesh.tets[t];
    const double tv = a.options.tet_density[t] * SMP::discrete_lie_flow_tet_determinant(mesh.points[std::size_t(k[0])], mesh.points[std::size_t(k[1])],
                                                          mesh.points[std::size_t(k[2])], mesh.points[std::size_t(k[3])]);
    const double uv = SMP::discrete_lie_flow_tet_determinant(x[std::size_t(k[0])], x[std::size_t(k[1])], x[std::size_t(k[2])], x[std::size_t(k[3])]);
    T += tv; U += uv;
    if(in_roi[t]) { r.target += tv; r.achieved += uv; }
  }
  r.target /= T;
  r.achieved /= U;
  return r;
}

/// The JSON report (and CSV row) of a run.
json volume_report(const Volume_arguments& a, const SMP::Discrete_lie_flow_volume_report& R, std::size_t dropped,
                   const Roi_share& roi, const Command_seconds& io)
{
  json j;
  j["input"] = a.input;
  // As `dlf disk` and `dlf sphere`: a valid map short of its goal is "not_converged" (exit 3).
  j["status"] = R.status != SMP::OK ? "error" : R.converged() ? "ok" : "not_converged";
  j["message"] = R.message;
  j["stop_reason"] = stop_name(R.stop_reason);
  j["vertices"] = R.vertices;
  j["unused_vertices_dropped"] = dropped;
  j["border_vertices"] = R.border_vertices;
  j["tets"] = R.tets;
  j["iterations"] = R.iterations;
  j["start"] = { { "certified", R.start_certified }, { "tutte_negative_tets", R.start_negative_tets },
                 { "tutte_flat_tets", R.start_flat_tets }, { "untangle_iterations", R.untangle_iterations },
                 { "border_d_area", R.border.final_d_area }, { "border_stop_reason", stop_name(R.border.stop_reason) },
                 { "d_vol", R.initial_d_vol } };
  j["final"] = { { "d_vol", R.final_d_vol }, { "inverted_tets", R.inverted_tets }, { "flat_tets", R.flat_tets },
                 { "border_faces_not_star_shaped", R.inverted_border_faces },
                 { "log_volume_mean_abs", R.log_volume_mean_abs }, { "log_volume_max_abs", R.log_volume_max_abs },
                 { "min_ratio", R.min_ratio }, { "max_ratio", R.max_ratio }, { "volume", R.volume },
                 { "ball_volume", 4 * std::acos(-1.) / 3 } };
  json shares = json::array();
  for(const auto& s : R.shares)
    shares.push_back({ { "density", s.density }, { "tets", s.tets }, { "target_share", s.target_share },
                       { "achieved_share", s.achieved_share }, { "relative_error", s.relative_error() } });
  j["shares"] = shares;
  if(a.has_roi)
    j["roi"] = { { "ball", a.roi.ball }, { "factor", a.roi.factor }, { "target_share", roi.target },
                 { "achieved_share", roi.achieved }, { "relative_error", roi.achieved / roi.target - 1 } };
  j["options"] = { { "mode", a.mode }, { "collapse_guard", a.options.paper_collapse_guard }, { "tolerance", a.options.tolerance }, { "share_tolerance", a.options.share_tolerance }, { "max_iterations", a.options.max_iterations }, { "mu", a.options.mu },
                     { "border_start", a.border_start }, { "border_max_iterations", a.options.border.max_iterations },
                     { "untangle_iterations", a.options.untangle_max_iterations },
                     { "coarse_aggregate", a.options.coarse_aggregate }, { "cg_forcing", a.options.cg_forcing },
                     { "threads", a.options.threads },
                     { "threads_used", R.threads } };
  j["counters"] = { { "rejected_by_exact_check", R.rejected_by_exact_check }, { "cg_iterations", R.cg_iterations } };
  // The start is the border's spherical map, the interior's Tutte map and its untangling.
  j["seconds"] = seconds_json(io, R.seconds_border + R.seconds_interior + R.seconds_untangle, R.seconds_flow,
                              R.seconds_total);
  j["seconds"]["border"] = R.seconds_border;
  j["seconds"]["interior"] = R.seconds_interior;
  j["seconds"]["untangle"] = R.seconds_untangle;
  if(a.options.record_history) {
    json h = json::array();
    for(const auto& I : R.history)
      h.push_back({ { "iteration", I.iteration }, { "step", I.step }, { "critical_step", I.critical_step }, { "limiting_tet", I.limiting_tet },
                    { "d_vol", I.d_vol }, { "cg_iterations", I.cg_iterations }, { "seconds", I.seconds } });
    j["history"] = h;
  }
  return j;
}

/// The summary lines on stdout (none with `--quiet`).
void print_volume_summary(const Volume_arguments& a, const SMP::Discrete_lie_flow_volume_report& R,
                          std::size_t dropped, const Roi_share& roi)
{
  if(a.quiet) return;
  std::printf("volume: %zu tets, %s after %zu iterations: D_vol %.6g (start %.6g), mean |log r| %.3g, max |log r| %.3g, "
              "%zu inverted (exact), %.1f s\n", R.tets, stop_name(R.stop_reason), R.iterations, R.final_d_vol,
              R.initial_d_vol, R.log_volume_mean_abs, R.log_volume_max_abs, R.inverted_tets, R.seconds_total);
  if(R.start_negative_tets + R.start_flat_tets > 0)
    std::printf("start: Tutte folded %zu tets (%zu flat), untangled in %zu iterations\n", R.start_negative_tets,
                R.start_flat_tets, R.untangle_iterations);
  if(a.has_roi)
    std::printf("roi: share %.6g, target %.6g (%+.3f%%)\n", roi.achieved, roi.target, 100 * (roi.achieved / roi.target - 1));
  if(dropped) std::printf("note: %zu vertices of no tetrahedron were left out\n", dropped);
}

/// The exit code; a valid map short of its goal warns on stderr first.
int volume_exit_code(const SMP::Discrete_lie_flow_volume_report& R)
{
  if(R.converged()) return EXIT_OK;
  // As dlf disk and dlf sphere: the goal missed and its value, then what to try.
  std::cerr << "dlf: warning: " << R.message << "; "
            << (R.stop_reason == SMP::Discrete_lie_flow_stop_reason::ITERATION_CAP
                  ? "it was still improving: a larger --max-iterations may reach the tolerance"
                  : R.stop_reason == SMP::Discrete_lie_flow_stop_reason::INTERRUPTED ? "the run was interrupted"
                                                                                     : "more iterations will not help")
            << "\n";
  return EXIT_NOT_CONVERGED;
}

} // namespace

int volume_command(const std::vector<std::string>& args)
{
  Volume_arguments a;
  if(!parse_volume_arguments(args, a)) return EXIT_OK;
  const Volume_arguments& A = a;
  Output_files files;
  if(!A.output.empty()) files.declare(A.output, "-o");
  if(!A.report_path.empty()) files.declare(A.report_path, "--report");
  if(!A.csv_path.empty()) files.declare(A.csv_path, "--csv");
  if(!A.svg_path.empty()) files.declare(A.svg_path, "--svg");

  Command_seconds io;
  const auto since = [](std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  };
  auto t0 = std::chrono::steady_clock::now();
  SMP::Discrete_lie_flow_tet_mesh mesh;
  const std::size_t dropped = read_volume_input(a, mesh);
  io.read = since(t0);
  const std::vector<char> in_roi = apply_roi_density(a, mesh);
  const bool in_place = !A.verbose && isatty(fileno(stdout));
  if(!A.quiet) a.options.callback = volume_progress(A.verbose);
  SMP::Discrete_lie_flow_volume_parameterizer_3<> dlf(A.options);
  struct P { double a, b, c; P(double x, double y, double z) : a(x), b(y), c(z) {} };
  std::vector<P> ball;
  const SMP::Error_code code = dlf.parameterize(
    [&] { std::vector<CGAL::Simple_cartesian<double>::Point_3> p; for(const auto& q : mesh.points) p.emplace_back(q[0], q[1], q[2]); return p; }(),
    mesh.tets, ball);
  if(in_place && !A.quiet) std::printf("\n");
  const SMP::Discrete_lie_flow_volume_report& R = dlf.report();
  if(code != SMP::OK) {
    // The input's faults are bad input; a start that cannot be certified is the flow's.
    const bool bad_input = code == SMP::ERROR_EMPTY_MESH || code == SMP::ERROR_WRONG_PARAMETER ||
                           code == SMP::ERROR_NO_TOPOLOGICAL_BALL || code == int(SMP::ERROR_DEGENERATE_INPUT) ||
                           code == int(SMP::ERROR_INVALID_DENSITY);
    throw Cli_error(A.input + ": " + R.message, bad_input ? EXIT_BAD_INPUT : EXIT_FLOW_ERROR);
  }
  t0 = std::chrono::steady_clock::now();
  std::vector<Vec3> x(ball.size());
  for(std::size_t i = 0; i < ball.size(); ++i) x[i] = {{ ball[i].a, ball[i].b, ball[i].c }};
  SMP::Discrete_lie_flow_ball_border border;
  std::string message;
  SMP::discrete_lie_flow_ball_border(mesh.points, mesh.tets, border, message); // checked by the run: the border faces
  const Roi_share roi = roi_share(A, mesh, in_roi, x);
  io.check = since(t0);
  t0 = std::chrono::steady_clock::now();
  if(!A.output.empty())
    files.write(A.output, [&](std::ostream& os) { SMP::write_medit_tet_mesh(os, x, mesh.tets, mesh.tet_refs, border.faces); });
  io.write = since(t0);
  t0 = std::chrono::steady_clock::now();
  if(!A.svg_path.empty()) {
    std::ostringstream caption;
    caption << A.input << ": D_vol " << R.final_d_vol << ", " << R.tets << " tetrahedra";
    files.write(A.svg_path, [&](std::ostream& os) { write_svg_ball(os, x, border, R.volume_ratio, caption.str()); });
  }
  io.pictures = since(t0);
  if(!A.report_path.empty() || !A.csv_path.empty()) {
    const json j = volume_report(A, R, dropped, roi, io);
    if(!A.report_path.empty()) files.write(A.report_path, [&](std::ostream& os) { os << j.dump(2) << '\n'; });
    if(!A.csv_path.empty()) files.write(A.csv_path, [&](std::ostream& os) { write_csv_report(os, j); });
  }
  files.commit();
  print_volume_summary(A, R, dropped, roi);
  return volume_exit_code(R);
}

} // namespace dlf_cli
