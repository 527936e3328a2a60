// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// `dlf disk` without its files: check, flow and measure a mesh given as
// arrays, and build the JSON report of doc/design.md. The command line and
// the Python module both call these, so that they check the same things and
// report the same fields.

#ifndef DLF_CLI_DISK_OUTCOME_H
#define DLF_CLI_DISK_OUTCOME_H

#include "arguments.h"
#include "cli_error.h"
#include "density_input.h"
#include "disk_run.h"
#include "mesh_input.h"
#include "metrics.h"
#include "seam_input.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace dlf_cli {

struct Disk_outcome
{
  Seam_cut cut;                   ///< with `--seam` only
  std::vector<Border_loop> loops; ///< of the mapped mesh, longest first
  Density_setup density;
  Disk_run run;
  Metrics initial, final_metrics; ///< valid when `initial_ptr()`, `final_ptr()` are not null
  bool ok = false;                ///< the parameterizer returned OK

  const Metrics* initial_ptr() const { return run.initial_uv.empty() ? nullptr : &initial; }
  const Metrics* final_ptr() const { return ok ? &final_metrics : nullptr; }
};

/// Checks the topology of `input` (cut along `settings.seam` if given),
/// builds the density (of `density_values`, one per face or per vertex, if
/// not empty; else of the settings' file or regions), runs the flow and
/// measures its maps. Throws `Cli_error` on unsuitable input; a flow error
/// is returned (`ok` false), as `disk_failure()` words it.
Disk_outcome compute_disk(const Indexed_mesh& input, Disk_settings& settings,
                          const std::vector<double>& density_values = std::vector<double>());

/// The mesh the flow mapped: the input, or the input cut open along seams.
inline const Indexed_mesh& mapped_mesh(const Indexed_mesh& input, const Disk_settings& s, const Disk_outcome& o)
{
  return s.seam.empty() ? input : o.cut.mesh;
}

/// The JSON report of doc/design.md ("dlf disk --report").
nlohmann::ordered_json disk_report(const Disk_settings& settings, const Indexed_mesh& input, const Disk_outcome& outcome);

/// The error of a failed run (`!outcome.ok`): its message and exit code.
Cli_error disk_failure(const Disk_settings& settings, const Indexed_mesh& input, const Disk_outcome& outcome);

} // namespace dlf_cli

#endif
