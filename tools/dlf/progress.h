// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Progress of a flow, one line per iteration from the options' callback:
// rewritten in place when stdout is a terminal, plain lines otherwise (logs
// and pipes keep every line); `--verbose` adds the step's details and never
// overwrites; `--quiet` prints nothing.

#ifndef DLF_CLI_PROGRESS_H
#define DLF_CLI_PROGRESS_H

#include "arguments.h"

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_options.h>

#include <cstdio>
#include <functional>

namespace dlf_cli {

class Progress
{
public:
  /// `show_flips`: a column for edge flips (paper mode).
  Progress(Verbosity verbosity, bool show_flips, std::FILE* out = stdout);
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  /// The callback to put in the options (empty when quiet); refers to this
  /// object, which must outlive the run.
  std::function<bool(const CGAL::Surface_mesh_parameterization::Discrete_lie_flow_iteration&)> callback();

  /// Ends an in-place line, so that what follows starts on a fresh line.
  void finish();

private:
  bool print(const CGAL::Surface_mesh_parameterization::Discrete_lie_flow_iteration& it);

  Verbosity m_verbosity;
  bool m_show_flips, m_in_place, m_line_open = false;
  std::FILE* m_out;
};

/// Runs `flow()` (a command's run on its read input) with a progress line
/// per iteration through `options.callback`, ended whether `flow` returns
/// or throws; the callback is put back as it was, so that the options
/// never keep one that refers to the ended progress.
template <class Flow>
auto run_with_progress(Verbosity verbosity, bool show_flips,
                       CGAL::Surface_mesh_parameterization::Discrete_lie_flow_options& options, Flow flow) -> decltype(flow())
{
  Progress progress(verbosity, show_flips);
  const auto callback = options.callback;
  options.callback = progress.callback();
  try {
    auto outcome = flow();
    progress.finish();
    options.callback = callback;
    return outcome;
  } catch(...) {
    progress.finish();
    options.callback = callback;
    throw;
  }
}

} // namespace dlf_cli

#endif
