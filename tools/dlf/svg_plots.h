// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Plots of a run as SVG: the convergence of the flow (d_area − 2 and the
// area residual per iteration, log scale, of one run; the paper's Fig. 14
// overlays two runs, adaptive and fixed step, as benchmark/fig14.sh does) and
// the histograms of per-face log area ratios before and after (its Fig. 11
// bins per-vertex ratios; doc/paper_errata.md).

#ifndef DLF_CLI_SVG_PLOTS_H
#define DLF_CLI_SVG_PLOTS_H

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_options.h>

#include <ostream>
#include <string>
#include <vector>

namespace dlf_cli {

/// `initial_d_area` is drawn at iteration 0 (NaN: not drawn); `tolerance`,
/// if > 0, as the dashed target line of d_area − 2.
void write_convergence_plot(std::ostream& out,
                            const std::vector<CGAL::Surface_mesh_parameterization::Discrete_lie_flow_iteration>& history,
                            double initial_d_area, double tolerance, const std::string& caption);

/// Two panels, each over its own symmetric range; NaN entries (inverted or
/// flat faces) are counted apart. `before` may be empty (not drawn).
void write_log_ratio_histogram(std::ostream& out, const std::vector<double>& before, const std::vector<double>& after,
                               bool weighted, const std::string& caption);

} // namespace dlf_cli

#endif
