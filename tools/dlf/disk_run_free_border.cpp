// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The free-border initial maps: LSCM and ARAP, both pinned by two vertices
// (CGAL's Two_vertices_parameterizer_3, their default border).

#include "disk_run_inits.h"

namespace dlf_cli {

Disk_run run_disk_free_border(const Indexed_mesh& mesh, const Disk_settings& settings)
{
  return run_free_border_init<Surface_mesh>(settings,
                                            [&](const auto& init) { return run_disk_with(mesh, init, settings); });
}

} // namespace dlf_cli
