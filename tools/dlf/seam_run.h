// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// `dlf disk --seam`: the run on CGAL's Seam_mesh over the input's
// Surface_mesh, with the initial map the command line names.

#ifndef DLF_CLI_SEAM_RUN_H
#define DLF_CLI_SEAM_RUN_H

#include "disk_run.h"
#include "seam_input.h"

namespace dlf_cli {

/// Runs the flow on the Seam_mesh of `input` with the seams of `cut`; the
/// run's maps are indexed by the vertices of `cut.mesh` (one per seam side),
/// and so are the report's `domain_faces`. Throws `Cli_error` if CGAL's
/// Seam_mesh does not see the cut that `cut` describes.
/// tutte, mvc or dcp on a circle or a square:
Disk_run run_seamed_disk_fixed_border(const Indexed_mesh& input, const Seam_cut& cut, const Disk_settings& settings);
/// lscm or arap:
Disk_run run_seamed_disk_free_border(const Indexed_mesh& input, const Seam_cut& cut, const Disk_settings& settings);

inline Disk_run run_seamed_disk(const Indexed_mesh& input, const Seam_cut& cut, const Disk_settings& settings)
{
  return has_fixed_border(settings.init) ? run_seamed_disk_fixed_border(input, cut, settings)
                                         : run_seamed_disk_free_border(input, cut, settings);
}

} // namespace dlf_cli

#endif
