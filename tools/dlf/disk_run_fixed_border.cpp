// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The fixed-border initial maps: {Tutte, mean value, discrete conformal} ×
// {circle, square}, each with the direct solver.

#include "disk_run_inits.h"

namespace dlf_cli {

Disk_run run_disk_fixed_border(const Indexed_mesh& mesh, const Disk_settings& settings)
{
  return run_fixed_border_init<Surface_mesh>(settings,
                                             [&](const auto& init) { return run_disk_with(mesh, init, settings); });
}

} // namespace dlf_cli
