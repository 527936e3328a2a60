// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the tool's SVG pictures share: the diverging colour scale of log area
// ratios and its colour bar, per-face log area ratios, XML escaping.

#ifndef DLF_CLI_SVG_COMMON_H
#define DLF_CLI_SVG_COMMON_H

#include "mesh_input.h"

#include <ostream>
#include <string>
#include <vector>

namespace dlf_cli {

/// White at ratio 1, blue where the domain is too small, red where it is too
/// large, saturated at a factor `scale_end` (> 1) either way, as "#rrggbb".
const std::string& colour_of_log_ratio(double log_ratio, double scale_end = 4);

/// The end E of the scale 1/E to E: 4 when `fixed`; else fitted to the run,
/// the largest ratio or inverse ratio of `log_ratios` (NaN skipped) rounded
/// up to two significant digits, at least 1.1 (below, a converged map would
/// show its last percent of noise saturated).
double colour_scale_end(const std::vector<double>& log_ratios, bool fixed);

std::string xml_escape(const std::string& s);

/// The XML declaration, the `<svg>` element (ended by "</svg>\n"), a white
/// background and the caption as title and first line.
void write_svg_header(std::ostream& out, double width, double height, const std::string& caption);

/// The vertical colour bar of the scale 1/`scale_end` to `scale_end` at
/// (x, y), `height` tall, captioned by `quantity` (what the ratio divides,
/// at most two lines); the legend below it ends `colour_bar_legend` lower;
/// with a key for the black triangles when `has_bad_faces`. Its group
/// carries the scale as `data-scale-min` and `data-scale-max`.
void write_colour_bar(std::ostream& out, double x, double y, double height, bool has_bad_faces,
                      const std::string& quantity, double scale_end);
const double colour_bar_legend = 60;
/// The fixed 1/4 to 4 bar, of domain / surface or, `weighted`, domain / (ρ·surface).
void write_colour_bar(std::ostream& out, double x, double y, double height, bool has_bad_faces, bool weighted);

/// The bar's caption of the ratio a picture colours: raw (domain / surface)
/// or not (domain / (ρ·surface)), with a density or not.
std::string ratio_quantity(bool raw, bool has_density);

/// Per face: its surface area times its density (1 where `face_density` is empty).
std::vector<double> weighted_face_areas(const Indexed_mesh& mesh, const std::vector<double>& face_density);

/// Per face: log(area_Ω / (ρ area_M)) after the uniform scaling of the
/// metrics (the domain's total area made equal to Σ ρ area_M); NaN for a face
/// whose domain triangle is flat or, by the sign of its double-precision area,
/// against the majority orientation. Domain triangles are flat triangles
/// between the points of `domain` (2D: z = 0).
std::vector<double> face_log_area_ratios(const Indexed_mesh& mesh, const std::vector<Vec2>& domain,
                                         const std::vector<double>& face_density);
std::vector<double> face_log_area_ratios(const Indexed_mesh& mesh, const std::vector<Vec3>& domain,
                                         const std::vector<double>& face_density);

} // namespace dlf_cli

#endif
