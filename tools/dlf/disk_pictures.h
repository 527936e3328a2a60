// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The pictures `dlf disk` writes on request: the uv layout (--svg), the
// convergence plot, the histograms of log area ratios and the textured OBJ
// (OBJ + MTL + checkerboard PNG), all through `Output_files`.

#ifndef DLF_CLI_DISK_PICTURES_H
#define DLF_CLI_DISK_PICTURES_H

#include "arguments.h"
#include "density_input.h"
#include "disk_run.h"
#include "output_files.h"

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace dlf_cli {

/// Declares every picture file `settings` asks for (see `Output_files::declare()`).
void declare_pictures(Output_files& outputs, const Disk_settings& settings);

/// Writes them for a successful `run` of `mesh`; returns each file with the
/// seconds its writing took. When `mesh` is the input cut along seams,
/// `input` is the input: the textured OBJ's `v` and faces are its, and the
/// faces of `mesh` index the `vt` (per-corner uv); the layout draws `mesh`.
std::vector<std::pair<std::string, double> > write_pictures(Output_files& outputs, const Disk_settings& settings,
                                                           const Indexed_mesh& mesh, const Disk_run& run,
                                                           const Density_setup& density, const std::string& caption,
                                                           const Indexed_mesh* input = nullptr);

/// The faces of every region of interest, increasing, each once.
std::vector<int> region_faces(const Density_setup& density);

/// The edges between faces of different density, when the density takes at
/// most `max_levels` values (a piecewise-constant density: its pieces'
/// outlines); empty otherwise.
std::vector<std::array<int, 2> > density_outline(const Indexed_mesh& mesh, const std::vector<double>& face_density,
                                                 std::size_t max_levels = 16);

} // namespace dlf_cli

#endif
