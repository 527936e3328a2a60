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

#include <nlohmann/json.hpp>

#include <array>
#include <cstddef>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace dlf_cli {

/// A region of interest on the input mesh and its share of the domain area.
struct Density_region
{
  std::string name;          ///< as the command line gave it
  double factor = 1;
  std::vector<int> faces;    ///< input face indices, increasing
  double surface = 0;        ///< Σ_region area / Σ area: its share of the surface
  double mean_density = 1;   ///< Σ_region ρ·area / Σ_region area
  double prescribed = 0;     ///< Σ_region ρ·area / Σ ρ·area
  double achieved = 0;       ///< Σ_region domain area / Σ domain area (after measure_regions())
  double relative_error() const { return (achieved - prescribed) / prescribed; }
  /// Its domain area over its surface area, the domain scaled to the area
  /// Σ ρ·area (a face of density 1 that reached its target keeps its area):
  /// what the layout's raw colours show, `mean_density` when the share is
  /// reached (the factor, for a region that no other overlaps). Not
  /// achieved / surface, which the renormalisation of the whole pulls
  /// towards 1 as the region grows.
  double magnification() const { return achieved / prescribed * mean_density; }
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

/// Per region, the report's entry: name, factor, faces, its share of the
/// surface (`surface_fraction`), of the domain prescribed (ρ·area) and
/// achieved, the relative error, reached or not, and the magnification
/// achieved and prescribed (`Density_region::magnification()`); the
/// achieved values null unless `measured` (the flow failed).
nlohmann::ordered_json regions_json(const Density_setup& setup, bool measured);

/// The same, one line a region, for the summary; `domain` names it ("domain", "sphere").
void print_regions(std::ostream& out, const Density_setup& setup, const std::string& domain, bool measured);

/// The edges (vertex pairs) that bound the union of `faces`: those with a
/// region face on one side only.
std::vector<std::array<int, 2> > region_outline(const Indexed_mesh& mesh, const std::vector<int>& faces);

} // namespace dlf_cli

#endif
