// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_DISCRETE_LIE_FLOW_REPORT_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_DISCRETE_LIE_FLOW_REPORT_H

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_options.h>

#include <array>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgDiscreteLieFlowOptions
/// What a run of the Discrete Lie Flow did. Shared by the copies of a
/// parameterizer, so a named object passed by value to `parameterize()` still
/// sees the report of its last run.
struct Discrete_lie_flow_report
{
  /// `OK`, or the error code that `parameterize()` returned.
  Error_code status = OK;
  std::string message;          ///< one line naming the offending element on error
  /// Why the flow stopped.
  Discrete_lie_flow_stop_reason stop_reason = Discrete_lie_flow_stop_reason::NOT_RUN;
  Discrete_lie_flow_border border = Discrete_lie_flow_border::AUTOMATIC; ///< the border the flow used
  /// The number of accepted iterations.
  std::size_t iterations = 0;
  double initial_d_area = 0;    ///< on the certified triangulation, before the flow
  double final_d_area = 0;      ///< on the certified triangulation (the flowing one in paper mode)
  double final_residual = 0;    ///< Σ (A_Ω − A_M)² / (Σ A_Ω)² on that triangulation
  /// The largest error of a region's share of the domain (density_levels.h;
  /// the measure of `options.share_tolerance`); 0 without a density.
  double final_share_error = 0;
  std::size_t flips = 0;        ///< paper mode
  std::size_t caller_inverted_faces = 0;   ///< the caller's triangles not positive under the final map (exact)
  std::size_t flowing_inverted_faces = 0;  ///< the certified triangulation's, always 0 on success
  std::size_t rejected_by_exact_check = 0; ///< trial steps the doubles accepted and the exact predicate refused
  ///@{
  /// Numeric factorisations and symbolic analyses of the flow's sparse matrices.
  std::size_t factorizations = 0, symbolic_analyses = 0;
  ///@}
  ///@{
  /// Seconds spent on the initial map and on the flow.
  double seconds_initial = 0, seconds_flow = 0;
  ///@}
  ///@{
  /// Split of seconds_flow: matrix assembly, factorisation and solve, step search and certification.
  double seconds_assembly = 0, seconds_solve = 0, seconds_step = 0;
  ///@}
  std::vector<Discrete_lie_flow_iteration> history; ///< when options.record_history
  /// The final domain triangulation as triples of vertex indices (the
  /// `VertexIndexMap` of the call); the input's in certified mode.
  std::vector<std::array<int, 3> > domain_faces;
  ///@{
  /// Per vertex index: the lumped areas A_M (target, scaled to the domain's
  /// total) and A_Ω of the final map, on `domain_faces`.
  std::vector<double> target_area, domain_area;
  ///@}
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
