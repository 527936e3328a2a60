// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The uv layout as an SVG picture: each triangle filled by its log area
// ratio on a diverging blue–white–red scale (fitted to the run, or fixed at
// 1/4 to 4), with a colour bar; the regions of interest shaded and outlined
// on top. The ratio is domain / surface, the domain scaled to the area
// Σ ρ·surface: "raw", it is ρ wherever the map reached its target (a face of
// density 1 keeps its area); "prescribed", it is divided by ρ (1 there).

#ifndef DLF_CLI_SVG_LAYOUT_H
#define DLF_CLI_SVG_LAYOUT_H

#include "arguments.h"
#include "mesh_input.h"

#include <array>
#include <ostream>
#include <string>
#include <vector>

namespace dlf_cli {

/// `face_density`: per face, empty for ρ ≡ 1. `outline`: edges (vertex
/// pairs) drawn as dark lines over the triangles, named in the legend by
/// `outline_label`; `shaded`: faces (increasing) shaded under it.
void write_svg_layout(std::ostream& out, const Indexed_mesh& mesh, const std::vector<Vec2>& uv,
                      const std::string& caption, const Svg_options& style,
                      const std::vector<double>& face_density = std::vector<double>(),
                      const std::vector<std::array<int, 2> >& outline = std::vector<std::array<int, 2> >(),
                      const std::string& outline_label = "region of interest",
                      const std::vector<int>& shaded = std::vector<int>());

} // namespace dlf_cli

#endif
