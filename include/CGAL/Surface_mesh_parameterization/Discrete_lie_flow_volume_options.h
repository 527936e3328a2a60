// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_DISCRETE_LIE_FLOW_VOLUME_OPTIONS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_DISCRETE_LIE_FLOW_VOLUME_OPTIONS_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_options.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_report.h>

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgDiscreteLieFlowOptions
/// Settings of `Discrete_lie_flow_volume_parameterizer_3`. Both flows read
/// `tolerance`, `max_iterations`, `mu`, `star_shaped_border`,
/// `share_tolerance` and `callback`; the certified mode also the conjugate
/// gradients' settings (`cg_max_iterations`, `cholesky_every`,
/// `coarse_aggregate`, `cg_forcing`) and `threads`, the paper mode
/// `paper_collapse_guard`. The start reads `border`,
/// `untangle_max_iterations` and `callback`, the run `mode`, `tet_density`
/// and `record_history`.
struct Discrete_lie_flow_volume_options
{
  /// Which flow moves the vertices from the certified start: `CERTIFIED`
  /// (the default) descends D_vol by Gauss–Newton steps; `PAPER` runs the
  /// paper's flow as far as its formulas reach in 3D (the Poisson potential
  /// of the vertex volumes' mismatch with the P1 stiffness of the current
  /// tets, volume-weighted vertex gradients, μ times the critical step;
  /// doc/volume.md, "Paper mode"), every step still certified by the exact
  /// predicate; it uses neither the conjugate gradients' settings nor
  /// `cholesky_every`. `LITERAL` is refused (`ERROR_WRONG_PARAMETER`).
  Discrete_lie_flow_mode mode = Discrete_lie_flow_mode::CERTIFIED;
  /// Paper mode: before each step, a tet already below its target that the
  /// velocities would flatten gets its volume rate projected to zero (the
  /// planar paper mode's collapse guard; false: the paper's step as written,
  /// which flattens tets of four border corners within a few steps).
  bool paper_collapse_guard = true;
  double tolerance = 0.01;          ///< stop when D_vol − 2 ≤ tolerance
  /// Iteration cap of the flow (the plateau rule ends a flow that no longer
  /// gains well before it; doc/volume.md).
  std::size_t max_iterations = 1000;
  double mu = 0.8;                  ///< fraction of the critical step, in (0, 1)
  std::size_t cg_max_iterations = 60; ///< conjugate-gradient cap of each Gauss–Newton solve
  /// The conjugate gradients' preconditioner: 0 (the default) the 3 × 3
  /// blocks of every vertex; k > 0 a sparse Cholesky factorisation of the
  /// whole Gauss–Newton matrix, refreshed every k iterations (fewer
  /// iterations to a lower D_vol on meshes with protrusions, each several
  /// times dearer; doc/volume.md).
  std::size_t cholesky_every = 0;
  /// Threads of the certified flow's per-tetrahedron and per-vertex passes
  /// (the paper mode runs on one): 0 (the default) automatic, one below
  /// 150,000 tetrahedra, else the hardware threads (at most 8); the result
  /// is the same whatever the number.
  int threads = 0;
  /// The conjugate gradients' coarse level: aggregates of this many
  /// vertices (spatially compact), each moving by one translation, solved
  /// exactly besides the 3 × 3 blocks (0: the blocks alone, 5 to 10 times
  /// more flow time at a million tetrahedra; doc/volume.md).
  std::size_t coarse_aggregate = 64;
  /// Inexact Newton: the conjugate gradients' tolerance follows Eisenstat
  /// and Walker's forcing term, loose far from the minimum (false: a fixed
  /// relative tolerance of 1e-3, up to the cap).
  bool cg_forcing = true;
  /// Iteration cap of the start's untangling, its stages and regions
  /// together (each region of a stage at most 10,000; volume_untangle.h).
  std::size_t untangle_max_iterations = 12000;
  /// Keep the border star-shaped during the flow: every border triangle
  /// positive seen from the centre, besides every tet positive; both
  /// together certify that the map is a bijection onto its image (the
  /// start always is). Off (the default): only the tets constrain the flow,
  /// which reaches a far lower D_vol on meshes with protrusions, and the
  /// report counts the border triangles seen reversed
  /// (`inverted_border_faces`; 0 again certifies the bijection).
  bool star_shaped_border = false;
  /// Per-tet density ρ > 0 (empty: 1): a tet's share of the ball is
  /// proportional to ρ × its volume.
  std::vector<double> tet_density;
  /// With a density: converged also needs the tets of every density value
  /// (up to 32 values) to hold their share of the volume within this,
  /// relative (0: D_vol alone decides).
  double share_tolerance = 0.005;
  /// Settings of the spherical map of the border (the start).
  Discrete_lie_flow_options border;
  /// Keep every iteration in the report's `history`.
  bool record_history = false;
  /// Called after every iteration (untangling and flow); false stops the run.
  std::function<bool(const Discrete_lie_flow_volume_iteration&)> callback;
};

/// \ingroup PkgDiscreteLieFlowOptions
/// One density level's share of the ball: the tets of one density value.
struct Discrete_lie_flow_volume_share
{
  double density = 1;        ///< the density value ρ of this level
  std::size_t tets = 0;      ///< the number of tets with that value
  double target_share = 0;   ///< Σ ρ vol_M / Σ ρ vol_M over all tets
  double achieved_share = 0; ///< Σ vol_Ω / Σ vol_Ω
  /// achieved / target − 1 (0 without a target).
  double relative_error() const { return target_share > 0 ? achieved_share / target_share - 1 : 0; }
};

/// \ingroup PkgDiscreteLieFlowOptions
/// What a run of `Discrete_lie_flow_volume_parameterizer_3` did.
struct Discrete_lie_flow_volume_report
{
  Error_code status = OK; ///< OK, or the error that stopped the run
  std::string message;  ///< "Success", or what stopped the run (the offending element on error)
  Discrete_lie_flow_stop_reason stop_reason = Discrete_lie_flow_stop_reason::NOT_RUN; ///< why the flow stopped
  /// Whether the flow reached its tolerances.
  bool converged() const { return stop_reason == Discrete_lie_flow_stop_reason::CONVERGED; }
  std::size_t vertices = 0;        ///< vertices of the tet mesh
  std::size_t border_vertices = 0; ///< of which on its border
  std::size_t tets = 0;            ///< tets of the mesh
  std::size_t border_faces = 0;    ///< border triangles
  std::size_t iterations = 0;      ///< iterations of the flow
  double initial_d_vol = 0;  ///< D_vol of the certified start
  double final_d_vol = 0;    ///< D_vol = Σ w_t (r_t + 1/r_t), optimum 2
  double log_volume_mean_abs = 0; ///< mean of |log r_t|
  double log_volume_max_abs = 0;  ///< largest |log r_t|
  double min_ratio = 0;           ///< smallest r_t = (vol_Ω/Σ vol_Ω)/w_t
  double max_ratio = 0;           ///< largest r_t
  double volume = 0;         ///< Σ vol_Ω, the volume of the image (the polytope inscribed in the unit ball)
  std::size_t inverted_tets = 0; ///< negative tets of the result, by CGAL's exact orientation
  std::size_t flat_tets = 0;     ///< flat tets of the result, likewise
  std::size_t inverted_border_faces = 0; ///< border triangles with orientation(O, a, b, c) ≠ POSITIVE (O the centre)
  bool start_certified = false; ///< every tet of the start positive by the exact predicate
  std::size_t start_negative_tets = 0; ///< negative tets of Tutte's embedding, before untangling
  std::size_t start_flat_tets = 0;     ///< flat tets of Tutte's embedding, before untangling
  std::size_t untangle_iterations = 0; ///< iterations of the start's untangling (every region and stage)
  std::size_t rejected_by_exact_check = 0; ///< trial steps the doubles accepted and the exact predicate refused
  std::size_t cg_iterations = 0; ///< conjugate-gradient steps of the flow, in all
  /// Threads the flow used (`Discrete_lie_flow_volume_options::threads`,
  /// 0 resolved to the automatic choice).
  int threads = 0;
  std::vector<Discrete_lie_flow_volume_share> shares; ///< per density value (up to 32 values)
  double share_error_max = 0; ///< largest |relative_error()| of `shares`
  Discrete_lie_flow_report border; ///< the spherical map of the border
  double seconds_border = 0;   ///< the spherical map of the border
  double seconds_interior = 0; ///< Tutte's embedding of the interior
  double seconds_untangle = 0; ///< the untangling
  double seconds_flow = 0;     ///< the flow
  double seconds_total = 0;    ///< the whole run
  std::vector<Discrete_lie_flow_volume_iteration> history; ///< with `record_history`
  std::vector<double> volume_ratio; ///< r_t per tet of the result
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
