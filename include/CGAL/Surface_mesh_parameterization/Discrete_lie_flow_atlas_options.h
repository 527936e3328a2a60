// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_DISCRETE_LIE_FLOW_ATLAS_OPTIONS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_DISCRETE_LIE_FLOW_ATLAS_OPTIONS_H

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
/// The flow settings of an atlas's charts: the defaults, with an iteration
/// cap of 150 (a chart that needs more is split).
inline Discrete_lie_flow_options atlas_flow_defaults()
{
  Discrete_lie_flow_options o;
  o.max_iterations = 150;
  return o;
}

/// \ingroup PkgDiscreteLieFlowOptions
/// Settings of `discrete_lie_flow_atlas()`. Defaults are the measured choices
/// (doc/atlas.md).
struct Discrete_lie_flow_atlas_options
{
  /// The flow of every chart: tolerance, caps, solver threads. Its
  /// `face_density` (ρ > 0 per face, in the order of `faces(mesh)`) weighs
  /// the whole atlas: a face gets ρ times its share of the surface. The mode
  /// must be certified (the atlas is certified fold-free). Its iteration cap
  /// is the splitting rule: a chart whose flow has not converged after
  /// `max_iterations` (150 here, measured in doc/atlas.md) is split.
  Discrete_lie_flow_options flow = atlas_flow_defaults();
  /// The border of every chart: `SQUARE` (the default: a square chart fills
  /// its slot of the packing) or `CIRCLE`.
  Discrete_lie_flow_border border = Discrete_lie_flow_border::SQUARE;
  /// The seam of a closed component runs through this many tips
  /// (extremities of protrusions), at least 2. Two, the farthest pair, give
  /// the shortest seam; on CGAL's closed genus-0 meshes every chart still
  /// converges with it (doc/atlas.md compares 2, 4 and 8).
  std::size_t tips = 2;
  /// Empty space around every chart in the unit square, in uv units (half
  /// of it on each side of a chart's box), ≥ 0.
  double gutter = 1. / 1024;
  /// Each chart fills a cell of a squarified treemap of the unit square,
  /// stretched to the cell's shape by an area-preserving affine map
  /// (u, v) → (a·u, v/a): the areas, hence D_area, do not change, and square
  /// charts leave no space but the gutter. `false`: the charts keep their
  /// shape and are packed on shelves (lower packing efficiency).
  bool stretch_to_fill = true;
  /// A chart whose flow does not converge is split in two (geodesic halves)
  /// and each half flattened again, at most this many times in a row.
  std::size_t max_split_depth = 3;
  /// Charts of fewer faces are not split further. A chart whose flow stops
  /// short and that cannot be split (this size, `max_split_depth`) gives
  /// each of its triangles a chart of its own, laid out isometrically
  /// (exact): every chart of the atlas converges.
  std::size_t min_split_faces = 64;
  /// Charts of fewer faces than `flow.disk.coarse_to_fine_faces` flow
  /// toward D_area − 2 ≤ this (if below `flow.tolerance`); one that stops
  /// within `flow.tolerance` counts as converged (not split): on meshes of planar
  /// pieces another atlas's charts come within 0.002 of the optimum, and
  /// below that size the further iterations cost little (bunny00, 75K
  /// faces: 1.4× the time; doc/atlas.md). Larger charts keep
  /// `flow.tolerance` (a 1.2M-face chart at 0.001 takes more than 70 s
  /// instead of 55). 0: `flow.tolerance` everywhere.
  double small_chart_tolerance = 1e-3;
  /// A chart whose flow does not converge and that cannot be split gives
  /// up its triangles with three corners on its border, at most this many
  /// times in a row: the border fixes such a triangle's area, so the flow
  /// cannot bring it to its share (the input's jagged borders, strips of a
  /// cut). Each becomes a chart of its own, laid out isometrically (exact);
  /// the rest is flattened again. 0: never (doc/atlas.md measures it).
  std::size_t max_border_peels = 3;
  /// Called with one line per stage (cutting, each chart, packing); may be empty.
  std::function<void(const std::string&)> progress;
  /// `flow.callback` (each iteration; false stops the chart's flow) is called
  /// for the charts of at least this many faces only: an atlas of a
  /// thousand small charts would report tens of thousands of iterations.
  /// 0: every chart.
  std::size_t callback_faces = 0;
};

/// \ingroup PkgDiscreteLieFlowOptions
/// One chart of an atlas.
struct Discrete_lie_flow_atlas_chart
{
  std::size_t faces = 0;     ///< triangles of the chart
  std::size_t vertices = 0;  ///< vertices of the chart (a vertex on a seam counts once per side)
  std::size_t holes = 0;     ///< inner border loops left floating
  std::size_t split_depth = 0; ///< how many splits made it (0: a whole component or a cut one)
  std::size_t three_border_corner_faces = 0; ///< triangles with all corners on the chart's border
  double area_share = 0;     ///< its share of the (density-weighted) surface area
  Error_code code = OK;      ///< the flow's result
  Discrete_lie_flow_stop_reason stop_reason = Discrete_lie_flow_stop_reason::NOT_RUN; ///< why its flow stopped
  std::size_t iterations = 0; ///< iterations of its flow
  double d_area = 0;         ///< the chart's D_area after its flow
  std::string message;       ///< the flow's message
};

/// \ingroup PkgDiscreteLieFlowOptions
/// What `discrete_lie_flow_atlas()` did. The distortion is that of the whole
/// atlas: every triangle's uv area against its share of the surface area.
struct Discrete_lie_flow_atlas_report
{
  Error_code code = OK;              ///< `OK`, or why there is no atlas
  std::string message;               ///< "Success", or the offending element
  std::size_t components = 0;        ///< connected components with faces
  std::size_t isolated_vertices = 0; ///< vertices on no face (ignored)
  std::size_t closed_components = 0; ///< components without border
  std::size_t max_genus = 0;         ///< the largest genus of a component
  std::size_t charts = 0;            ///< charts in the atlas
  std::size_t splits = 0;            ///< charts split because their flow did not converge
  std::size_t peeled_faces = 0;      ///< triangles made charts of their own: fixed by their chart's border (`max_border_peels`), or of a chart that could not be split further
  std::size_t unconverged_charts = 0; ///< charts whose flow stopped short of its tolerance (valid maps still)
  std::size_t three_border_corner_faces = 0; ///< triangles with all corners on their chart's border
  double seam_length = 0;            ///< 3D length of the edges cut open (the input's own border not counted)
  double surface_area = 0;           ///< 3D area of the input
  double packing_efficiency = 0;     ///< uv area of the charts / area of the unit square
  double scale = 0;                  ///< uv area per unit of (density-weighted) surface area
  double max_chart_stretch = 1;      ///< the largest a or 1/a of the charts' area-preserving stretches (1: none)
  Discrete_lie_flow_distortion metrics; ///< the whole atlas's distortion (D_area, log area ratios, ...)
  std::size_t inverted_faces = 0;    ///< uv triangles negative by the exact predicate
  std::size_t degenerate_faces = 0;  ///< uv triangles of zero area by the exact predicate
  std::size_t overlapping_chart_pairs = 0; ///< pairs of charts whose boxes overlap (exact comparisons)
  std::size_t points_outside = 0;    ///< uv corners outside [0, 1]²
  double seconds_cut = 0;            ///< components, seams, splits
  double seconds_flow = 0;           ///< the charts' flows
  double seconds_pack = 0;           ///< packing and checks
  double seconds = 0;                ///< the whole call
  std::vector<Discrete_lie_flow_atlas_chart> chart_reports; ///< per chart, in the order of their uv placement

  /// Every chart's flow converged.
  bool converged() const { return code == OK && unconverged_charts == 0; }
  /// A valid atlas: no inverted or degenerate triangle, no overlap, all in the unit square.
  bool valid() const
  {
    return code == OK && inverted_faces == 0 && degenerate_faces == 0 && overlapping_chart_pairs == 0 && points_outside == 0;
  }
};

/// \ingroup PkgDiscreteLieFlowOptions
/// The score of an atlas given as per-corner uv, whoever made it
/// (`discrete_lie_flow_atlas_score()`); orientations and overlaps by CGAL's
/// exact predicates on the stored doubles.
struct Discrete_lie_flow_atlas_score
{
  std::size_t faces = 0;                    ///< triangles scored
  std::size_t charts = 0;                   ///< faces joined across edges whose two sides share their uv
  double seam_length = 0;                   ///< 3D length of the edges cut open (the input's border not counted)
  double surface_area = 0;                  ///< 3D area of the triangles
  double uv_area = 0;                       ///< Σ |uv area| of the faces
  double packing_efficiency = 0;            ///< uv_area over the area of the uv's bounding rectangle
  double bounding_width = 0;                ///< width of the uv's bounding rectangle
  double bounding_height = 0;               ///< height of the uv's bounding rectangle
  std::size_t inverted_faces = 0;           ///< against the orientation of most of their chart's area, exact
  std::size_t mirrored_charts = 0;          ///< charts oriented clockwise as a whole (not a fold)
  std::size_t degenerate_faces = 0;         ///< zero uv area, exact
  std::size_t overlapping_face_pairs = 0;   ///< pairs of uv triangles whose interiors meet, exact
  std::size_t overlapping_pairs_in_a_chart = 0; ///< of which both in one chart (a fold)
  Discrete_lie_flow_distortion metrics;     ///< of the whole atlas (d_area: every triangle against its share)
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
