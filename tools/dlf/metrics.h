// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The METRICS block of doc/design.md (computed by the library's
// discrete_lie_flow_distortion()), as JSON and as text.

#ifndef DLF_CLI_METRICS_H
#define DLF_CLI_METRICS_H

#include "mesh_input.h"

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_distortion.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_report.h>

#include <nlohmann/json.hpp>

#include <ostream>
#include <string>
#include <vector>

namespace dlf_cli {

typedef CGAL::Surface_mesh_parameterization::Discrete_lie_flow_distortion Metrics;

/// Distortion of the map `uv` of the caller's triangles `mesh.faces`,
/// against density-weighted areas when `face_density` (per face) is given.
Metrics compute_metrics(const Indexed_mesh& mesh, const std::vector<Vec2>& uv,
                        const std::vector<double>& face_density = std::vector<double>());

nlohmann::ordered_json metrics_to_json(const Metrics& m);

/// One metric a line, each prefixed by `indent`.
void print_metrics(std::ostream& out, const Metrics& m, const std::string& indent);

/// The coarse-to-fine levels of a disk or sphere run into `j`: `levels`,
/// `seconds.levels` and `levels_refused`.
void add_levels_json(nlohmann::ordered_json& j, const CGAL::Surface_mesh_parameterization::Discrete_lie_flow_report& R);

/// The "coarse to fine:" line of the summary (nothing without levels or a refusal).
void print_levels(std::ostream& out, const CGAL::Surface_mesh_parameterization::Discrete_lie_flow_report& R);

} // namespace dlf_cli

#endif
