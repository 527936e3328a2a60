// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A spherical map as an SVG picture: two orthographic views of the unit
// sphere, from +z and from −z, each triangle drawn once in the view it faces,
// filled by its log area ratio on the scale of the uv layout picture, the
// regions of interest shaded.

#ifndef DLF_CLI_SVG_SPHERE_H
#define DLF_CLI_SVG_SPHERE_H

#include "arguments.h"
#include "mesh_input.h"

#include <ostream>
#include <string>
#include <vector>

namespace dlf_cli {

/// `sphere`: per input vertex, a point on the unit sphere; `face_density`:
/// per face, empty for ρ ≡ 1; `shaded`: faces (increasing) shaded on top.
void write_svg_sphere(std::ostream& out, const Indexed_mesh& mesh, const std::vector<Vec3>& sphere,
                      const std::string& caption, const Svg_options& style,
                      const std::vector<double>& face_density = std::vector<double>(),
                      const std::vector<int>& shaded = std::vector<int>());

} // namespace dlf_cli

#endif
