// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Measure control on the command line: the density of `--density FILE`, or
// the one that `--roi` / `--roi-ball` with `--factor` and `--band` build with
// the library's region helpers; and how much of the domain each region got.

#ifndef DLF_CLI_DENSITY_INPUT_H
#define DLF_CLI_DENSITY_INPUT_H

#include "arguments.h"
#include "mesh_input.h"

#include <array>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace dlf_cli {

/// A region of interest on the input mesh and its share of the domain area.
struct Density_region
{
  std::string name;          ///< as the command line gave it
  double factor = 1;
  std::vector<int> faces;    ///< input face indices, increasing
  double prescribed = 0;     ///< Σ_region ρ·area / Σ ρ·area
  double achieved = 0;       ///< Σ_region domain area / Σ domain area (after measure_regions())
  double relative_error() const { return (achieved - prescribed) / prescribed; }
};

struct Density_setup
{
  std::vector<double> face_density; ///< per input face; empty: ρ ≡ 1
  std::string source;               ///< "none", "face" or "vertex" (a --density file), "regions"
  std::vector<Density_region> regions;
};

/// A region whose achieved share misses its prescribed share by more than
/// this (relative) is reported as not reached.
const double region_share_tolerance = 0.01;

/// Reads `settings.density_file`, or builds the density of `settings.regions`
/// (ρ = Π_k ρ_k, ρ_k the factor of region k blended to 1 across the band);
/// fills each region's prescribed share. Throws `Cli_error` naming the file,
/// value or region at fault.
Density_setup make_density(const Indexed_mesh& mesh, const Disk_settings& settings);

/// The density of one value per face, or per vertex (a face takes the mean
/// of its corners; faces win when the counts agree), each > 0 and finite;
/// `where(k)` names the k-th value (or, for k == values.size(), the whole)
/// in messages. Throws `Cli_error`.
Density_setup density_of_values(const Indexed_mesh& mesh, const std::vector<double>& values,
                                const std::function<std::string(std::size_t)>& where);

/// The faces a CGAL selection file selects: its face line (line 2), or, when
/// that is empty, the faces whose three vertices its vertex line (line 1)
/// selects. Throws `Cli_error`.
std::vector<int> read_selection(const std::string& path, const Indexed_mesh& mesh);

/// Fills the achieved shares of `setup.regions` under the map `uv`.
void measure_regions(const Indexed_mesh& mesh, const std::vector<Vec2>& uv, Density_setup& setup);

/// The edges (vertex pairs) that bound the union of `faces`: those with a
/// region face on one side only.
std::vector<std::array<int, 2> > region_outline(const Indexed_mesh& mesh, const std::vector<int>& faces);

} // namespace dlf_cli

#endif
