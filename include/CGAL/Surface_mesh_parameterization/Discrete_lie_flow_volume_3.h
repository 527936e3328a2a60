// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_DISCRETE_LIE_FLOW_VOLUME_3_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_DISCRETE_LIE_FLOW_VOLUME_3_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_options.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_report.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_sphere_3.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/default_solver.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/volume/volume_flow.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/volume/volume_mesh.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/volume/volume_paper_flow.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/volume/volume_start.h>

#include <CGAL/Surface_mesh_parameterization/Error_code.h>

#include <array>
#include <chrono>
#include <cmath>
#include <functional>
#include <iomanip>
#include <map>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgDiscreteLieFlowOptions
/// Settings of `Discrete_lie_flow_volume_parameterizer_3`.
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
  /// Threads of the flow's per-tetrahedron and per-vertex passes: 0 (the
  /// default) automatic, one below 150,000 tetrahedra, else the hardware
  /// threads (at most 8); the result is the same whatever the number.
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

namespace internal {
namespace dlf {

/// The flow's settings that come straight from the options (the callback
/// and the density levels are set by the caller).
inline Volume_flow_settings volume_flow_settings(const Discrete_lie_flow_volume_options& O)
{
  Volume_flow_settings S;
  S.tolerance = O.tolerance;
  S.max_iterations = O.max_iterations;
  S.mu = O.mu;
  S.cg_max_iterations = O.cg_max_iterations;
  S.cholesky_every = O.cholesky_every;
  S.threads = O.threads;
  S.coarse_aggregate = O.coarse_aggregate;
  S.cg_forcing = O.cg_forcing;
  S.star_shaped_border = O.star_shaped_border;
  S.share_tolerance = O.share_tolerance;
  S.paper_collapse_guard = O.paper_collapse_guard;
  return S;
}

} // namespace dlf
} // namespace internal

/// \ingroup PkgDiscreteLieFlowParameterizers
///
/// Volume-preserving (or density-prescribed) map of a tetrahedral mesh of a
/// topological ball onto the unit ball, the volumetric Discrete Lie Flow:
/// the paper (Su et al. 2019, \ref DLFBibSu2019) proves its flow in any
/// dimension and leaves tetrahedral meshes as future work (§7.2).
///
/// The start is certified bijective: the border triangles go onto the unit
/// sphere by `Discrete_lie_flow_sphere_parameterizer_3` (every spherical
/// triangle positive by the exact predicate), the interior vertices by
/// Tutte's barycentric embedding; when that folds tets (it can in 3D),
/// Garanzha et al.'s regularised barrier (χ_ε(u) = (u + √(ε² + u²))/2 with
/// ε continuation) untangles them until every tet is positive by CGAL's
/// exact `orientation(p, q, r, s)`, else the run fails with
/// `ERROR_INITIAL_MAP_FOLDED` and a message counting the folds.
///
/// The flow descends D_vol = Σ w_t (r_t + 1/r_t) (w_t the tet's prescribed
/// share ρ_t vol_t / Σ ρ vol, r_t its achieved share over w_t; minimum 2)
/// along a regularised Gauss–Newton direction solved by preconditioned
/// conjugate gradients: the interior vertices move in space, the border
/// vertices in the tangent planes of the sphere and are re-normalised
/// after the step. Every step is at most μ times the smallest positive
/// root of the tets' cubics det(p + λv), then halved until the energy drops
/// and every tet is positive by the exact predicate: the result is never
/// folded. The paper mode (`options().mode = Discrete_lie_flow_mode::PAPER`)
/// replaces the direction by the paper's Poisson step, from the same start
/// and with the same certification.
///
/// \tparam SolverTraits_ `CGAL::Eigen_solver_traits<S>` with `S` an Eigen
///   sparse SPD solver with `analyzePattern()`/`factorize()` for Tutte's system of the start (the border's spherical map uses its own default).
template <class SolverTraits_ = Default>
class Discrete_lie_flow_volume_parameterizer_3
{
public:
  /// The solver traits of the start's sparse SPD system (Tutte's embedding).
  typedef typename Default::Get<SolverTraits_,
    Eigen_solver_traits<internal::dlf::Default_spd_solver> >::type Solver_traits;

  /// \param options flow settings (tolerances, caps, density, callback)
  explicit Discrete_lie_flow_volume_parameterizer_3(const Discrete_lie_flow_volume_options& options =
                                                      Discrete_lie_flow_volume_options())
    : m_options(options)
  {}

  /// The settings, to read or change before `parameterize()`.
  Discrete_lie_flow_volume_options& options() { return m_options; }
  /// The settings.
  const Discrete_lie_flow_volume_options& options() const { return m_options; }
  /// The report of this object's last run.
  const Discrete_lie_flow_volume_report& report() const { return m_report; }

  /// Maps the tet soup (`points`: anything with `x()`, `y()`, `z()`;
  /// `tets`: four 0-based indices per tet, positively oriented) into the
  /// unit ball: `ball` receives one point per input point (only on success).
  template <class InputPoint, class OutputPoint>
  Error_code parameterize(const std::vector<InputPoint>& points, const std::vector<std::array<int, 4> >& tets,
                          std::vector<OutputPoint>& ball)
  {
    std::vector<internal::dlf::Vec3> xyz(points.size());
    for(std::size_t i = 0; i < points.size(); ++i)
      xyz[i] = {{ CGAL::to_double(points[i].x()), CGAL::to_double(points[i].y()), CGAL::to_double(points[i].z()) }};
    std::vector<internal::dlf::Vec3> out;
    const Error_code code = run(xyz, tets, out);
    if(code != OK) return code;
    ball.clear();
    for(const auto& p : out) ball.push_back(OutputPoint(p[0], p[1], p[2]));
    return OK;
  }

  /// Maps the cells of a `Mesh_complex_3_in_triangulation_3` (CGAL's Mesh_3
  /// output) into the unit ball: `ball_map` (a writable property map
  /// `Vertex_handle` → point constructible from three doubles) receives the
  /// image of every vertex of a cell in the complex. The tet of a cell is
  /// (v0, v1, v2, v3) as the triangulation stores it (positively oriented).
  template <class C3T3, class VertexBallMap>
  Error_code parameterize_complex(const C3T3& c3t3, VertexBallMap ball_map)
  {
    typedef typename C3T3::Triangulation::Vertex_handle Vertex_handle;
    std::map<Vertex_handle, int> index;
    std::vector<Vertex_handle> handles;
    std::vector<internal::dlf::Vec3> xyz;
    std::vector<std::array<int, 4> > tets;
    for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c) {
      std::array<int, 4> t;
      for(int k = 0; k < 4; ++k) {
        const Vertex_handle v = c->vertex(k);
        auto it = index.find(v);
        if(it == index.end()) {
          it = index.emplace(v, int(handles.size())).first;
          handles.push_back(v);
          const auto& p = c3t3.triangulation().point(v);
          xyz.push_back({{ CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()) }});
        }
        t[std::size_t(k)] = it->second;
      }
      tets.push_back(t);
    }
    std::vector<internal::dlf::Vec3> out;
    const Error_code code = run(xyz, tets, out);
    if(code != OK) return code;
    typedef typename boost::property_traits<VertexBallMap>::value_type Point;
    for(std::size_t i = 0; i < handles.size(); ++i) put(ball_map, handles[i], Point(out[i][0], out[i][1], out[i][2]));
    return OK;
  }

private:
  Error_code fail(int code, const std::string& message)
  {
    m_report.status = Error_code(code);
    m_report.message = message.empty() ? std::string(discrete_lie_flow_error_message(code)) : message;
    return Error_code(code);
  }

  Error_code run(const std::vector<internal::dlf::Vec3>& xyz, const std::vector<std::array<int, 4> >& tets,
                 std::vector<internal::dlf::Vec3>& x)
  {
    namespace D = internal::dlf;
    typedef std::chrono::steady_clock Clock;
    const Clock::time_point t_start = Clock::now();
    Discrete_lie_flow_volume_report& R = m_report;
    R = Discrete_lie_flow_volume_report();
    const Discrete_lie_flow_volume_options& O = m_options;
    if(!(O.mu > 0 && O.mu < 1)) return fail(ERROR_WRONG_PARAMETER, "mu must lie in (0, 1)");
    if(!(O.tolerance > 0)) return fail(ERROR_WRONG_PARAMETER, "the tolerance must be positive");
    if(O.mode == Discrete_lie_flow_mode::LITERAL)
      return fail(ERROR_WRONG_PARAMETER, "the volumetric flow has a certified and a paper mode, no literal one");
    R.vertices = xyz.size();
    R.tets = tets.size();
    R.threads = D::volume_flow_threads(O.threads, tets.size());
    D::Ball_topology topo;
    std::string message;
    int code = D::check_ball(xyz, tets, topo, message);
    if(code != OK) return fail(code, message);
    R.border_vertices = topo.border_vertices;
    R.border_faces = topo.border_faces.size();
    // Targets ρ_t vol_t.
    if(!O.tet_density.empty() && O.tet_density.size() != tets.size())
      return fail(ERROR_INVALID_DENSITY, "the density has " + std::to_string(O.tet_density.size()) +
                                         " values for " + std::to_string(tets.size()) + " tetrahedra");
    std::vector<double> target(tets.size());
    for(std::size_t t = 0; t < tets.size(); ++t) {
      const double rho = O.tet_density.empty() ? 1. : O.tet_density[t];
      if(!(rho > 0) || !std::isfinite(rho))
        return fail(ERROR_INVALID_DENSITY, "the density of tetrahedron " + std::to_string(t) + " is " +
                                           std::to_string(rho) + "; it must be finite and positive");
      const D::Tet& k = tets[t];
      target[t] = rho * D::tet_det(xyz[std::size_t(k[0])], xyz[std::size_t(k[1])], xyz[std::size_t(k[2])], xyz[std::size_t(k[3])]);
      if(!(target[t] > 0))
        return fail(ERROR_DEGENERATE_INPUT, "tetrahedron " + std::to_string(t) +
                                            " has a volume that rounds to zero or below in doubles");
    }
    // The certified start.
    D::Volume_start_info start;
    const auto border_to_sphere = [&O](const D::Volume_border_mesh& border, auto sphere, Discrete_lie_flow_report& report) {
      Discrete_lie_flow_sphere_parameterizer_3<D::Volume_border_mesh> flow(O.border);
      const Error_code c = flow.parameterize(border, sphere);
      report = flow.report();
      return c;
    };
    code = D::volume_start<typename Solver_traits::Solver>(xyz, tets, topo, target, border_to_sphere,
                                                           O.untangle_max_iterations, O.callback, x, start, message);
    R.border = start.border;
    R.start_negative_tets = start.tutte_negative_tets;
    R.start_flat_tets = start.tutte_flat_tets;
    R.untangle_iterations = start.untangle_iterations;
    R.seconds_border = start.seconds_border;
    R.seconds_interior = start.seconds_interior;
    R.seconds_untangle = start.seconds_untangle;
    if(code != OK) return fail(code, message);
    R.start_certified = true;
    // The certified flow.
    D::Volume_energy energy(target);
    std::vector<double> u;
    D::tet_dets(x, tets, u);
    R.initial_d_vol = energy.value(u, 0);
    D::Volume_flow_settings S = D::volume_flow_settings(O);
    S.callback = O.callback; // the flow's iterations too, not only the start's
    if(!O.tet_density.empty() && O.share_tolerance > 0) {
      std::map<double, int> ids;
      for(double rho : O.tet_density) {
        if(ids.size() > 32) break;
        ids.emplace(rho, int(ids.size()));
      }
      if(ids.size() <= 32 && ids.size() > 1) {
        S.level.resize(tets.size());
        S.level_share.assign(ids.size(), 0.);
        double Tsum = 0;
        for(std::size_t t = 0; t < tets.size(); ++t) {
          S.level[t] = ids[O.tet_density[t]];
          S.level_share[std::size_t(S.level[t])] += target[t];
          Tsum += target[t];
        }
        for(double& a : S.level_share) a /= Tsum;
      }
    }
    const Clock::time_point t_flow = Clock::now();
    // With density levels: where D_vol's minimum leaves a level short of its
    // share (its tets at the border cannot all reach their volumes), the
    // level's targets are scaled by prescribed/achieved and the flow runs
    // again from there (at most 6 rounds); D_vol is always reported against
    // the prescribed targets.
    std::vector<double> flow_target = target;
    D::Volume_flow_outcome out;
    for(int round = 0;; ++round) {
      std::vector<D::Volume_iteration>* history = O.record_history ? &R.history : nullptr;
      const D::Volume_flow_outcome o =
        O.mode == Discrete_lie_flow_mode::PAPER
          ? D::run_volume_paper_flow(x, tets, topo.on_border, topo.border_faces, flow_target, S, history)
          : D::run_volume_flow(x, tets, topo.on_border, topo.border_faces, flow_target, S, history);
      out.iterations += o.iterations;
      out.rejected_by_exact_check += o.rejected_by_exact_check;
      out.cg_iterations += o.cg_iterations;
      out.stop_reason = o.stop_reason;
      if(S.level.empty() || round >= 5 || o.stop_reason == Discrete_lie_flow_stop_reason::CONVERGED ||
         o.stop_reason == Discrete_lie_flow_stop_reason::INTERRUPTED)
        break;
      std::vector<double> achieved;
      D::tet_dets(x, tets, u);
      if(D::level_share_error(S.level, S.level_share, u, &achieved) <= S.share_tolerance) break;
      for(std::size_t t = 0; t < tets.size(); ++t) {
        const std::size_t k = std::size_t(S.level[t]);
        flow_target[t] *= S.level_share[k] / achieved[k];
      }
    }
    // Converged: D_vol against the prescribed targets, and the shares.
    // (The last round may have stopped on its rescaled targets' plateau with
    // both tolerances met on the prescribed ones: that is converged.)
    D::tet_dets(x, tets, u);
    const double d_vol_reached = energy.value(u, 0);
    const double share_error_reached = D::level_share_error(S.level, S.level_share, u);
    const bool reached = d_vol_reached - 2 <= O.tolerance && share_error_reached <= S.share_tolerance;
    if(reached && out.stop_reason != Discrete_lie_flow_stop_reason::INTERRUPTED)
      out.stop_reason = Discrete_lie_flow_stop_reason::CONVERGED;
    else if(!reached && out.stop_reason == Discrete_lie_flow_stop_reason::CONVERGED)
      out.stop_reason = Discrete_lie_flow_stop_reason::PLATEAU;
    R.seconds_flow = std::chrono::duration<double>(Clock::now() - t_flow).count();
    R.stop_reason = out.stop_reason;
    R.iterations = out.iterations;
    R.rejected_by_exact_check = out.rejected_by_exact_check;
    R.cg_iterations = out.cg_iterations;
    // Measures of the result, recomputed from scratch.
    const D::Tet_orientation_counts bad = D::count_bad_tets(x, tets);
    R.inverted_border_faces = D::count_bad_border_faces(x, topo.border_faces);
    R.inverted_tets = bad.negative;
    R.flat_tets = bad.flat;
    D::tet_dets(x, tets, u);
    R.final_d_vol = energy.value(u, 0);
    double U = 0, Tsum = 0;
    for(std::size_t t = 0; t < tets.size(); ++t) { U += u[t]; Tsum += target[t]; }
    R.volume = U / 6;
    R.volume_ratio.resize(tets.size());
    R.min_ratio = std::numeric_limits<double>::infinity();
    R.max_ratio = 0;
    double sum_abs = 0;
    std::map<double, Discrete_lie_flow_volume_share> levels;
    for(std::size_t t = 0; t < tets.size(); ++t) {
      const double r = (u[t] / U) / (target[t] / Tsum);
      R.volume_ratio[t] = r;
      R.min_ratio = (std::min)(R.min_ratio, r);
      R.max_ratio = (std::max)(R.max_ratio, r);
      const double l = std::abs(std::log(r));
      sum_abs += l;
      R.log_volume_max_abs = (std::max)(R.log_volume_max_abs, l);
      const double rho = O.tet_density.empty() ? 1. : O.tet_density[t];
      if(levels.size() < 33 || levels.count(rho)) {
        Discrete_lie_flow_volume_share& s = levels[rho];
        s.density = rho;
        ++s.tets;
        s.target_share += target[t] / Tsum;
        s.achieved_share += u[t] / U;
      }
    }
    R.log_volume_mean_abs = sum_abs / double(tets.size());
    if(levels.size() <= 32)
      for(const auto& kv : levels) {
        R.shares.push_back(kv.second);
        R.share_error_max = (std::max)(R.share_error_max, std::abs(kv.second.relative_error()));
      }
    R.seconds_total = std::chrono::duration<double>(Clock::now() - t_start).count();
    if(bad.not_positive() != 0 || (O.star_shaped_border && R.inverted_border_faces != 0)) // cannot happen: every accepted step is certified
      return fail(ERROR_NO_1_TO_1_MAPPING, "the flow left " + std::to_string(bad.not_positive()) +
                                           " tetrahedra and " + std::to_string(R.inverted_border_faces) +
                                           " border triangles not positive");
    R.status = OK;
    if(R.converged()) {
      R.message = "Success";
    } else {
      // As the surface flows: where it stopped, each goal missed with its value.
      std::ostringstream missed;
      missed << std::setprecision(6);
      if(!(d_vol_reached - 2 <= O.tolerance)) missed << "D_vol " << d_vol_reached << " > " << 2 + O.tolerance;
      if(!S.level.empty() && !(share_error_reached <= S.share_tolerance))
        missed << (missed.tellp() > 0 ? "; " : "") << "share error " << share_error_reached << " > " << S.share_tolerance;
      std::ostringstream s;
      s << std::setprecision(6) << "not converged: stopped (" << discrete_lie_flow_stop_reason_name(R.stop_reason)
        << ") after " << R.iterations << " iterations short of "
        << (missed.tellp() > 0 ? missed.str() : std::string("the flow's own stop rule"))
        << "; the map is valid and fold-free, D_vol " << R.final_d_vol;
      R.message = s.str();
    }
    return OK;
  }

  Discrete_lie_flow_volume_options m_options;
  Discrete_lie_flow_volume_report m_report;
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
