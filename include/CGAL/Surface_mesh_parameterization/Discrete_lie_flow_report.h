// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_DISCRETE_LIE_FLOW_REPORT_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_DISCRETE_LIE_FLOW_REPORT_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_options.h>

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgDiscreteLieFlowOptions
/// The distortion of a map from the input triangles to domain triangles
/// (planar, or flat triangles between sphere points), after the domain is
/// scaled uniformly so that its total area equals the total
/// (density-weighted) input area (doc/design.md, "Metrics").
struct Discrete_lie_flow_distortion
{
  double d_area = 0;              ///< Σ w_t (σ1σ2 + 1/(σ1σ2)), optimum 2
  double arap = 0;                ///< Σ w_t ((σ1 − 1)² + (σ2 − 1)²), σ2 < 0 on inverted faces
  double symmetric_dirichlet = 0; ///< Σ_t (σ1² + σ1⁻² + σ2² + σ2⁻²), plain sum
  double log_area_mean_abs = 0;   ///< mean over faces of |log(area_Ω / (ρ area_M))|
  double log_area_max_abs = 0;    ///< largest |log(area_Ω / (ρ area_M))|
  double log_area_rms = 0;        ///< root mean square of log(area_Ω / (ρ area_M))
  std::size_t inverted_faces = 0;   ///< by exact orientation, against the majority orientation
  std::size_t degenerate_faces = 0; ///< exactly zero domain area; left out of the sums
  double min_angle_degrees = 0;     ///< smallest angle of a domain triangle
  std::size_t faces_below_1_degree = 0; ///< domain triangles with an angle below 1°
  /// The paper's Table 1 "Wasserstein distance": `√Σ_t (S_t − Ŝ_t)²`, with
  /// `S_t` and `Ŝ_t` the shares of face t in the (density-weighted) input area
  /// and in the unsigned domain area (doc/design.md, "Metrics").
  double wasserstein_table1 = 0;
  double area_total = 0;            ///< `Σ_t |S_t − Ŝ_t|`, the reading of Table 5's Area_total in doc/design.md
  double beltrami_mean = 0;         ///< mean over faces of |μ|, the Beltrami coefficient of the map input → domain
  double beltrami_weighted_mean = 0; ///< `Σ w_t |μ_t|`
  double beltrami_max = 0;          ///< largest |μ_t| (above 1 on inverted faces)
};

/// \ingroup PkgDiscreteLieFlowOptions
/// How far apart two planar maps `a` and `b` of the same triangles are
/// (`discrete_lie_flow_map_difference()`; doc/design.md, "Metrics"): the
/// paper's comparison of DLF with optimal transport (its Table 6 and
/// Figs. 17–18).
struct Discrete_lie_flow_map_difference
{
  /// `√(Σ_i m_i |b_i − a_i|²)`, `m_i` the vertex's share of the
  /// (density-weighted) input area lumped at vertices: the transport cost
  /// of moving the measure `a` carries to `b` vertex by vertex.
  double transport_cost = 0;
  double beltrami_mean = 0;          ///< mean over faces of |μ| of ψ = b ∘ a⁻¹ (affine per face)
  double beltrami_weighted_mean = 0; ///< the same weighted by the faces' shares of the input area
  double beltrami_max = 0;           ///< largest |μ| of ψ
  std::size_t faces_not_compared = 0; ///< faces degenerate in `a` or `b` (no Beltrami coefficient)
};

/// \ingroup PkgDiscreteLieFlowOptions
/// One coarse level of the disk's coarse-to-fine flow
/// (`Discrete_lie_flow_report::levels`, coarsest first).
struct Discrete_lie_flow_level
{
  std::size_t vertices = 0;   ///< vertices of the level (with holes: their fill's too)
  std::size_t faces = 0;      ///< faces of the level (with holes: their fill's too)
  std::size_t iterations = 0; ///< flow iterations on the level (0: the map carried down and swept vertex by vertex)
  double d_area = 0;          ///< D_area of the level's map (its own targets) after its work
  double seconds = 0;         ///< the level's work: its flow, or the map carried down and swept
};

/// \ingroup PkgDiscreteLieFlowOptions
/// What a run of the Discrete Lie Flow did, on the disk
/// (`Discrete_lie_flow_parameterizer_3`) and on the sphere
/// (`Discrete_lie_flow_sphere_parameterizer_3`): the same names for the same
/// things; a field that only one of them fills says so. Each parameterizer
/// object owns the report of its last run; CGAL's `parameterize()` called on
/// a named `Discrete_lie_flow_parameterizer_3` runs that object, not a copy.
struct Discrete_lie_flow_report
{
  /// `OK`, or the error code that `parameterize()` returned.
  Error_code status = OK;
  std::string message;          ///< "Success"; where a valid run stopped short of the targets; or the offending element on error
  /// Why the flow stopped.
  Discrete_lie_flow_stop_reason stop_reason = Discrete_lie_flow_stop_reason::NOT_RUN;
  /// Whether the flow reached its targets (stop reason `CONVERGED`). A run
  /// that returned `OK` without converging (iteration cap, plateau, stall,
  /// interruption) still gives a valid, fold-free map, short of the targets:
  /// its `message` says where it stopped.
  bool converged() const { return stop_reason == Discrete_lie_flow_stop_reason::CONVERGED; }
  std::size_t vertices = 0;     ///< of the flowed component (the disk) or mesh (the sphere)
  std::size_t faces = 0;        ///< of the flowed component (the disk) or mesh (the sphere)
  /// The number of accepted iterations.
  std::size_t iterations = 0;
  double initial_d_area = 0;    ///< on the certified triangulation, before the flow (with holes: on the caller's faces)
  double final_d_area = 0;      ///< on the certified triangulation (the flowing one in paper mode; with holes: the caller's faces)
  double final_residual = 0;    ///< Σ (A_Ω − A_M)² / (Σ A_Ω)² on that triangulation
  /// The largest error of a region's share of the domain (the measure of
  /// `share_tolerance`, doc/measure_control.md); 0 without a density.
  double final_share_error = 0;
  std::size_t flips = 0;        ///< paper mode: edge flips in total
  /// The caller's triangles not positively oriented under the final map
  /// (exact predicate; inverted or degenerate): 0 in certified mode.
  std::size_t caller_inverted_faces = 0;
  /// The certified triangulation's (the flowing one in paper mode; with
  /// holes, the caller's faces and the fill of the holes): always 0 on success.
  std::size_t flowing_inverted_faces = 0;
  /// Literal mode, stop reason `COLLAPSED`: the faces of the flowing
  /// triangulation that the refused step inverted or made degenerate (exact
  /// predicate); 0 when the step no longer moved the mesh.
  std::size_t collapse_faces = 0;
  std::size_t rejected_by_exact_check = 0; ///< trial steps the doubles accepted and the exact predicate refused
  std::size_t factorizations = 0;          ///< numeric factorisations of the flow's sparse matrices
  std::size_t symbolic_analyses = 0;       ///< symbolic analyses (a new sparsity pattern)
  double seconds_initial = 0;   ///< the initial map
  double seconds_flow = 0;      ///< the flow
  ///@{
  /// Split of seconds_flow: matrix assembly, factorisation and solve, step
  /// search with certification, flips and relaxation sweeps.
  double seconds_assembly = 0, seconds_solve = 0, seconds_step = 0;
  ///@}
  ///@{
  /// The distortion metrics of the initial and the final map on the caller's
  /// triangles; valid when `status` is `OK`.
  Discrete_lie_flow_distortion initial_metrics, final_metrics;
  ///@}
  std::vector<Discrete_lie_flow_iteration> history; ///< when options.record_history
  /// The final domain triangulation as triples of vertex indices (the disk:
  /// the `VertexIndexMap` of the call; the sphere: the order of
  /// `vertices(mesh)`): the input's in certified mode, the flowing one in paper mode.
  std::vector<std::array<int, 3> > domain_faces;
  ///@{
  /// Per vertex index: the lumped areas A_M (target, scaled to the domain's
  /// total) and A_Ω of the final map, on `domain_faces`.
  std::vector<double> target_area, domain_area;
  ///@}
  /// Per face (the order of the input's faces): the density ρ the flow used.
  std::vector<double> face_density;
  /// The disk: the map the flow started from, per vertex index (with holes,
  /// the library's start inside the initial parameterizer's outer loop);
  /// empty when the initial map failed.
  std::vector<std::array<double, 2> > initial_uv;
  /// The disk: the border the flow used (circle, square, free or floating).
  Discrete_lie_flow_border border = Discrete_lie_flow_border::AUTOMATIC;
  /// The sphere, paper mode: edges of `domain_faces` left non-Delaunay (0
  /// except with flips off, or when the last flips were undone because they
  /// raised D_area: starts compressed to the rounding level).
  std::size_t flowing_non_delaunay_edges = 0;
  /// The disk: the border loops other than the given one (holes), filled for
  /// the flow and left free; 0 for a disk. With holes the initial map is the
  /// library's own (Tutte's embedding of the filled disk inside the initial
  /// parameterizer's outer loop), and `history` and `final_residual` follow
  /// the filled disk.
  std::size_t holes = 0;
  /// The sphere: which initial map the flow started from.
  Discrete_lie_flow_sphere_start sphere_start = Discrete_lie_flow_sphere_start::TUTTE;
  /// The sphere: the face of the initial map's north cap (index in face order;
  /// -1 for a given map).
  int puncture_face = -1;
  /// The sphere: the plane scale of the stereographic lift.
  double initial_scale = 0;
  /// The sphere: the punctures tried before one was certified.
  std::size_t initial_attempts = 0;
  /// The sphere: edge-split vertices removed for the coarse start (0: the
  /// start is the mesh's own); the initial map is then the coarse mesh's map
  /// after `coarse_iterations` of the flow, these vertices put back on the
  /// arcs between their neighbours, and `puncture_face` is a coarse face.
  std::size_t split_vertices_removed = 0;
  /// The sphere: iterations of the coarse mesh's flow (0 without a coarse start).
  std::size_t coarse_iterations = 0;
  /// The disk and the sphere, certified mode: the coarse-to-fine flow's
  /// levels, coarsest first, the last one the caller's mesh with the map
  /// carried down to it (empty when the flow ran on the mesh alone,
  /// `Discrete_lie_flow_disk_options::coarse_to_fine_faces`,
  /// `Discrete_lie_flow_sphere_options::coarse_to_fine_faces`). `iterations`
  /// and the history are the finest level's flow, from that map.
  std::vector<Discrete_lie_flow_level> levels;
  /// The time the coarse levels took to build (the disk: within
  /// `seconds_flow`; the sphere: within `seconds_initial`).
  double seconds_levels = 0;
  /// Why the coarse levels' map was not taken as the start (empty when it was, or when there were none).
  std::string levels_refused;
};

/// \ingroup PkgDiscreteLieFlowOptions
/// What one iteration of the volumetric flow did (or of its start's
/// untangling): passed to `Discrete_lie_flow_volume_options::callback` and
/// kept in `Discrete_lie_flow_volume_report::history`.
struct Discrete_lie_flow_volume_iteration
{
  std::size_t iteration = 0; ///< 1 for the first step
  double step = 0;           ///< the accepted step λ (1: the full Gauss–Newton step)
  double critical_step = 0;  ///< the smallest critical step of the direction
  int limiting_tet = -1;     ///< the tet (caller's index) of that step, −1 if none
  double d_vol = 0;          ///< D_vol after the step (with ε > 0: the regularised energy)
  double epsilon = 0;        ///< the untangling's ε, 0 in the certified flow
  bool untangling = false;   ///< an iteration of the start's untangling (its polish at ε = 0 too)
  std::size_t negative_tets = 0; ///< by the doubles, after the step (untangling)
  std::size_t cg_iterations = 0; ///< conjugate-gradient steps of this iteration's direction
  double seconds = 0;        ///< since the flow started
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
