// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Command lines of `dlf disk` and `dlf score` (Boost.Program_options), and
// the help texts.

#ifndef DLF_CLI_ARGUMENTS_H
#define DLF_CLI_ARGUMENTS_H

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_options.h>

#include <boost/program_options/option.hpp>
#include <boost/program_options/options_description.hpp>
#include <boost/program_options/variables_map.hpp>

#include <array>
#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

namespace dlf_cli {

enum class Verbosity { QUIET, NORMAL, VERBOSE };

/// A region of interest of `--roi FILE` or `--roi-ball X Y Z R`, with its `--factor`.
struct Region_option
{
  std::string selection_file;       ///< `--roi`: a CGAL selection file; empty for a ball
  std::array<double, 4> ball{};     ///< `--roi-ball`: centre x, y, z and radius
  std::vector<int> faces;           ///< the Python module's face indices (increasing); then neither of the above
  std::string label;                ///< the Python module's name of the region; empty: from the above
  double factor = 1;
  std::string name() const;         ///< as the command line gave it, for messages and the report
};

/// How `--svg` colours the triangles (`--svg-colour`, `--svg-scale`, `--svg-max-faces`).
struct Svg_options
{
  std::string colour;             ///< prescribed | raw; empty until resolved: raw with a density, else prescribed
  std::string scale = "fitted";   ///< fitted (to the run's range) | fixed (1/4 to 4)
  std::size_t max_faces = 50000;  ///< more faces than this: the triangles are drawn as one embedded PNG
  bool raw() const { return colour == "raw"; }
  bool fixed_scale() const { return scale == "fixed"; }
};

/// D_area − 2 at which a run with a density stops unless `--tolerance` is
/// given (measured: with the plain run's 1e-2 a region's share misses its
/// prescribed share by up to 13%; see doc/measure_control.md).
const double density_tolerance = 5e-4;

struct Disk_settings
{
  std::string input;
  std::string seam;                             ///< `--seam`: a CGAL selection file; empty: no cut
  std::vector<long> seam_pairs;                 ///< the Python module's seam edges (a0 b0 a1 b1 ...); then `seam` names them
  std::string output, report, domain_mesh, svg; ///< empty: not written
  std::string csv;                              ///< `--csv`: the report as one CSV row
  std::string convergence_svg, histogram_svg;   ///< `--plot-convergence`, `--plot-histogram`
  Svg_options svg_options;
  std::string texture_obj;                      ///< `--texture`: NAME.obj, with NAME.mtl and NAME.png
  int texture_size = 1024;                      ///< `--texture-size`: pixels a side
  bool history_in_report = false;               ///< `--history`
  std::string mode = "certified";               ///< certified | paper | literal
  std::string init = "tutte";                   ///< tutte | mvc | dcp | lscm | arap | uv (`--init-uv`)
  std::string init_uv_file;                     ///< `--init-uv`: the caller's initial map (OBJ)
  std::vector<std::array<double, 2> > init_uv;  ///< its uv per input vertex, once read
  std::string border;                           ///< circle | square | free (resolved from init if not given)
  std::string density_file;                     ///< `--density`: one value per face or per vertex
  std::vector<Region_option> regions;           ///< `--roi` / `--roi-ball`, in command-line order
  double band = 0;                              ///< `--band`: width of the transition to density 1
  int outer_loop = 0;                           ///< `--outer-loop`: the border loop mapped to the border (border_loops() order)
  std::vector<char> on_outer_loop;              ///< per input vertex, once the mesh is read: on that loop (empty: the only loop)
  CGAL::Surface_mesh_parameterization::Discrete_lie_flow_options options;
  Verbosity verbosity = Verbosity::NORMAL;
  bool has_density() const { return !density_file.empty() || !regions.empty(); }
};

struct Score_settings
{
  std::string mesh, parameterization, report, csv;
  Verbosity verbosity = Verbosity::NORMAL;
};

/// Parse the arguments that follow `dlf disk` / `dlf score`. Return false
/// when `--help` was asked (and printed); throw `Cli_error` on a usage error.
bool parse_disk_arguments(const std::vector<std::string>& args, Disk_settings& settings);
bool parse_score_arguments(const std::vector<std::string>& args, Score_settings& settings);

void print_main_help(std::ostream& out);

/// Parses the arguments of `dlf COMMAND` against `visible`, the remaining
/// words going to the positional option `positional_name`; long options only
/// by their full name. Boost's exceptions become one-line usage errors
/// (`Cli_error`). `ordered`, if given, receives the options in order.
boost::program_options::variables_map parse_command_line(const std::string& command, const std::vector<std::string>& args,
                                                         const boost::program_options::options_description& visible,
                                                         const std::string& positional_name,
                                                         std::vector<boost::program_options::option>* ordered = nullptr);

/// The words given to the positional option `name` (none: empty).
std::vector<std::string> positional_arguments(const boost::program_options::variables_map& vm, const std::string& name);

/// For the commands that take `--roi-ball X Y Z R` (whose values may look
/// like options): the arguments with each ball glued into one value.
std::vector<std::string> glue_region_balls(const std::vector<std::string>& args);

/// `-q` / `-v` into `verbosity`; both given: a usage error.
void set_verbosity(const boost::program_options::variables_map& vm, Verbosity& verbosity);

/// The regions of `--roi` / `--roi-ball` with the k-th `--factor`, in
/// command-line order, into `settings`; throws `Cli_error` on a missing or
/// bad factor, on regions beside `--density`, on `--band` without regions
/// or below 0.
void read_region_arguments(const boost::program_options::variables_map& vm,
                           const std::vector<boost::program_options::option>& ordered, Disk_settings& settings);

/// The options of `Svg_options`, for `dlf disk` and `dlf sphere`.
void add_svg_options(boost::program_options::options_description& options, Svg_options& svg);

/// Checks them (one of `--svg`, else refused) and resolves the colour's
/// default: raw when the run has a density (`has_density`), else prescribed.
void check_svg_options(const boost::program_options::variables_map& vm, bool has_svg, bool has_density, Svg_options& svg);

/// True for the fixed-border initial maps (convex border: circle or square).
/// The library's mode of a --mode value: certified, paper or literal.
CGAL::Surface_mesh_parameterization::Discrete_lie_flow_mode mode_of(const std::string& mode);

/// Refuses the options that another mode alone reads (--literal-targets,
/// --no-flips: paper; --threshold: literal) and bad --threshold or
/// --fixed-step values.
void check_mode_options(const boost::program_options::variables_map& vm, const std::string& mode,
                        const CGAL::Surface_mesh_parameterization::Discrete_lie_flow_options& options);

inline bool has_fixed_border(const std::string& init) { return init == "tutte" || init == "mvc" || init == "dcp"; }

} // namespace dlf_cli

#endif
