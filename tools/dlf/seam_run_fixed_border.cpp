// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// `dlf disk --seam` with a fixed-border initial map (tutte, mvc, dcp).

#include "seam_run_impl.h"

namespace dlf_cli {

Disk_run run_seamed_disk_fixed_border(const Indexed_mesh& input, const Seam_cut& cut, const Disk_settings& settings)
{
  return with_seam_mesh(input, cut, [&](Seam_mesh& mesh, Seam_halfedge bhd, Seam_vertex_index_map vimap) {
    return run_fixed_border_init<Seam_mesh>(
      settings, [&](const auto& init) { return run_disk_on(mesh, bhd, vimap, init, settings); });
  });
}

} // namespace dlf_cli
