// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "arguments.h"
#include "cli_error.h"
#include "cli_util.h"

#include <boost/program_options.hpp>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <sstream>

namespace dlf_cli {

namespace po = boost::program_options;
namespace SMP = CGAL::Surface_mesh_parameterization;

namespace {

// Long options only by their full name: a guessed prefix would silently
// change meaning when an option is added.
const int parser_style = po::command_line_style::default_style & ~po::command_line_style::allow_guessing;

void require_one_of(const std::string& option, const std::string& value, const std::vector<std::string>& allowed)
{
  for(const std::string& a : allowed)
    if(value == a) return;
  std::string list;
  for(std::size_t k = 0; k < allowed.size(); ++k) list += (k == 0 ? "" : k + 1 == allowed.size() ? " or " : ", ") + allowed[k];
  throw Cli_error("invalid value '" + value + "' for --" + option + " (expected " + list + ")");
}

// Parses, turning Boost's exceptions into one-line usage errors. `ordered`,
// if given, receives the options in command-line order.
po::variables_map parse(const std::string& command, const std::vector<std::string>& args,
                        const po::options_description& visible, const std::string& positional_name,
                        std::vector<po::option>* ordered = nullptr)
{
  po::options_description all;
  all.add(visible);
  all.add_options()(positional_name.c_str(), po::value<std::vector<std::string> >());
  po::positional_options_description positional;
  positional.add(positional_name.c_str(), -1);
  po::variables_map vm;
  try {
    const po::parsed_options parsed = po::command_line_parser(args).options(all).positional(positional).style(parser_style).run();
    po::store(parsed, vm);
    po::notify(vm);
    if(ordered) *ordered = parsed.options;
  } catch(const po::error& e) {
    throw Cli_error(std::string(e.what()) + " (see 'dlf " + command + " --help')");
  }
  return vm;
}

bool parse_number(const std::string& token, double& x)
{
  char* end = nullptr;
  x = std::strtod(token.c_str(), &end);
  return !token.empty() && end == token.c_str() + token.size();
}

// `--roi-ball X Y Z R` takes four values, some of which may look like options
// (-0.5): glue them to the option before Boost sees them.
std::vector<std::string> glue_roi_ball(const std::vector<std::string>& args)
{
  std::vector<std::string> out;
  for(std::size_t k = 0; k < args.size(); ++k) {
    if(args[k] != "--roi-ball") { out.push_back(args[k]); continue; }
    std::string values;
    for(std::size_t j = 1; j <= 4; ++j) {
      double x;
      if(k + j >= args.size() || !parse_number(args[k + j], x))
        throw Cli_error("--roi-ball expects four numbers X Y Z R" +
                        (k + j < args.size() ? ", got '" + args[k + j] + "'" : std::string(", got ") + std::to_string(j - 1)));
      values += (j == 1 ? "" : " ") + args[k + j];
    }
    out.push_back("--roi-ball=" + values);
    k += 4;
  }
  return out;
}

Region_option ball_region(const std::string& value)
{
  std::istringstream in(value);
  std::string token;
  Region_option r;
  int n = 0;
  while(in >> token) {
    double x;
    if(n == 4 || !parse_number(token, x)) throw Cli_error("--roi-ball expects four numbers X Y Z R, got '" + value + "'");
    r.ball[std::size_t(n++)] = x;
  }
  if(n != 4) throw Cli_error("--roi-ball expects four numbers X Y Z R, got '" + value + "'");
  if(!(r.ball[3] > 0) || !std::isfinite(r.ball[3]) || !std::isfinite(r.ball[0] + r.ball[1] + r.ball[2]))
    throw Cli_error("--roi-ball: the centre must be finite and the radius a positive number, got '" + value + "'");
  return r;
}

// The regions and their factors, in command-line order: the k-th --factor
// belongs to the k-th region.
std::vector<Region_option> regions_of(const std::vector<po::option>& ordered)
{
  std::vector<Region_option> regions;
  std::vector<double> factors;
  for(const po::option& o : ordered) {
    if(o.value.empty()) continue;
    if(o.string_key == "roi") {
      Region_option r;
      r.selection_file = o.value[0];
      regions.push_back(r);
    } else if(o.string_key == "roi-ball") {
      regions.push_back(ball_region(o.value[0]));
    } else if(o.string_key == "factor") {
      double f;
      if(!parse_number(o.value[0], f) || !(f > 0) || !std::isfinite(f))
        throw Cli_error("--factor must be a positive number, got '" + o.value[0] + "'");
      factors.push_back(f);
    }
  }
  if(regions.size() != factors.size())
    throw Cli_error(std::to_string(regions.size()) + " region" + (regions.size() == 1 ? "" : "s") + " (--roi, --roi-ball) but " +
                    std::to_string(factors.size()) + " --factor: give one --factor per region (the k-th --factor "
                    "belongs to the k-th region)");
  for(std::size_t k = 0; k < regions.size(); ++k) regions[k].factor = factors[k];
  return regions;
}

std::vector<std::string> positionals(const po::variables_map& vm, const std::string& name)
{
  return vm.count(name) ? vm[name].as<std::vector<std::string> >() : std::vector<std::string>();
}

const char* disk_examples =
  "Examples:\n"
  "  dlf disk face.off -o face_uv.obj\n"
  "      area-preserving map onto a disk (Tutte initial map, certified flow)\n"
  "  dlf disk face.off -o face_uv.obj --border square --svg face.svg --report face.json\n"
  "      onto a square, with a picture of the area ratios and a JSON report\n"
  "  dlf disk face.off -o face_uv.obj --init lscm\n"
  "      free border: the border keeps the shape of the LSCM map\n"
  "  dlf disk lion.off -o lion_uv.obj --outer-loop 1\n"
  "      a mesh with holes: its second-longest loop goes to the circle, the other loops float\n"
  "  dlf disk face.off --mode paper --history --report paper.json --domain-mesh flipped.obj\n"
  "      the paper's algorithm (edge flips), its per-iteration history and flipped triangulation\n"
  "  dlf disk face.off -o face_uv.obj --roi-ball 0.1 -0.2 0.5 0.3 --factor 4 --band 0.1 --svg roi.svg\n"
  "      measure control: the faces in the ball get 4 times their share of the domain area\n"
  "  dlf disk face.off -o face_uv.obj --svg face.svg --texture face_tex.obj --plot-convergence conv.svg\n"
  "           --plot-histogram hist.svg\n"
  "      every picture: layout, textured mesh (face_tex.obj + .mtl + .png), convergence, histograms\n"
  "  dlf disk blob.off -o blob_uv.obj --seam blob.selection.txt --texture blob_tex.obj\n"
  "      cut along seams first (CGAL's Seam_mesh); the OBJs have one vt per seam side, f v/vt\n"
  "  dlf disk face.off -o face_uv.obj --density rho.txt --report rho.json\n"
  "      a density per face or per vertex (plain-text numbers), density-weighted metrics\n"
  "  dlf score face.off face_uv.obj\n"
  "      the distortion of a map written by 'dlf disk' (or any per-vertex uv OBJ)\n"
  "  dlf score blob_uv.obj\n"
  "      the same, the mesh read from the OBJ itself (e.g. a map with seams, per-corner uv)\n"
  "  dlf info face.off\n"
  "      topology and degeneracies of a mesh, and which command fits it\n"
  "\n"
  "Progress: one line per iteration (iteration, step, residual, d_area, elapsed), rewritten in\n"
  "place when stdout is a terminal, plain lines otherwise; -q silences it, -v adds details.\n"
  "\n"
  "Exit status: 0 success (converged), 1 usage error or unsuitable input (unreadable, not a\n"
  "disk, degenerate triangles, ...), 2 the flow failed (e.g. the initial map folds), 3 a\n"
  "valid, fold-free map was written but the flow stopped short of its targets (iteration\n"
  "cap, plateau, stall: status \"not_converged\", with what to try on stderr). When the\n"
  "parameterizer reports an error, only the report is written, with the error's status.\n";

} // namespace

void print_main_help(std::ostream& out)
{
  out << "dlf: Discrete Lie Flow, area-preserving parameterization (CGAL Surface_mesh_parameterization)\n"
         "\n"
         "Usage:\n"
         "  dlf disk INPUT [options]        map a disk-topology triangle mesh onto the plane\n"
         "  dlf atlas MESH -o OUT.obj       any mesh (components, genus, polygons) to an area-preserving atlas\n"
         "  dlf score [MESH] PARAM.obj      measure the distortion of an existing map\n"
         "  dlf sphere INPUT [options]      map a closed genus-0 mesh onto the unit sphere\n"
         "  dlf volume MESH.mesh [options]  map a tetrahedral mesh of a ball into the unit ball\n"
         "  dlf tetrahedralize SURFACE -o OUT.mesh  tetrahedra of a closed surface's solid (Mesh_3)\n"
         "  dlf info MESH                   topology and degeneracy report; which command fits\n"
         "\n"
         "'dlf COMMAND --help' lists the options of a command.\n\n"
      << disk_examples;
}

std::string Region_option::name() const
{
  if(!label.empty()) return label;
  if(!selection_file.empty()) return "roi " + selection_file;
  std::ostringstream s;
  s << "roi-ball " << ball[0] << ' ' << ball[1] << ' ' << ball[2] << ' ' << ball[3];
  return s.str();
}

/// The library's mode of a --mode value (checked before).
SMP::Discrete_lie_flow_mode mode_of(const std::string& mode)
{
  return mode == "paper" ? SMP::Discrete_lie_flow_mode::PAPER
       : mode == "literal" ? SMP::Discrete_lie_flow_mode::LITERAL : SMP::Discrete_lie_flow_mode::CERTIFIED;
}

/// The options that one mode alone reads, refused with the others.
void check_mode_options(const po::variables_map& vm, const std::string& mode, const SMP::Discrete_lie_flow_options& opt)
{
  if(mode != "paper") {
    if(vm.count("literal-targets")) throw Cli_error("--literal-targets applies to --mode paper only");
    if(vm.count("no-flips")) throw Cli_error("--no-flips applies to --mode paper only");
  }
  if(vm.count("threshold") && !vm["threshold"].defaulted()) {
    if(mode != "literal") throw Cli_error("--threshold applies to --mode literal only");
    if(!(opt.paper.residual_threshold > 0) || !std::isfinite(opt.paper.residual_threshold))
      throw Cli_error("--threshold must be a number > 0");
  }
  if(vm.count("fixed-step") && !(opt.fixed_step > 0 && std::isfinite(opt.fixed_step)))
    throw Cli_error("--fixed-step must be a number > 0");
}

void add_svg_options(po::options_description& o, Svg_options& svg)
{
  o.add_options()
    ("svg-colour", po::value<std::string>(&svg.colour)->value_name("C"),
     "what --svg colours: raw, domain / surface area in the density's unit (a face of density 1 keeps its "
     "area: a region of --factor 4 shows 4), the default with a density or region; or prescribed, "
     "domain / (density x surface): 1 wherever the map reached its target, the default otherwise")
    ("svg-scale", po::value<std::string>(&svg.scale)->value_name("S")->default_value(svg.scale),
     "fitted: a scale 1/E to E, E the run's largest ratio or inverse ratio (rounded up to 2 digits, at "
     "least 1.1); fixed: 1/4 to 4 whatever the run")
    ("svg-max-faces", po::value<std::size_t>(&svg.max_faces)->value_name("N")->default_value(svg.max_faces),
     "--svg of more than N triangles draws them as one embedded PNG, 2 pixels a unit of the picture "
     "(a polygon takes about 100 bytes: the file stays under about 5 MB)");
}

void check_svg_options(const po::variables_map& vm, bool has_svg, bool has_density, Svg_options& svg)
{
  for(const char* name : { "svg-colour", "svg-scale", "svg-max-faces" })
    if(vm.count(name) && !vm[name].defaulted() && !has_svg) throw Cli_error(std::string("--") + name + " applies to --svg only");
  if(svg.colour.empty()) svg.colour = has_density ? "raw" : "prescribed";
  require_one_of("svg-colour", svg.colour, { "prescribed", "raw" });
  require_one_of("svg-scale", svg.scale, { "fitted", "fixed" });
  if(svg.max_faces < 1) throw Cli_error("--svg-max-faces must be >= 1");
}

namespace {

/// The numbers of `dlf disk` parsed apart from its settings: their checks
/// come first, their values go into the options last.
struct Disk_numbers
{
  double tolerance = 0, mu = 0;
  long long max_iterations = 0;
};

/// The options of `dlf disk`, bound to `s` and `n`.
void add_disk_options(po::options_description& o, Disk_settings& s, Disk_numbers& n, const std::string& tolerance_help)
{
  o.add_options()
    ("help,h", "show this help")
    ("output,o", po::value<std::string>(&s.output)->value_name("OUT.obj"),
     "write the map: v = input positions, vt = uv (same vertex order), f a/a b/b c/c; with --seam, "
     "one vt per side of a seam and f a/p b/q c/r")
    ("seam", po::value<std::string>(&s.seam)->value_name("SEAM.selection.txt"),
     "cut the mesh open along seams and map the cut surface (through CGAL's Seam_mesh), which must be a "
     "disk: a CGAL selection file whose line 3 lists the seam edges as pairs of vertex indices; if line 3 "
     "is empty, the vertices of line 1 are joined by shortest edge paths")
    ("mode", po::value<std::string>(&s.mode)->value_name("M")->default_value("certified"),
     "certified: never folds the input triangles; paper: the paper's flow with edge flips, stabilised "
     "(line search, collapse guard, plateau tests); literal: Algorithm 1 as printed (step mu * min critical "
     "step, stop when ||h_M - h_Omega||^2 < --threshold; a collapse ends the run)")
    ("init", po::value<std::string>(&s.init)->value_name("I")->default_value("tutte"),
     "initial map: tutte, mvc (mean value), dcp (discrete conformal) with a circle or square border; "
     "lscm, arap with a free border")
    ("init-uv", po::value<std::string>(&s.init_uv_file)->value_name("MAP.obj"),
     "the caller's own initial map instead of --init: an OBJ of the input with one vt (or a flat v) per "
     "vertex, flip-free; any domain, convex or not (the paper's Fig. 10): the border slides along its polygon "
     "(--border free)")
    ("border", po::value<std::string>(&s.border)->value_name("B"),
     "circle or square (tutte, mvc, dcp; default circle), or free: the border slides along the initial "
     "map's border (the only choice, and the default, for lscm and arap)")
    ("outer-loop", po::value<int>(&s.outer_loop)->value_name("K")->default_value(0),
     "a mesh with holes (genus 0, several border loops): the loop that goes to the border, counted from 0 "
     "in the order of 'dlf info' (longest first, by 3D length); the others are holes and float")
    ("report", po::value<std::string>(&s.report)->value_name("R.json"), "write a JSON report (status, metrics, timings)")
    ("csv", po::value<std::string>(&s.csv)->value_name("R.csv"),
     "write the report as CSV: a header and one row, the JSON report's keys flattened (final.d_area, seconds.flow)")
    ("domain-mesh", po::value<std::string>(&s.domain_mesh)->value_name("DOMAIN.obj"),
     "write the final domain triangulation (differs from the input's in paper mode)")
    ("svg", po::value<std::string>(&s.svg)->value_name("LAYOUT.svg"),
     "draw the uv layout, triangles coloured by area ratio (--svg-colour), with a colour bar and the regions "
     "of interest shaded and outlined (or the outlines of the pieces of a piecewise-constant --density)");
  add_svg_options(o, s.svg_options);
  o.add_options()
    ("plot-convergence", po::value<std::string>(&s.convergence_svg)->value_name("PLOT.svg"),
     "plot d_area - 2 and the area residual per iteration (log scale)")
    ("plot-histogram", po::value<std::string>(&s.histogram_svg)->value_name("PLOT.svg"),
     "histograms of the per-face log area ratios of the initial map and of the result")
    ("texture", po::value<std::string>(&s.texture_obj)->value_name("NAME.obj"),
     "write NAME.obj (uv scaled into [0,1]^2), NAME.mtl and NAME.png (a checkerboard): the mesh opens "
     "textured in MeshLab or Blender")
    ("texture-size", po::value<int>(&s.texture_size)->value_name("N")->default_value(s.texture_size),
     "pixels a side of the checkerboard PNG (16 x 16 squares)")
    ("tolerance", po::value<double>(&n.tolerance)->value_name("X")->default_value(n.tolerance),
     tolerance_help.c_str())
    ("max-iterations", po::value<long long>(&n.max_iterations)->value_name("N")->default_value(n.max_iterations),
     "iteration cap")
    ("mu", po::value<double>(&n.mu)->value_name("X"),
     "fraction in (0, 1) of the smallest critical step that a step may take (default: the mode's own)")
    ("fixed-step", po::value<double>(&s.options.fixed_step)->value_name("X"),
     "a fixed step X > 0 instead of the adaptive one (the paper's Table 2); literal mode: a step that "
     "folds the flowing mesh ends the run as collapsed, other modes: as stalled")
    ("threshold", po::value<double>(&s.options.paper.residual_threshold)->value_name("X")
       ->default_value(s.options.paper.residual_threshold),
     "literal mode: stop when ||h_M - h_Omega||^2 < X, vertex area elements in units of their mean")
    ("literal-targets", "paper mode: lump the target areas once on the input triangles (Algorithm 1 read literally)")
    ("no-flips", "paper mode: no Delaunay edge flips")
    ("density", po::value<std::string>(&s.density_file)->value_name("FILE"),
     "measure control: a density > 0 per face, or per vertex (a face takes the mean of its corners), "
     "as plain text (numbers separated by white space, '#' comments); the domain area of a face "
     "becomes proportional to density times area")
    ("roi", po::value<std::vector<std::string> >()->composing()->value_name("FILE"),
     "a region of interest: a CGAL selection file (*.selection.txt: line 1 vertex indices, line 2 face "
     "indices; without faces, the faces whose 3 vertices are selected); needs --factor")
    ("roi-ball", po::value<std::vector<std::string> >()->composing()->value_name("X Y Z R"),
     "a region of interest: the faces whose centroid lies in this ball; needs --factor")
    ("factor", po::value<std::vector<double> >()->composing()->value_name("F"),
     "density of a region (> 0: 4 gives it 4 times its share of the domain area); the k-th --factor "
     "belongs to the k-th --roi or --roi-ball, and overlapping regions multiply")
    ("band", po::value<double>(&s.band)->value_name("W"),
     "width (3D length, along edges) of a transition from each region's factor to 1 around it")
    ("share-tolerance", po::value<double>(&s.options.certified.share_tolerance)->value_name("X")->default_value(s.options.certified.share_tolerance, shortest_text(s.options.certified.share_tolerance)),
     "with a density, certified mode: converged also needs every region of the density (every set of faces below or above "
     "a density value) within X of its prescribed share of the domain area, relative (0: d_area alone decides)")
    ("coarse-to-fine-faces", po::value<std::size_t>(&s.options.disk.coarse_to_fine_faces)->value_name("N")
       ->default_value(s.options.disk.coarse_to_fine_faces),
     "certified mode: a disk of N faces or more flows coarse to fine (coarser disks made by collapses flowed "
     "first, their map carried down; 0: never)")
    ("history", "add the per-iteration history to the report")
    ("quiet,q", "print nothing on success (no progress, no summary)")
    ("verbose,v", "progress with the step's details (critical step, limiting face, backtracks), never "
     "overwritten, and the time spent writing each output");
}

/// The checks of the parsed command line, in the order of their messages;
/// the region's tolerance into `n` with a density.
void check_disk_arguments(const po::variables_map& vm, const std::vector<po::option>& ordered, Disk_settings& s,
                          Disk_numbers& n)
{
  require_one_of("mode", s.mode, { "certified", "paper", "literal" });
  require_one_of("init", s.init, { "tutte", "mvc", "dcp", "lscm", "arap" });
  if(!s.init_uv_file.empty()) {
    if(!vm["init"].defaulted()) throw Cli_error("--init-uv and --init exclude each other");
    if(!s.seam.empty()) throw Cli_error("--init-uv applies to meshes without --seam");
    if(!s.border.empty() && s.border != "free")
      throw Cli_error("--init-uv keeps the map's own border: --border free only");
    s.init = "uv";
    s.border = "free";
  }
  if(s.border.empty()) s.border = has_fixed_border(s.init) ? "circle" : "free";
  require_one_of("border", s.border, { "circle", "square", "free" });
  if(!has_fixed_border(s.init) && s.border != "free")
    throw Cli_error("--border " + s.border + " needs a fixed-border initial map (--init tutte, mvc or dcp); " +
                    s.init + " gives a free border");
  if(!(n.tolerance >= 0) || !std::isfinite(n.tolerance)) throw Cli_error("--tolerance must be a number >= 0");
  if(vm.count("mu") && !(n.mu > 0 && n.mu < 1)) throw Cli_error("--mu must be in (0, 1)");
  if(n.max_iterations < 0) throw Cli_error("--max-iterations must be >= 0");
  if(s.outer_loop < 0) throw Cli_error("--outer-loop must be >= 0");
  // Below 16 pixels a side the 16 squares vanish; above 16384 the PNG is huge.
  if(s.texture_size < 16 || s.texture_size > 16384) throw Cli_error("--texture-size must be in [16, 16384]");
  if(vm.count("texture-size") && !vm["texture-size"].defaulted() && s.texture_obj.empty())
    throw Cli_error("--texture-size applies to --texture only");
  read_region_arguments(vm, ordered, s);
  if(!(s.options.certified.share_tolerance >= 0) || !std::isfinite(s.options.certified.share_tolerance))
    throw Cli_error("--share-tolerance must be a number >= 0");
  if(s.has_density() && vm["tolerance"].defaulted()) n.tolerance = density_tolerance;
  check_svg_options(vm, !s.svg.empty(), s.has_density(), s.svg_options);
  check_mode_options(vm, s.mode, s.options);
}

/// The flow's options from the checked settings.
void set_disk_flow_options(const po::variables_map& vm, Disk_settings& s, const Disk_numbers& n)
{
  SMP::Discrete_lie_flow_options& opt = s.options;
  opt.mode = mode_of(s.mode);
  opt.disk.border = s.border == "circle" ? SMP::Discrete_lie_flow_border::CIRCLE
             : s.border == "square" ? SMP::Discrete_lie_flow_border::SQUARE : SMP::Discrete_lie_flow_border::FREE;
  opt.tolerance = n.tolerance;
  opt.mu = n.mu;
  opt.max_iterations = std::size_t(n.max_iterations);
  opt.paper.lump_targets_on_flowing_faces = vm.count("literal-targets") == 0;
  opt.paper.delaunay_flips = vm.count("no-flips") == 0;
  s.history_in_report = vm.count("history") != 0;
  opt.record_history = s.history_in_report || !s.convergence_svg.empty();
}

} // namespace

bool parse_disk_arguments(const std::vector<std::string>& args, Disk_settings& s)
{
  const SMP::Discrete_lie_flow_options defaults;
  Disk_numbers n;
  n.tolerance = defaults.tolerance;
  n.mu = defaults.mu;
  n.max_iterations = (long long)(defaults.max_iterations);

  std::ostringstream tolerance_help;
  tolerance_help << "stop when d_area - 2 <= X (" << density_tolerance << " when a density or region is given)";

  po::options_description o("Options");
  add_disk_options(o, s, n, tolerance_help.str());
  std::vector<po::option> ordered;
  const po::variables_map vm = parse("disk", glue_roi_ball(args), o, "input", &ordered);
  if(vm.count("help")) {
    std::cout << "Usage: dlf disk INPUT [options]\n\n"
                 "Area-preserving parameterization of a disk-topology triangle mesh (any format CGAL\n"
                 "reads: OFF, OBJ, PLY, STL) by the Discrete Lie Flow; with --density, --roi or\n"
                 "--roi-ball, measure-controlled: each face gets density times its share of the area;\n"
                 "with --seam, of any mesh that its seams cut open into a disk.\n\n"
              << o << "\n" << disk_examples;
    return false;
  }
  const std::vector<std::string> inputs = positionals(vm, "input");
  if(inputs.empty()) throw Cli_error("missing INPUT mesh (see 'dlf disk --help')");
  if(inputs.size() > 1) throw Cli_error("one INPUT mesh expected, got '" + inputs[0] + "' and '" + inputs[1] + "'");
  s.input = inputs[0];
  set_verbosity(vm, s.verbosity);

  check_disk_arguments(vm, ordered, s, n);
  set_disk_flow_options(vm, s, n);
  return true;
}

bool parse_score_arguments(const std::vector<std::string>& args, Score_settings& s)
{
  po::options_description o("Options");
  o.add_options()
    ("help,h", "show this help")
    ("report", po::value<std::string>(&s.report)->value_name("R.json"), "write the metrics as JSON")
    ("csv", po::value<std::string>(&s.csv)->value_name("R.csv"),
     "write the same as CSV: a header and one row, the JSON's keys flattened (metrics.d_area)")
    ("quiet,q", "print nothing on success")
    ("verbose,v", "same as the default");
  const po::variables_map vm = parse("score", args, o, "files");
  if(vm.count("help")) {
    std::cout << "Usage: dlf score [MESH] PARAM.obj [--report R.json] [--csv R.csv]\n\n"
                 "Distortion metrics (d_area, arap, symmetric Dirichlet, log area ratio, inverted and\n"
                 "degenerate faces, smallest angle, the paper's Table 1 'Wasserstein distance' and\n"
                 "Area_total of the faces' area shares, Beltrami coefficient |mu|) of the map of MESH's\n"
                 "triangles given by PARAM.obj:\n"
                 "its 'vt' lines, one per MESH vertex in order (as 'dlf disk' writes them), or, without\n"
                 "'vt', the x and y of its 'v' lines when all z are 0. When its faces 'f a/p b/q c/r'\n"
                 "name other 'vt' than their 'v' (per-corner uv: a map with seams, as 'dlf disk --seam'\n"
                 "writes it), its faces must be MESH's, and the metrics are those of MESH cut open, one\n"
                 "vertex per 'vt'. Without MESH, the mesh is PARAM.obj's own 'v' and 'f'.\n"
                 "A per-corner map is also scored as an atlas, whoever made it: charts, seam length,\n"
                 "packing efficiency, D_area, folded and degenerate uv triangles, overlapping uv\n"
                 "triangle pairs (exact; 'atlas' in the report).\n\n"
              << o;
    return false;
  }
  const std::vector<std::string> files = positionals(vm, "files");
  if(files.empty() || files.size() > 2)
    throw Cli_error("expected [MESH] PARAM.obj, got " + std::to_string(files.size()) + " file names (see 'dlf score --help')");
  s.mesh = files[0];
  s.parameterization = files.back();
  set_verbosity(vm, s.verbosity);
  return true;
}

std::vector<std::string> glue_region_balls(const std::vector<std::string>& args) { return glue_roi_ball(args); }

po::variables_map parse_command_line(const std::string& command, const std::vector<std::string>& args,
                                     const po::options_description& visible, const std::string& positional_name,
                                     std::vector<po::option>* ordered)
{
  return parse(command, args, visible, positional_name, ordered);
}

std::vector<std::string> positional_arguments(const po::variables_map& vm, const std::string& name)
{
  return positionals(vm, name);
}

void set_verbosity(const po::variables_map& vm, Verbosity& verbosity)
{
  if(vm.count("quiet") && vm.count("verbose")) throw Cli_error("--quiet and --verbose exclude each other");
  if(vm.count("quiet")) verbosity = Verbosity::QUIET;
  if(vm.count("verbose")) verbosity = Verbosity::VERBOSE;
}

void read_region_arguments(const po::variables_map& vm, const std::vector<po::option>& ordered, Disk_settings& s)
{
  s.regions = regions_of(ordered);
  if(!s.density_file.empty() && !s.regions.empty()) throw Cli_error("--density and --roi/--roi-ball exclude each other");
  if(vm.count("band") && s.regions.empty()) throw Cli_error("--band applies to --roi and --roi-ball only");
  if(!(s.band >= 0) || !std::isfinite(s.band)) throw Cli_error("--band must be a number >= 0");
}

} // namespace dlf_cli
