// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// `dlf disk`: read, check, flow, measure, write (all outputs or none), tell.

#include "arguments.h"
#include "cli_error.h"
#include "commands.h"
#include "density_input.h"
#include "disk_outcome.h"
#include "disk_pictures.h"
#include "disk_run.h"
#include "metrics.h"
#include "obj_io.h"
#include "output_files.h"
#include "progress.h"
#include "seam_run.h"
#include "verdict.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace dlf_cli {

namespace {

namespace SMP = CGAL::Surface_mesh_parameterization;
// Insertion order, so that a report reads top-down: status first, history last.
using json = nlohmann::ordered_json;

// The border the flow used; the requested one if the flow did not start.
std::string used_border(const Disk_run& run, const Disk_settings& s)
{
  return run.report.border == SMP::Discrete_lie_flow_border::AUTOMATIC ? s.border : SMP::discrete_lie_flow_border_name(run.report.border);
}

// The parameterizer's codes that blame the input rather than the flow (exit
// code 1, like the tool's own input checks).
bool is_input_error(int code)
{
  return code == SMP::ERROR_EMPTY_MESH || code == SMP::ERROR_NON_TRIANGULAR_MESH ||
         code == SMP::ERROR_NO_TOPOLOGICAL_DISC || code == SMP::ERROR_DEGENERATE_INPUT ||
         code == SMP::ERROR_INVALID_DENSITY;
}

json history_json(const std::vector<SMP::Discrete_lie_flow_iteration>& history)
{
  json h = json::array();
  for(const SMP::Discrete_lie_flow_iteration& it : history)
    h.push_back({ { "iteration", it.iteration }, { "step", it.step }, { "critical_step", it.critical_step },
                  { "limiting_face", it.limiting_face }, { "d_area", it.d_area }, { "residual", it.residual },
                  { "backtracks", it.backtracks }, { "flips", it.flips }, { "seconds", it.seconds } });
  return h;
}

// What may get a region closer to its share, by why the flow stopped.
const char* share_hint(SMP::Discrete_lie_flow_stop_reason r)
{
  switch(r) {
  case SMP::Discrete_lie_flow_stop_reason::CONVERGED: return "a smaller --tolerance may help";
  case SMP::Discrete_lie_flow_stop_reason::ITERATION_CAP: return "a larger --max-iterations may help";
  default: return "a wider --band or a factor closer to 1 may help";
  }
}

json density_json(const Disk_settings& s, const Density_setup& d)
{
  if(d.source == "none") return json(nullptr);
  json j;
  j["source"] = d.source;
  if(!s.density_file.empty()) j["file"] = s.density_file;
  if(!d.regions.empty()) j["band"] = s.band;
  j["min"] = *std::min_element(d.face_density.begin(), d.face_density.end());
  j["max"] = *std::max_element(d.face_density.begin(), d.face_density.end());
  return j;
}


// With --seam: the seams and the cut surface that the flow mapped.
json seam_json(const Disk_settings& s, const Seam_cut& cut)
{
  if(s.seam.empty()) return json(nullptr);
  json j;
  j["file"] = s.seam;
  j["edges"] = cut.seams.edges.size();
  j["joined_vertices"] = cut.seams.cones; // 0: the edges are the file's line 3
  j["cut_vertices"] = cut.mesh.xyz.size();
  return j;
}

json make_report(const Disk_settings& s, const Indexed_mesh& input, const Seam_cut& cut,
                 const std::vector<Border_loop>& loops, const Disk_run& run,
                 const Metrics* initial, const Metrics* final_metrics, const Density_setup& density,
                 const Command_seconds& io = Command_seconds())
{
  const SMP::Discrete_lie_flow_report& R = run.report;
  json j = run_report_head(run.status, R, s.input, input, io, run.seconds);
  j["initial"] = initial ? metrics_to_json(*initial) : json(nullptr);
  j["final"] = final_metrics ? metrics_to_json(*final_metrics) : json(nullptr);
  j["mode"] = s.mode;
  j["init"] = s.init;
  j["border"] = used_border(run, s);
  j["border_loops"] = loops.size();
  j["outer_loop"] = { { "index", s.outer_loop }, { "length", loops[std::size_t(s.outer_loop)].length },
                      { "vertices", loops[std::size_t(s.outer_loop)].vertices.size() } };
  j["holes"] = loops.size() - 1; // they float (the library fills them for the flow)
  j["caller_inverted_faces"] = R.caller_inverted_faces;
  j["flowing_inverted_faces"] = R.flowing_inverted_faces;
  j["flips"] = R.flips;
  j["initial_domain_d_area"] = R.initial_d_area;
  j["domain_d_area"] = R.final_d_area;
  j["final_residual"] = R.final_residual;
  j["rejected_by_exact_check"] = R.rejected_by_exact_check;
  j["collapse_faces"] = R.collapse_faces;
  j["seam"] = seam_json(s, cut);
  j["options"] = { { "tolerance", s.options.tolerance }, { "share_tolerance", s.options.certified.share_tolerance },
                   { "max_iterations", s.options.max_iterations },
                   { "mu", s.options.mu > 0 ? json(s.options.mu) : json(nullptr) }, // null: the mode's default
                   { "literal_targets", !s.options.paper.lump_targets_on_flowing_faces },
                   { "delaunay_flips", s.options.paper.delaunay_flips },
                   { "fixed_step", s.options.fixed_step > 0 ? json(s.options.fixed_step) : json(nullptr) },
                   { "threshold", s.options.paper.residual_threshold } };
  // Metrics above are density-weighted (doc/design.md) when a density is given.
  j["density"] = density_json(s, density);
  if(density.source != "none") j["density"]["share_error"] = R.final_share_error; // density_levels.h
  if(!density.regions.empty()) j["regions"] = regions_json(density, final_metrics != nullptr);
  if(s.history_in_report) j["history"] = history_json(R.history);
  add_levels_json(j, R);
  return j;
}

void print_summary(std::ostream& out, const Disk_settings& s, const Indexed_mesh& input, const Seam_cut& cut,
                   const std::vector<Border_loop>& loops, const Disk_run& run,
                   const Metrics* initial, const Metrics* final_metrics, const Density_setup& density,
                   const std::vector<std::string>& written,
                   const std::vector<std::pair<std::string, double> >& picture_timings)
{
  const SMP::Discrete_lie_flow_report& R = run.report;
  out << std::setprecision(8);
  out << "dlf disk " << s.input << ": " << input.xyz.size() << " vertices, " << input.faces.size() << " faces\n";
  if(!s.seam.empty()) {
    out << "  seams " << s.seam << ": " << cut.seams.edges.size() << " edges";
    if(cut.seams.cones) out << " (shortest paths joining its " << cut.seams.cones << " vertices)";
    out << ", cut open: " << cut.mesh.xyz.size() << " vertices (one per seam side)\n";
  }
  out << "  mode " << s.mode << ", init " << s.init << ", border " << used_border(run, s) << "\n"
      << "  status " << run_status(run.status, R) << ": " << R.message << "\n";
  if(loops.size() > 1) {
    const Border_loop& outer = loops[std::size_t(s.outer_loop)];
    out << "  border loops " << loops.size() << ": loop " << s.outer_loop << " is outer (length " << outer.length << ", "
        << outer.vertices.size() << " vertices; --outer-loop K picks another, as 'dlf info' lists them), "
        << loops.size() - 1 << (loops.size() == 2 ? " hole floats" : " holes float") << "\n"
        << "  initial map: " << s.init << " places the outer loop; the start is Tutte's embedding of the disk with "
           "its holes filled\n";
  }
  print_levels(out, R);
  out
      << "  iterations " << R.iterations << " (" << SMP::discrete_lie_flow_stop_reason_name(R.stop_reason) << ")\n";
  if(initial) {
    out << "  d_area " << initial->d_area;
    if(final_metrics) out << " -> " << final_metrics->d_area;
    out << " (optimum 2" << (density.source == "none" ? "" : ", density-weighted") << ")\n  inverted faces "
        << initial->inverted_faces;
    if(final_metrics) out << " -> " << final_metrics->inverted_faces;
    out << "\n";
  }
  if(s.mode != "certified") out << "  edge flips " << R.flips << "\n";
  if(!s.density_file.empty()) out << "  density per " << density.source << " from " << s.density_file << "\n";
  print_regions(out, density, "domain", final_metrics != nullptr);
  out << std::setprecision(3) << "  seconds: initial map " << R.seconds_initial << ", flow " << R.seconds_flow
      << ", total " << run.seconds << "\n";
  if(s.verbosity == Verbosity::VERBOSE)
    for(const auto& p : picture_timings) out << "  seconds writing " << p.first << ": " << p.second << "\n";
  for(const std::string& w : written) out << "  wrote " << w << "\n";
}

// Why the square refused a border that is long enough: an ear (a triangle
// with two border edges) must sit on a corner, or the square's side would
// flatten it, and a square has four corners.
std::string square_border_hint(const Disk_settings& s, const Disk_run& run, const Indexed_mesh& mesh,
                               const std::vector<Border_loop>& loops)
{
  if(s.border != "square" || run.status != SMP::ERROR_BORDER_TOO_SHORT || loops.empty()) return "";
  const std::vector<int>& outer = loops[std::size_t(s.outer_loop)].vertices;
  if(outer.size() < 4) return " (the outer loop has " + std::to_string(outer.size()) + " vertices; a square needs 4)";
  std::vector<int> faces_at(mesh.xyz.size(), 0);
  for(const Triangle& t : mesh.faces)
    for(int v : t) ++faces_at[std::size_t(v)];
  std::vector<int> ears;
  for(int v : outer)
    if(faces_at[std::size_t(v)] == 1) ears.push_back(v);
  if(ears.size() <= 4) return "";
  std::string first;
  for(std::size_t k = 0; k < ears.size() && k < 5; ++k) first += (k ? ", " : "") + std::to_string(ears[k]);
  return " (the outer loop has " + std::to_string(ears.size()) + " ears, triangles with two border edges, at vertices " +
         first + (ears.size() > 5 ? ", ..." : "") + ": each must be a corner of the square or its side would flatten it, "
         "and a square has 4; use --border circle, the default)";
}

} // namespace

Disk_outcome compute_disk(const Indexed_mesh& input, Disk_settings& s, const std::vector<double>& density_values)
{
  Disk_outcome o;
  // With seams, the flow maps the input cut open (one vertex per seam side),
  // which must pass the check of an uncut input; densities and regions are
  // the input's (faces keep their order).
  if(!s.seam.empty())
    o.cut = s.seam_pairs.empty()
              ? read_and_cut(input, s.input, s.seam, check_disk_topology)
              : checked_cut(input, s.input, seam_selection_of_pairs(s.seam_pairs, input, s.seam), s.seam, check_disk_topology);
  const Indexed_mesh& mesh = mapped_mesh(input, s, o);
  o.loops = check_disk_topology(mesh, s.input);
  const std::vector<Border_loop>& loops = o.loops;
  if(!s.seam.empty() && s.outer_loop != 0)
    throw Cli_error("--outer-loop applies without --seam (with seams, the longest loop of the cut surface is the outer one)");
  if(std::size_t(s.outer_loop) >= loops.size())
    throw Cli_error("--outer-loop " + std::to_string(s.outer_loop) + ": " + s.input + " has " +
                    std::to_string(loops.size()) + " border loop" + (loops.size() == 1 ? "" : "s") + " (0 to " +
                    std::to_string(loops.size() - 1) + ", longest first, as 'dlf info' lists them)");
  if(loops.size() > 1) {
    s.on_outer_loop.assign(mesh.xyz.size(), 0);
    for(int v : loops[std::size_t(s.outer_loop)].vertices) s.on_outer_loop[std::size_t(v)] = 1;
  }
  if(loops.size() > 1 && s.mode != "certified")
    throw Cli_error("--mode " + s.mode + " takes disks only: " + s.input + " has " + std::to_string(loops.size() - 1) +
                    (loops.size() == 2 ? " hole" : " holes") + " (the certified mode, the default, fills them for the flow)");
  if(!s.init_uv_file.empty()) s.init_uv = read_uv_obj(s.init_uv_file, input.xyz.size());
  o.density = density_values.empty()
                ? make_density(input, s)
                : density_of_values(input, density_values, [&](std::size_t k) {
                    return k < density_values.size() ? "density[" + std::to_string(k) + "]" : std::string("density");
                  });
  s.options.face_density = o.density.face_density; // faces in input order, as Surface_mesh keeps them

  o.run = s.seam.empty() ? run_disk(input, s) : run_seamed_disk(input, o.cut, s);
  o.ok = o.run.status == SMP::OK;

  // The library measures both maps of a successful run; a failed run's
  // initial map is measured here.
  if(o.ok) {
    o.initial = o.run.report.initial_metrics;
    o.final_metrics = o.run.report.final_metrics;
    measure_regions(mesh, o.run.final_uv, o.density);
  } else if(!o.run.initial_uv.empty()) {
    o.initial = compute_metrics(mesh, o.run.initial_uv, o.density.face_density);
  }
  return o;
}

json disk_report(const Disk_settings& s, const Indexed_mesh& input, const Disk_outcome& o)
{
  return make_report(s, input, o.cut, o.loops, o.run, o.initial_ptr(), o.final_ptr(), o.density);
}

Cli_error disk_failure(const Disk_settings& s, const Indexed_mesh& input, const Disk_outcome& o)
{
  return Cli_error(s.input + ": " + SMP::discrete_lie_flow_error_name(o.run.status) + ": " + o.run.report.message +
                     square_border_hint(s, o.run, mapped_mesh(input, s, o), o.loops),
                   is_input_error(o.run.status) ? EXIT_BAD_INPUT : EXIT_FLOW_ERROR);
}

int disk_command(const std::vector<std::string>& args)
{
  Disk_settings s;
  if(!parse_disk_arguments(args, s)) return EXIT_OK;

  Output_files outputs;
  if(!s.output.empty()) outputs.declare(s.output, "-o");
  if(!s.domain_mesh.empty()) outputs.declare(s.domain_mesh, "--domain-mesh");
  declare_pictures(outputs, s);
  if(!s.report.empty()) outputs.declare(s.report, "--report");
  if(!s.csv.empty()) outputs.declare(s.csv, "--csv");

  Command_seconds io;
  auto t0 = std::chrono::steady_clock::now();
  const Indexed_mesh input = read_triangle_mesh(s.input);
  io.read = seconds_since(t0);
  t0 = std::chrono::steady_clock::now();
  Disk_outcome outcome =
    run_with_progress(s.verbosity, s.mode != "certified", s.options, [&] { return compute_disk(input, s); });
  io.check = (std::max)(0., seconds_since(t0) - outcome.run.seconds);
  const Seam_cut& cut = outcome.cut;
  const Indexed_mesh& mesh = mapped_mesh(input, s, outcome);
  const std::vector<Border_loop>& loops = outcome.loops;
  Density_setup& density = outcome.density;
  const Disk_run& run = outcome.run;
  const bool ok = outcome.ok;
  const Metrics& final_metrics = outcome.final_metrics;
  const Metrics* initial_ptr = outcome.initial_ptr();
  const Metrics* final_ptr = outcome.final_ptr();

  // On a flow error, only the report is written: it says what went wrong.
  std::vector<std::pair<std::string, double> > picture_timings;
  if(ok) {
    std::ostringstream comment;
    comment << std::setprecision(10) << "dlf disk " << s.input << ": mode " << s.mode << ", init " << s.init
            << ", border " << used_border(run, s) << (s.seam.empty() ? "" : ", seams " + s.seam) << ", d_area "
            << final_metrics.d_area;
    // v and f are the input's; with seams, vt are per side and f a/p b/q c/r.
    t0 = std::chrono::steady_clock::now();
    if(!s.output.empty())
      outputs.write(s.output, [&](std::ostream& o) {
        write_uv_obj(o, input.xyz, run.final_uv, input.faces, mesh.faces, comment.str());
      });
    io.write = seconds_since(t0);
    if(!s.domain_mesh.empty()) {
      // Certified mode keeps the input triangulation; its faces are written
      // in input order (the report lists them in the library's walk order).
      const std::vector<Triangle>& domain =
        s.mode != "certified" ? run.report.domain_faces : mesh.faces;
      std::vector<Triangle> domain_positions = domain;
      if(!s.seam.empty())
        for(Triangle& t : domain_positions)
          for(int& v : t) v = cut.input_vertex[std::size_t(v)];
      outputs.write(s.domain_mesh, [&](std::ostream& o) {
        write_uv_obj(o, input.xyz, run.final_uv, domain_positions, domain, comment.str() + " (domain triangulation)");
      });
    }
    picture_timings = write_pictures(outputs, s, mesh, run, density, comment.str(), &input);
  }
  for(const auto& p : picture_timings) io.pictures += p.second;
  if(!s.report.empty() || !s.csv.empty())
    write_report_files(outputs, s.report, s.csv, make_report(s, input, cut, loops, run, initial_ptr, final_ptr, density, io));
  outputs.commit();

  if(s.verbosity != Verbosity::QUIET)
    print_summary(std::cout, s, input, cut, loops, run, initial_ptr, final_ptr, density, outputs.committed(), picture_timings);
  // A region that missed its share is not an error (the map is valid), but never silent.
  for(const Density_region& r : density.regions)
    if(ok && !(std::abs(r.relative_error()) <= region_share_tolerance))
      std::cerr << "dlf: warning: region " << r.name << " got " << r.achieved << " of the domain area, prescribed "
                << r.prescribed << " (" << std::showpos << std::setprecision(3) << 100 * r.relative_error() << std::noshowpos
                << "%): the flow stopped (" << SMP::discrete_lie_flow_stop_reason_name(run.report.stop_reason) << ") after "
                << run.report.iterations << " iterations; " << share_hint(run.report.stop_reason) << "\n";
  if(!ok) throw disk_failure(s, input, outcome);
  return exit_code_of_ok_run(run.report, true);
}

} // namespace dlf_cli
