// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// One run of Discrete_lie_flow_parameterizer_3 with the initial map the
// command line names, on a Surface_mesh whose vertex indices are the input's.

#ifndef DLF_CLI_DISK_RUN_H
#define DLF_CLI_DISK_RUN_H

#include "arguments.h"
#include "mesh_input.h"

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_parameterizer_3.h>

#include <vector>

namespace dlf_cli {

struct Disk_run
{
  CGAL::Surface_mesh_parameterization::Error_code status = CGAL::Surface_mesh_parameterization::OK;
  CGAL::Surface_mesh_parameterization::Discrete_lie_flow_report report;
  std::vector<Vec2> initial_uv; ///< the initial map, per input vertex; empty if it could not be computed
  std::vector<Vec2> final_uv;   ///< the result, per input vertex; empty unless status is OK
  double seconds = 0;           ///< the whole parameterize() call
};

/// Run the flow on `mesh` (a disk, checked) as `settings` say; one per
/// family of initial maps, each in its own translation unit.
/// tutte, mvc or dcp on a circle or a square:
Disk_run run_disk_fixed_border(const Indexed_mesh& mesh, const Disk_settings& settings);
/// lscm or arap:
Disk_run run_disk_free_border(const Indexed_mesh& mesh, const Disk_settings& settings);

inline Disk_run run_disk(const Indexed_mesh& mesh, const Disk_settings& settings)
{
  return has_fixed_border(settings.init) ? run_disk_fixed_border(mesh, settings) : run_disk_free_border(mesh, settings);
}

} // namespace dlf_cli

#endif
