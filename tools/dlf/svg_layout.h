// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The uv layout as an SVG picture: each triangle filled by its log area
// ratio (domain / surface, after the uniform scaling of the metrics; with a
// density, domain / (density × surface)) on a diverging blue–white–red scale
// clamped at ±log 4, with a colour bar; the outlines of regions of interest
// drawn on top.

#ifndef DLF_CLI_SVG_LAYOUT_H
#define DLF_CLI_SVG_LAYOUT_H

#include "mesh_input.h"

#include <array>
#include <ostream>
#include <string>
#include <vector>

namespace dlf_cli {

/// `face_density`: per face, empty for ρ ≡ 1. `outline`: edges (vertex
/// pairs) drawn as dark lines over the triangles, named in the legend by
/// `outline_label`.
void write_svg_layout(std::ostream& out, const Indexed_mesh& mesh, const std::vector<Vec2>& uv,
                      const std::string& caption,
                      const std::vector<double>& face_density = std::vector<double>(),
                      const std::vector<std::array<int, 2> >& outline = std::vector<std::array<int, 2> >(),
                      const std::string& outline_label = "region of interest");

} // namespace dlf_cli

#endif
