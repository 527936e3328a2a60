// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_DISCRETE_LIE_FLOW_OPTIONS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_DISCRETE_LIE_FLOW_OPTIONS_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_version.h>
#include <CGAL/Surface_mesh_parameterization/Error_code.h>

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgDiscreteLieFlowErrors
/// Error codes of the Discrete Lie Flow parameterizers, continuing SMP's
/// `Error_code` (they are returned as `Error_code` values; all fit in its range).
enum Discrete_lie_flow_error_code
{
  ERROR_INITIAL_MAP_FOLDED = ERROR_WRONG_PARAMETER + 1, ///< the initial map has inverted or degenerate faces
  ERROR_DEGENERATE_INPUT,        ///< non-finite coordinates or a zero-area face in the input
  ERROR_INVALID_DENSITY,         ///< a density is zero, negative, not finite, or wrongly sized
  ERROR_FLOW_STALLED,            ///< the flow could not improve the initial map at all
  ERROR_NOT_GENUS_0              ///< a spherical map needs a closed, connected, genus-0 mesh
};

/// \ingroup PkgDiscreteLieFlowErrors
/// The message of any `Error_code` value, including those of the Discrete Lie Flow.
/// (A `switch`, so that the compiler reports a code without a message.)
inline const char* discrete_lie_flow_error_message(int code)
{
  switch(code) {
  case OK: return "Success";
  case ERROR_EMPTY_MESH: return "Input mesh is empty";
  case ERROR_NON_TRIANGULAR_MESH: return "Input mesh is not triangular";
  case ERROR_NO_TOPOLOGICAL_DISC: return "Input mesh is not a topological disc";
  case ERROR_NO_TOPOLOGICAL_BALL: return "Input mesh is not a topological ball";
  case ERROR_BORDER_TOO_SHORT: return "This border parameterization requires a longer border";
  case ERROR_NON_CONVEX_BORDER: return "This parameterization method requires a convex border";
  case ERROR_CANNOT_SOLVE_LINEAR_SYSTEM: return "Cannot solve linear system";
  case ERROR_NO_1_TO_1_MAPPING: return "Parameterization failed: no one-to-one mapping";
  case ERROR_WRONG_PARAMETER: return "A method received an unexpected parameter";
  case ERROR_INITIAL_MAP_FOLDED: return "The initial map has inverted or degenerate triangles";
  case ERROR_DEGENERATE_INPUT: return "The input has non-finite coordinates or zero-area triangles";
  case ERROR_INVALID_DENSITY: return "The density is zero, negative, not finite or wrongly sized";
  case ERROR_FLOW_STALLED: return "The flow stalled before improving the initial map";
  case ERROR_NOT_GENUS_0: return "Input mesh is not a closed genus-0 surface";
  }
  return "Unknown error";
}

/// \ingroup PkgDiscreteLieFlowErrors
/// The code of CGAL's `Error_code` enum nearest in meaning to `code` (a code
/// of either enum): what the `Parameterizer_3` entry points of this package
/// return, so that CGAL's `get_error_message()` explains it and CGAL's
/// programs and tests read it as they read CGAL's own parameterizers'. The
/// precise code stays in the report (`Discrete_lie_flow_report::status`).
///
/// - a folded initial map, a flow that could not keep any step one-to-one:
///   `ERROR_NO_1_TO_1_MAPPING`;
/// - a zero-area face or a non-finite coordinate (the flow's cotangent
///   system is then undefined, as CGAL's own are): `ERROR_CANNOT_SOLVE_LINEAR_SYSTEM`;
/// - not a disk, not genus 0: `ERROR_NO_TOPOLOGICAL_DISC`, CGAL's "input not supported";
/// - an invalid density or a vertex index map that does not number the
///   vertices (`ERROR_WRONG_PARAMETER`, which CGAL 5.5's `get_error_message()`
///   has no text for: it returns a null pointer): `ERROR_NO_1_TO_1_MAPPING`,
///   no map was made;
/// - CGAL's other codes: themselves; any other value: `ERROR_NO_1_TO_1_MAPPING`.
inline Error_code discrete_lie_flow_cgal_error_code(int code)
{
  switch(code) {
  case OK: return OK;
  case ERROR_EMPTY_MESH: return ERROR_EMPTY_MESH;
  case ERROR_NON_TRIANGULAR_MESH: return ERROR_NON_TRIANGULAR_MESH;
  case ERROR_NO_TOPOLOGICAL_DISC: return ERROR_NO_TOPOLOGICAL_DISC;
  case ERROR_NO_TOPOLOGICAL_BALL: return ERROR_NO_TOPOLOGICAL_BALL;
  case ERROR_BORDER_TOO_SHORT: return ERROR_BORDER_TOO_SHORT;
  case ERROR_NON_CONVEX_BORDER: return ERROR_NON_CONVEX_BORDER;
  case ERROR_CANNOT_SOLVE_LINEAR_SYSTEM: return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
  case ERROR_NO_1_TO_1_MAPPING: return ERROR_NO_1_TO_1_MAPPING;
  case ERROR_WRONG_PARAMETER: return ERROR_NO_1_TO_1_MAPPING;
  case ERROR_INITIAL_MAP_FOLDED: return ERROR_NO_1_TO_1_MAPPING;
  case ERROR_DEGENERATE_INPUT: return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
  case ERROR_INVALID_DENSITY: return ERROR_NO_1_TO_1_MAPPING;
  case ERROR_FLOW_STALLED: return ERROR_NO_1_TO_1_MAPPING;
  case ERROR_NOT_GENUS_0: return ERROR_NO_TOPOLOGICAL_DISC;
  }
  return ERROR_NO_1_TO_1_MAPPING;
}

/// \ingroup PkgDiscreteLieFlowErrors
/// The identifier of an `Error_code` value as used in reports (`"ok"`, `"ERROR_NO_TOPOLOGICAL_DISC"`, ...).
inline const char* discrete_lie_flow_error_name(int code)
{
  switch(code) {
  case OK: return "ok";
  case ERROR_EMPTY_MESH: return "ERROR_EMPTY_MESH";
  case ERROR_NON_TRIANGULAR_MESH: return "ERROR_NON_TRIANGULAR_MESH";
  case ERROR_NO_TOPOLOGICAL_DISC: return "ERROR_NO_TOPOLOGICAL_DISC";
  case ERROR_NO_TOPOLOGICAL_BALL: return "ERROR_NO_TOPOLOGICAL_BALL";
  case ERROR_BORDER_TOO_SHORT: return "ERROR_BORDER_TOO_SHORT";
  case ERROR_NON_CONVEX_BORDER: return "ERROR_NON_CONVEX_BORDER";
  case ERROR_CANNOT_SOLVE_LINEAR_SYSTEM: return "ERROR_CANNOT_SOLVE_LINEAR_SYSTEM";
  case ERROR_NO_1_TO_1_MAPPING: return "ERROR_NO_1_TO_1_MAPPING";
  case ERROR_WRONG_PARAMETER: return "ERROR_WRONG_PARAMETER";
  case ERROR_INITIAL_MAP_FOLDED: return "ERROR_INITIAL_MAP_FOLDED";
  case ERROR_DEGENERATE_INPUT: return "ERROR_DEGENERATE_INPUT";
  case ERROR_INVALID_DENSITY: return "ERROR_INVALID_DENSITY";
  case ERROR_FLOW_STALLED: return "ERROR_FLOW_STALLED";
  case ERROR_NOT_GENUS_0: return "ERROR_NOT_GENUS_0";
  }
  return "ERROR_UNKNOWN";
}

/// \ingroup PkgDiscreteLieFlowOptions
/// Which flow moves the domain vertices.
enum class Discrete_lie_flow_mode
{
  /// Fold-free on the caller's triangles: DLF's Laplacian solve and certified
  /// critical-root step applied to the Sobolev gradient of the barrier energy
  /// D_area. Departs from the paper in the direction of motion. The default.
  CERTIFIED,
  /// The paper's flow, stabilised: Poisson potential of the area mismatch,
  /// Delaunay edge flips of the flowing domain mesh, a line search below the
  /// critical step, a collapse guard and plateau tests (doc/paper_mode.md);
  /// steps certified on the flowing triangulation. May fold the caller's
  /// triangles.
  PAPER,
  /// Algorithm 1 of the paper as printed (doc/paper_errata.md for where the
  /// print is corrected): Delaunay flips, targets lumped once on the input
  /// triangles, the Poisson potential, the step λ = μ·min λ̃_t (Eq. 5) or a
  /// fixed step, and the stop rule ‖h_M − h_Ω‖² < ε. No line search, no
  /// guard: a step that folds or collapses the flowing mesh ends the run
  /// (stop reason `COLLAPSED`), the last fold-free iterate returned.
  LITERAL
};

/// \ingroup PkgDiscreteLieFlowOptions
/// What the boundary vertices slide on.
enum class Discrete_lie_flow_border
{
  AUTOMATIC, ///< detected from the initial map: circle, square, or else free
  CIRCLE,    ///< the circle through the initial boundary
  SQUARE,    ///< the axis-aligned square of the initial boundary, corners fixed
  FREE,      ///< the initial boundary polyline (e.g. from LSCM or ARAP)
  /// No curve: the boundary vertices move as freely as the interior ones,
  /// but one, which holds the map in place (certified mode only; the
  /// others refuse it with `ERROR_WRONG_PARAMETER`). The default of
  /// `Discrete_lie_flow_parameterizer_3` with `Two_vertices_parameterizer_3`
  /// as second template argument, CGAL's free border.
  FLOATING
};

/// \ingroup PkgDiscreteLieFlowOptions
/// Where the spherical flow starts. Both of the library's starts puncture
/// one face, map the rest onto the plane with the puncture's corners fixed,
/// lift it by inverse stereographic projection at the scale of least D_area
/// and are accepted only when every face is positive by the exact predicate.
enum class Discrete_lie_flow_sphere_start
{
  /// Tutte's barycentric map, the puncture an equilateral triangle: bijective
  /// by construction. The default.
  TUTTE,
  /// The cotangent-harmonic (discrete conformal) map, the puncture a triangle
  /// similar to the face: the paper's kind of start (a conformal sphere map),
  /// in the style of Choi, Lam and Lui's FLASH without its south-pole
  /// correction. Cotangent weights may be negative, so it can fold; it is
  /// then refused with `ERROR_INITIAL_MAP_FOLDED`.
  CONFORMAL,
  /// Tutte's map with Floater's mean-value weights (positive, so bijective by
  /// construction like TUTTE) instead of uniform ones: they reproduce linear
  /// functions, so a vertex lying on a straight 3D edge between two
  /// neighbours stays between their images, and fans of needles keep their
  /// shape instead of fattening and compressing their neighbours.
  MEAN_VALUE,
  /// The caller's map (`Discrete_lie_flow_sphere_parameterizer_3::set_initial_map()`),
  /// certified the same way; reported, not selected by the options.
  GIVEN
};

/// \ingroup PkgDiscreteLieFlowOptions
/// Why the flow stopped.
enum class Discrete_lie_flow_stop_reason
{
  NOT_RUN,        ///< the flow did not start (an error occurred before)
  CONVERGED,      ///< the area distortion reached the tolerance
  PLATEAU,        ///< the area distortion stopped improving
  STALLED,        ///< the step collapsed (a triangle keeps limiting it, or no step is acceptable)
  ITERATION_CAP,  ///< the iteration cap was reached
  INTERRUPTED,    ///< the per-iteration callback asked to stop
  /// Literal mode: the step folded or degenerated a face of the flowing mesh
  /// (exact predicate), or no longer moved it (the critical step collapsed to
  /// the rounding level); the paper's "c" (Table 2). The step is not taken.
  COLLAPSED
};

/// \ingroup PkgDiscreteLieFlowOptions
/// The name of a stop reason as used in reports (`"converged"`, `"plateau"`, ...).
inline const char* discrete_lie_flow_stop_reason_name(Discrete_lie_flow_stop_reason r)
{
  switch(r) {
  case Discrete_lie_flow_stop_reason::NOT_RUN: return "not_run";
  case Discrete_lie_flow_stop_reason::CONVERGED: return "converged";
  case Discrete_lie_flow_stop_reason::PLATEAU: return "plateau";
  case Discrete_lie_flow_stop_reason::STALLED: return "stalled";
  case Discrete_lie_flow_stop_reason::ITERATION_CAP: return "iteration_cap";
  case Discrete_lie_flow_stop_reason::INTERRUPTED: return "interrupted";
  case Discrete_lie_flow_stop_reason::COLLAPSED: return "collapsed";
  }
  return "unknown";
}

/// \ingroup PkgDiscreteLieFlowOptions
/// The name of a mode as used in reports (`"certified"`, `"paper"`, `"literal"`).
inline const char* discrete_lie_flow_mode_name(Discrete_lie_flow_mode m)
{
  switch(m) {
  case Discrete_lie_flow_mode::CERTIFIED: return "certified";
  case Discrete_lie_flow_mode::PAPER: return "paper";
  case Discrete_lie_flow_mode::LITERAL: return "literal";
  }
  return "unknown";
}

/// \ingroup PkgDiscreteLieFlowOptions
/// The name of a border as used in reports (`"automatic"`, `"circle"`, `"square"`, `"free"`, `"floating"`).
inline const char* discrete_lie_flow_border_name(Discrete_lie_flow_border b)
{
  switch(b) {
  case Discrete_lie_flow_border::AUTOMATIC: return "automatic";
  case Discrete_lie_flow_border::CIRCLE: return "circle";
  case Discrete_lie_flow_border::SQUARE: return "square";
  case Discrete_lie_flow_border::FREE: return "free";
  case Discrete_lie_flow_border::FLOATING: return "floating";
  }
  return "unknown";
}

/// \ingroup PkgDiscreteLieFlowOptions
/// The name of a spherical start as used in reports (`"tutte"`, `"conformal"`, `"mean-value"`, `"given"`).
inline const char* discrete_lie_flow_sphere_start_name(Discrete_lie_flow_sphere_start s)
{
  switch(s) {
  case Discrete_lie_flow_sphere_start::TUTTE: return "tutte";
  case Discrete_lie_flow_sphere_start::CONFORMAL: return "conformal";
  case Discrete_lie_flow_sphere_start::MEAN_VALUE: return "mean-value";
  case Discrete_lie_flow_sphere_start::GIVEN: return "given";
  }
  return "unknown";
}

/// \ingroup PkgDiscreteLieFlowOptions
/// What one iteration of the flow did; passed to the per-iteration callback.
struct Discrete_lie_flow_iteration
{
  std::size_t iteration = 0;   ///< 1-based
  double step = 0;             ///< the accepted λ
  double critical_step = 0;    ///< min over triangles of the critical root along the direction
  int limiting_face = -1;      ///< the triangle that attains it (index in the certified triangulation)
  double d_area = 0;           ///< area distortion after the step (optimum 2)
  double residual = 0;         ///< Σ_i (A_Ω(i) − A_M(i))² / (Σ_i A_Ω(i))², after the step
  std::size_t backtracks = 0;  ///< step halvings before acceptance
  std::size_t flips = 0;       ///< edge flips before the solve (paper mode)
  double seconds = 0;          ///< elapsed since the flow started
};

/// \ingroup PkgDiscreteLieFlowOptions
/// Settings of the certified flows only (the paper mode is the paper's flow).
struct Discrete_lie_flow_certified_options
{
  /// With a non-uniform density, stop as converged only once every region of
  /// ρ (every sublevel set {ρ < c} between two of its values, and its
  /// complement) also has its prescribed share of the domain's area within
  /// this, relative; regions of fewer than 32 faces are not held (their
  /// share is a few faces' rounding). 0: D_area alone decides. D_area weighs
  /// each face's own error, so it lets a whole region drift
  /// (doc/measure_control.md).
  double share_tolerance = 5e-3;
};

/// \ingroup PkgDiscreteLieFlowOptions
/// Settings of the paper mode only (`step_cap`, `delaunay_flips`,
/// `lump_targets_on_flowing_faces`, `degeneracy_ratio`) and of the literal
/// mode only (`residual_threshold`).
struct Discrete_lie_flow_paper_options
{
  /// Literal mode: the stop rule ‖h_M − h_Ω‖² < ε of Algorithm 1, with the
  /// vertex area elements in units of their mean (ε bounds the mean squared
  /// relative mismatch: 1e-3 is about 3% rms).
  double residual_threshold = 1e-3;
  /// Largest step λ: the line search samples below min(4·step_cap, μ·λ_crit);
  /// step 1 is the full linearised correction.
  double step_cap = 1.0;
  /// Flip the flowing mesh to Delaunay before each solve.
  bool delaunay_flips = true;
  /// Lump the targets A_M on the flowing faces (a deviation from Algorithm 1,
  /// whose literal reading — A_M lumped once on the input faces — stalls as
  /// soon as a vertex changes valence). `false` gives the literal reading.
  bool lump_targets_on_flowing_faces = true;
  /// A step is refused when a flowing face's normalised area ratio falls
  /// below this (the degeneracy guard; orientation alone lets a face
  /// collapse towards zero while staying "positive").
  double degeneracy_ratio = 1e-8;
};

/// \ingroup PkgDiscreteLieFlowOptions
/// Settings of the disk only (`Discrete_lie_flow_parameterizer_3`).
struct Discrete_lie_flow_disk_options
{
  /// What the boundary vertices slide on; `AUTOMATIC` detects it from the initial map.
  Discrete_lie_flow_border border = Discrete_lie_flow_border::AUTOMATIC;
  /// The certified mode flows a disk of at least this many faces coarse to
  /// fine (0: never): a hierarchy of coarser disks made by collapses that
  /// keep the border and the start fold-free, the coarsest flowed, its map
  /// carried down level by level (exact predicate at each), the finest
  /// flowed from there. The finest level's iterations are what a large mesh
  /// costs; this takes most of them away (doc/coarse_to_fine.md).
  std::size_t coarse_to_fine_faces = 100000;
  /// Threads of the certified flow's vertex sweeps on disks of 100,000
  /// faces or more (smaller ones sweep on one): 0 the hardware threads (at
  /// most 8), else that many. The result is the same whatever the number.
  int threads = 0;
};

/// \ingroup PkgDiscreteLieFlowOptions
/// Settings of the sphere only (`Discrete_lie_flow_sphere_parameterizer_3`).
struct Discrete_lie_flow_sphere_options
{
  /// Stop as converged only once the mean |log area ratio| is also ≤ this
  /// (0: D_area alone decides). D_area − 2 ≈ Σ w (log r)² is dominated by a
  /// few outlier faces, the mean by the many; a Sobolev flow at D_area 2.01
  /// still had a mean of 0.05–0.09.
  double log_area_tolerance = 0.02;
  /// The initial map (`TUTTE` or `CONFORMAL`; a map of the caller's own is
  /// given with `set_initial_map()`).
  Discrete_lie_flow_sphere_start start = Discrete_lie_flow_sphere_start::TUTTE;
  /// The certified mode (Tutte or mean-value start) maps a mesh of at least
  /// this many faces coarse to fine (0, the default: never): coarser closed
  /// meshes made by collapses that keep genus 0, the coarsest given its own
  /// start and flowed, its map carried down level by level (exact predicate
  /// at each), the caller's mesh flowed from there; the plain start when a
  /// level's map is refused. Off by default: on the large meshes measured
  /// it was slower than the plain flow (doc/sphere.md, "Coarse to fine").
  std::size_t coarse_to_fine_faces = 0;
  /// Threads of the certified flow's vertex sweeps on meshes of 50,000
  /// vertices or more (smaller ones sweep on one): 0 the hardware threads
  /// (at most 8), else that many. The result is the same whatever the number.
  int threads = 0;
};

/// \ingroup PkgDiscreteLieFlowOptions
/// Settings of the Discrete Lie Flow: what every flow reads, and one part
/// per mode and per domain for what only that one reads. Defaults are the
/// measured choices.
struct Discrete_lie_flow_options
{
  /// Which flow: certified (the default; the caller's triangles, never folded) or the paper's.
  Discrete_lie_flow_mode mode = Discrete_lie_flow_mode::CERTIFIED;
  /// Stop when D_area − 2 ≤ tolerance (D_area ≤ 2.01 by default).
  double tolerance = 1e-2;
  /// Hard cap on the number of iterations.
  std::size_t max_iterations = 500;
  /// Fraction μ ∈ (0, 1) of the smallest critical root that a step may take;
  /// 0 selects the measured default (0.8; in paper mode 0.95, the bound of
  /// its line search, doc/paper_mode.md; in literal mode 0.8, the top of the
  /// paper's range 0.2–0.8).
  double mu = 0;
  /// Plateau test: stop when the progress (the energy; in paper mode the
  /// best D_area) improved by less than this relative amount over
  /// `plateau_window` iterations (paper mode: at least 3e-4, and a slow-tail
  /// test besides; 0 turns both off there).
  double plateau_tolerance = 1e-4;
  /// The number of iterations the plateau test looks back over.
  std::size_t plateau_window = 10;
  /// Stall detector of the paper modes and of the spherical certified flow:
  /// the same face limits this many consecutive short steps (paper), or this
  /// many steps in a row need 20 halvings or more (sphere, certified).
  std::size_t stall_window = 25;
  /// The most step halvings an iteration may make; beyond, the flow stops as stalled.
  std::size_t max_backtracks = 60;
  /// Fixed step instead of the adaptive one (0: adaptive). For the paper's
  /// Table 2 experiment; a fixed step that would fold is reported as stalled
  /// (literal mode: as collapsed).
  double fixed_step = 0;
  /// Per-face density ρ (> 0) in the order of `faces(mesh)`; empty means
  /// ρ ≡ 1. Targets are A_M(f) = ρ_f · area_M(f), normalised. Property maps
  /// can be given with `set_face_density()` / `set_vertex_density()` instead.
  std::vector<double> face_density;
  /// Threads of the BLAS under the sparse solver (OpenBLAS, as CHOLMOD's
  /// supernodal factorization uses it) during the parameterization (initial
  /// map and flow): 0 chooses (one below 500,000 vertices, where more gain
  /// nothing measurable and spinning threads lose much on a busy machine;
  /// the BLAS's own setting above; and OpenMP's dynamic adjustment, which
  /// holds CHOLMOD's own loops to the idle cores), a positive number sets
  /// it, a negative one leaves the BLAS alone. The previous setting is
  /// restored after the run; OPENBLAS_NUM_THREADS, GOTO_NUM_THREADS,
  /// OMP_NUM_THREADS or OMP_THREAD_LIMIT in the environment override it
  /// (doc/design.md, "Solver threads").
  int solver_threads = 0;
  /// Keep the per-iteration history in the report.
  bool record_history = false;
  /// Called after every iteration; return false to stop the flow.
  std::function<bool(const Discrete_lie_flow_iteration&)> callback;
  /// What the certified flows alone read.
  Discrete_lie_flow_certified_options certified;
  /// What the paper mode alone reads.
  Discrete_lie_flow_paper_options paper;
  /// What the disk alone reads.
  Discrete_lie_flow_disk_options disk;
  /// What the sphere alone reads.
  Discrete_lie_flow_sphere_options sphere;
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
