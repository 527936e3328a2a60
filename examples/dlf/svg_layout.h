// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The uv layout as an SVG picture: each triangle filled by its log area
// ratio (domain / surface, after the uniform scaling of the metrics) on a
// diverging blue–white–red scale clamped at ±log 4, with a colour bar.

#ifndef DLF_CLI_SVG_LAYOUT_H
#define DLF_CLI_SVG_LAYOUT_H

#include "mesh_input.h"

#include <ostream>
#include <string>
#include <vector>

namespace dlf_cli {

void write_svg_layout(std::ostream& out, const Indexed_mesh& mesh, const std::vector<Vec2>& uv,
                      const std::string& caption);

} // namespace dlf_cli

#endif
