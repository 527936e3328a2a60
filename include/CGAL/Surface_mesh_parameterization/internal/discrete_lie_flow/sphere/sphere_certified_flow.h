// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The certified flow on the unit sphere as a policy of the flow driver: the
// planar certified flow carried over to the flat triangles between sphere
// points, in two phases.
// - Opening: energy D_area on the cone areas ½ det[p0, p1, p2] (zero exactly
//   where the orientation predicate is, so a barrier for it even on the huge
//   faces of a start compressed by e^30); direction: the tangential Sobolev
//   gradient, preconditioned by the cotangent stiffness of the current
//   spherical mesh plus a small lumped mass term (x, y, z share one
//   factorisation), L-BFGS-corrected once D_area < 3. If it stalls or would
//   end while the flat D_area is still above 10, it goes on with the
//   spherical areas of the triangles as its element (faces spread over
//   nearly a hemisphere have small cone areas; sphere_spherical_area.h).
// - Polish, once D_area < 2.05 or the opening stops paying (plateau, the
//   flat D_area rising, or steps capped short by a few faces near
//   inversion): energy E(flat areas) + κ E(cone areas), E the D_area with
//   face weights half area, half uniform (Weighted_area_energy); direction:
//   regularised Gauss–Newton (sphere_gauss_newton.h), then vertex sweeps
//   (sphere_relaxation.h).
// Step: μ times the smallest positive root of the per-face orientation cubics
// det[p_k + λ d_k] (and at most 1 in the polish), points re-normalised,
// Armijo backtracking, every accepted step certified by the exact
// orientation of every face on the stored doubles. The measurements behind
// each choice: doc/sphere.md.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_SPHERE_CERTIFIED_FLOW_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_SPHERE_CERTIFIED_FLOW_H

#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/area_barrier_energy.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/area_elements.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/certification.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/critical_step.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/default_solver.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/density_levels.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/flow/flow_driver.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/sparse_solver.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/sphere/sphere_directions.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/sphere/sphere_gauss_newton.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/sphere/sphere_problem.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/sphere/sphere_relaxation.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/sphere/sphere_spherical_area.h>

#include <Eigen/Sparse>

#include <algorithm>
#include <array>
#include <cmath>
#include <thread>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// Internal knobs of the spherical flow, with the measured defaults
/// (doc/sphere.md, "Measurements behind the defaults", has the values that lost).
struct Sphere_flow_settings
{
  /// Weight of the lumped mass term in the Sobolev metric, relative to the
  /// stiffness (both of the current flat triangles). The l = 1 spherical
  /// harmonics have Dirichlet/mass ratio 2, so 0.1 keeps the global
  /// (Möbius-like) component of the gradient amplified but bounded.
  double mass_weight = 0.1;
  /// L-BFGS pairs kept on top of the Sobolev metric (K⁻¹ as the initial
  /// inverse Hessian), used only once D_area < `lbfgs_below`: far from the
  /// targets the barrier makes the curvature pairs misleading.
  std::size_t lbfgs_memory = 3;
  double lbfgs_below = 3;
  /// The polish's energy is E(flat areas) + `cone_weight` × E(cone areas).
  /// The flat areas are the metric's, but not a barrier: a triangle whose
  /// plane passes through the centre (orientation zero) keeps a large flat
  /// area. The cone area ½ det[p0, p1, p2] = flat area × plane distance h is
  /// one, so the sum is.
  double cone_weight = 0.03;
  /// Share of uniform weights 1/F in the polish energy's face weights (the
  /// rest area weights): D_area weighs faces by area, the mean |log area
  /// ratio| goal counts each face once.
  double uniform_weight = 0.5;
  /// D_area below which the direction is the regularised Gauss–Newton one
  /// (sphere_gauss_newton.h) instead of the Sobolev/L-BFGS one.
  double newton_below = 2.05;
  /// The opening crawls when a few faces near inversion cap every step
  /// (λ = μ λ_crit) while D_area is already low; the polish's vertex sweeps
  /// move exactly those faces. After three accepted opening steps shorter
  /// than `crawl_step` with D_area below `crawl_below`, polish.
  double crawl_step = 0.01;
  double crawl_below = 2.1;
  /// Irregular meshes (slivers, needles, face areas spanning decades) crawl
  /// from higher up: after `crawl_far_steps` accepted opening steps in a row
  /// shorter than `crawl_step` with D_area below `crawl_far_below`, polish
  /// too. (Long protrusions alternate short and long opening steps there:
  /// three in a row are not yet a crawl.)
  double crawl_far_below = 3;
  std::size_t crawl_far_steps = 8;
  /// The polish's direction: Gauss–Newton (else the opening's Sobolev/L-BFGS one).
  bool polish_gauss_newton = true;
  /// Initial ε of the Levenberg–Marquardt regularisation, relative to tr(H)/tr(S).
  double newton_regularization = 1e-2;
  /// Vertex-by-vertex relaxation sweeps after each polish step (sphere_relaxation.h).
  std::size_t relaxation_sweeps = 10;
  /// Sweeps visit the corners of the faces with |log area ratio| above this (0: every vertex).
  double relaxation_threshold = 0;
  /// Large meshes (from this many vertices on; CGAL's data set has none)
  /// spend their time in factorisations and sweeps of 100K unknowns and
  /// more, so there:
  /// - the polish's sweeps (every vertex) run on `sweep_parts` regions of
  ///   the mesh at once, then on the vertices between them
  ///   (`Sweep_partition`; the result does not depend on the number of
  ///   threads), and only `large_relaxation_sweeps` of them: the sweeps
  ///   after the fifth lowered the energy by 0.1% each at most;
  /// - CHOLMOD merges columns into coarser supernodes
  ///   (`use_coarse_supernodes()`);
  /// - an opening step shorter than `reuse_factor_below` lets the next
  ///   direction be solved with the last factorisation of the Sobolev
  ///   metric (every second iteration at most): the compressed start of a
  ///   scanned mesh unwinds in dozens of such steps.
  /// Measurements: doc/sphere.md, "Large irregular meshes: the cost of an
  /// iteration".
  std::size_t large_from = 50000;
  std::size_t sweep_parts = 8;
  std::size_t large_relaxation_sweeps = 5;
  double reuse_factor_below = 1e-2;
  /// Fans of needles stall the opening: the same few faces cap the Sobolev
  /// step at 1e-6 – 1e-5 for hundreds of iterations while D_area falls by
  /// 0.3–0.6% per step. When an opening step shorter than `crawl_step`
  /// lowers D_area (still above `local_sweep_above`) by less than
  /// `local_sweep_progress` (relative) and its
  /// limiting face limited at least `local_sweep_repeats` − 1 of the last
  /// `local_sweep_memory` steps too, `relaxation_sweeps` sweeps of the
  /// opening's energy move the vertices within `local_sweep_rings` rings of
  /// that face (0 memory: never). Local, so their cost is nothing beside a
  /// step. (Fired more often, they slowed the data set's compressed starts
  /// and the low-D_area openings of triceratops and bull: doc/sphere.md,
  /// "Irregular meshes".)
  std::size_t local_sweep_memory = 4;
  std::size_t local_sweep_repeats = 3;
  double local_sweep_progress = 0.003;
  double local_sweep_above = 10;
  std::size_t local_sweep_rings = 2;
  /// Levenberg–Marquardt update from the accepted step's length, not only
  /// its halvings (see `sphere_regularization()`).
  bool capped_steps_regularize = true;
  /// In a polish that a crawling opening started (`crawl_far_steps`), while
  /// the flat D_area is above `capped_far_above`, a capped step lets ε grow
  /// up to `capped_far_ceiling` instead of only back to
  /// `newton_regularization`. Irregular meshes crawl at D_area 2.8
  /// (diplodocus Loop×1 jittered), where the least regularised Gauss–Newton
  /// direction nearly inverts a few slivers and every step is capped at
  /// 0.02–0.07; the smoother direction of a larger ε takes long steps
  /// there. Elsewhere the ceiling stays the starting ε: growing to 1e4
  /// everywhere lost the refined part.off's convergence. A ceiling of 1
  /// instead of 0.1 saved two more iterations there but took bull's
  /// plateau from 314 to 373 iterations. Measurements: doc/sphere.md,
  /// "A compressed start on an irregular mesh".
  double capped_far_above = 2.5;
  double capped_far_ceiling = 0.1;
  /// The first time the opening's local sweeps would fire, or the opening
  /// would hand over to the polish (a plateau, a rising flat D_area, a
  /// crawl), while the flat D_area is above `spherical_opening_above`, the
  /// opening goes on with the spherical areas of the triangles as its
  /// element instead of the cone areas (sphere_spherical_area.h; 0: never).
  /// Fans of needles: bunny00 `+needles2` left its cone-area opening at
  /// flat D_area 87 with a few faces spread over nearly a hemisphere,
  /// corners near one great circle, whose cone areas looked right, and the
  /// polish crawled from there (13.35 after 500 iterations; 8.53 with the
  /// switch). Spherical areas from the start cost the data set's coarse
  /// meshes up to 44% more iterations; no data-set row stalls or hands
  /// over above D_area 10, so they run as before. Measurements:
  /// doc/sphere.md, "What the polish inherited from the opening".
  double spherical_opening_above = 10;
  /// Once on spherical areas, the opening hands over to the polish as soon
  /// as the flat D_area is below `spherical_polish_below`. bunny00
  /// `+needles2`: converged in 482 iterations (D_area 2.0025) with 15; 3.3
  /// at iteration 414 with 40; 8.53 at the 500-iteration cap without (the
  /// spherical opening crawls at steps of 2e-5–1e-4 from D_area 20 down).
  double spherical_polish_below = 15;
};

/// Levenberg–Marquardt update of the polish's ε after an accepted step of
/// length λ: only a full step lets it shrink by 4; two halvings or more
/// multiply it by 4 (as `updated_regularization()`); a step cut short below
/// λ = 1/2 by the critical root of a face that the direction nearly
/// inverts is a model not to be trusted as far as its full step, so ε grows
/// by min(4, 1/λ), but not past `capped_ceiling` (the starting ε: growing to
/// 1e4 there turned the refined part.off's converging polish into a plateau
/// at mean |log r| 0.0215). (`updated_regularization()` looks at the
/// halvings alone: a step capped at μ λ_crit without halvings shrank ε by 4
/// every time, down to 1e-8, and the ever less regularised direction nearly
/// inverted ever more faces: on irregular meshes the polish crawled at steps
/// of 1e-4–1e-3 for hundreds of iterations; doc/sphere.md, "Irregular meshes".)
inline double sphere_regularization(double eps, const Flow_step& step, double capped_ceiling)
{
  if(step.lambda >= 1 && step.halvings == 0) return (std::max)(eps / 4, 1e-8);
  if(step.halvings >= 2) return (std::min)(eps * 4, 1e4);
  if(step.lambda >= 0.5) return eps;
  return (std::max)(eps, (std::min)(eps * (std::min)(4., 1 / step.lambda), capped_ceiling));
}

/// The most a capped step lets the polish's ε grow to at flat D_area
/// `d_area`, in a polish that a crawling opening started or not (see
/// `Sphere_flow_settings::capped_far_ceiling`).
inline double sphere_capped_ceiling(const Sphere_flow_settings& settings, double d_area, bool after_crawl)
{
  return after_crawl && d_area > settings.capped_far_above ? settings.capped_far_ceiling : settings.newton_regularization;
}

/// The certified spherical flow as a policy of `run_flow()` (flow_driver.h),
/// from the positively oriented unit vectors `p` (moved in place; always
/// certified and not worse than the start).
template <class EigenSolver>
class Sphere_certified_flow : public Flow_policy_base
{
public:
  Sphere_certified_flow(const Sphere_problem& P, std::vector<Vec3>& p, const Discrete_lie_flow_options& opt,
                        EigenSolver& eigen_solver, const Sphere_flow_settings& settings)
    : Flow_policy_base(stopping_rules(opt)), m_P(P), m_p(p), m_opt(opt), m_settings(settings), m_n(p.size()), m_energy(P.target),
      m_polish_energy(P.target, settings.uniform_weight), m_cone_energy(P.target, 0), m_kappa(settings.cone_weight), m_solver(eigen_solver),
      m_newton_solver(m_newton_eigen_solver), m_eps(settings.newton_regularization), m_around(0, std::vector<Face>()),
      m_d(p.size()), m_trial(p.size()), m_levels(P.xyz, P.faces, P.target)
  {
    if(m_n >= settings.large_from) {
      use_coarse_supernodes(eigen_solver);
      use_coarse_supernodes(m_newton_eigen_solver);
    }
  }

  bool start(Flow_outcome& out)
  {
    m_E = evaluate(m_p, m_u, m_w);
    m_D = flat_d_area(m_p, m_P.faces, m_P.target);
    out.initial_d_area = out.final_d_area = m_D;
    m_stopping.restart(m_E);
    return std::isfinite(m_E);
  }

  bool converged()
  {
    if(!(m_D - 2 <= m_opt.tolerance)) return false;
    if(m_opt.sphere.log_area_tolerance > 0 && !(flat_mean_abs_log_ratio(m_p, m_P.faces, m_P.target) <= m_opt.sphere.log_area_tolerance))
      return false;
    if(!(m_opt.certified.share_tolerance > 0) || m_levels.uniform()) return true;
    signed_areas_sphere(m_p, m_P.faces, m_flat);
    return m_levels.error(m_flat) <= m_opt.certified.share_tolerance;
  }

  /// d = −P H g, P the tangent projection, H = K⁻¹ (the Sobolev gradient)
  /// far from the targets, L-BFGS-corrected K⁻¹ once D_area < lbfgs_below,
  /// the Gauss–Newton inverse in the polish.
  Direction_status direction(Flow_outcome& out)
  {
    if(!m_polish && (m_force_polish || m_D < m_settings.newton_below)) {
      m_polish = true;
      m_E = evaluate(m_p, m_u, m_w);
      m_stopping.restart(m_E);
      m_lambda_prev = infinite_step();
    }
    gradient();
    const Sparse_matrix* K;
    {
      Scoped_timer timer(out.seconds_assembly);
      K = &m_sobolev.assemble(m_n, [&](auto&& add) {
        sphere_sobolev_contributions(m_p, m_P.faces, m_settings.mass_weight, add);
      });
    }
    ++out.factorizations;
    m_newton = m_polish && m_settings.polish_gauss_newton; // factorises its own matrix instead of K
    if(m_newton) newton_direction(*K, out);
    else sobolev_direction(*K, out);
    m_slope = 0;
    double gg = 0;
    for(std::size_t v = 0; v < m_n; ++v) { m_slope += dot(m_g[v], m_d[v]); gg += dot(m_g[v], m_g[v]); }
    if(!(m_slope < 0)) {
      for(std::size_t v = 0; v < m_n; ++v) m_d[v] = {{ -m_g[v][0], -m_g[v][1], -m_g[v][2] }};
      m_slope = -gg;
      clear_pairs();
    }
    return m_slope < 0 ? Direction_status::DESCENT : Direction_status::NO_DESCENT;
  }

  void bound(Flow_step& step)
  {
    const std::vector<Face>& F = m_P.faces;
    step.critical = smallest_critical_step(F.size(), [&](std::size_t f, double best) {
      const std::size_t a = std::size_t(F[f][0]), b = std::size_t(F[f][1]), c = std::size_t(F[f][2]);
      const std::array<double, 4> k = orientation_cubic(m_p[a], m_p[b], m_p[c], m_d[a], m_d[b], m_d[c]);
      // Most faces cannot invert before the smallest root found so far: the
      // cubic stays above k3 − (|k2| + (|k1| + |k0| λ) λ) λ > 0 on [0, λ]
      // (a margin far above the rounding of these positive terms).
      if(((std::abs(k[0]) * best + std::abs(k[1])) * best + std::abs(k[2])) * best < (1 - 1e-9) * k[3])
        return infinite_step();
      return smallest_positive_root(k[0], k[1], k[2], k[3]);
    }, step.limiting);
    step.lambda = certified_first_step(m_opt, m_newton, m_lambda_prev, step.critical);
  }

  /// Armijo backtracking; the exact predicate has the last word. The slope
  /// is that of the linear move; re-normalisation only changes it at second order.
  void search(Flow_step& step, Flow_outcome& out)
  {
    for(; step.halvings <= m_opt.max_backtracks; ++step.halvings, step.lambda *= 0.5) {
      for(std::size_t v = 0; v < m_n; ++v)
        m_trial[v] = normalized(Vec3{{ m_p[v][0] + step.lambda * m_d[v][0], m_p[v][1] + step.lambda * m_d[v][1],
                                       m_p[v][2] + step.lambda * m_d[v][2] }});
      m_E_trial = evaluate(m_trial, m_u_trial, m_w_trial);
      if(!(m_E_trial <= m_E + 1e-4 * step.lambda * m_slope)) continue;
      if(!certified_trial_sphere(m_trial, m_P.faces)) { ++out.rejected_by_exact_check; continue; }
      step.accepted = true;
      return;
    }
  }

  void commit(const Flow_step& step, Flow_outcome& out)
  {
    if(m_newton) {
      // m_D is still the D_area the step started from.
      m_eps = m_settings.capped_steps_regularize ? sphere_regularization(m_eps, step, sphere_capped_ceiling(m_settings, m_D, m_after_crawl))
                                                 : updated_regularization(m_eps, step.halvings);
    }
    m_p_prev = m_p;
    m_g_prev = m_g;
    m_p.swap(m_trial);
    m_u.swap(m_u_trial);
    m_w.swap(m_w_trial);
    m_E = m_E_trial;
    if(m_polish && m_settings.relaxation_sweeps > 0) relax(out);
    else if(!m_polish) relax_around_repeated_limiter(step, out);
    m_D = flat_d_area(m_p, m_P.faces, m_P.target);
    m_lambda_prev = step.lambda;
    out.final_d_area = m_D;
    if(!m_polish) {
      // The cone areas differ from the flat ones on coarse meshes: once the
      // flat D_area keeps rising under the cone energy, or a few faces near
      // inversion cap every step, polish instead.
      m_rising = m_D > m_best_cone_D ? m_rising + 1 : 0;
      m_best_cone_D = (std::min)(m_best_cone_D, m_D);
      m_crawling = (m_D < m_settings.crawl_below && step.lambda < m_settings.crawl_step) ? m_crawling + 1 : 0;
      m_crawling_far = (m_D < m_settings.crawl_far_below && step.lambda < m_settings.crawl_step) ? m_crawling_far + 1 : 0;
      m_after_crawl = m_rising < 3 && m_crawling < 3 && m_crawling_far >= m_settings.crawl_far_steps;
      if(m_rising >= 3 || m_crawling >= 3 || m_crawling_far >= m_settings.crawl_far_steps) hand_over();
      // Spherical areas do not see great-circle slivers (large flat areas,
      // small spherical ones): the flat energy of the polish takes over early.
      if(m_spherical && m_D < m_settings.spherical_polish_below) m_force_polish = true;
    }
    // In the polish the mean |log r| may still fall while E hardly moves: a
    // plateau is when neither moves.
    if(m_polish && m_opt.sphere.log_area_tolerance > 0) m_mean_history.push_back(flat_mean_abs_log_ratio(m_p, m_P.faces, m_P.target));
  }

  double d_area() const { return m_D; }
  double progress() const { return m_E; }
  double residual() const
  {
    std::vector<double> flat;
    signed_areas_sphere(m_p, m_P.faces, flat);
    return area_residual(m_n, m_P.faces, flat, m_P.target);
  }

  /// A plateau of the opening ends the opening: polish from here.
  bool on_plateau()
  {
    if(!m_polish) { hand_over(); return false; }
    const std::size_t w = m_opt.plateau_window;
    const bool mean_moves = m_mean_history.size() > w &&
                            m_mean_history[m_mean_history.size() - 1 - w] - m_mean_history.back() > 1e-3 * m_mean_history.back();
    return !mean_moves;
  }

  void finish(Flow_outcome& out)
  {
    set_final_domain(out, residual(), m_solver.analyses() + m_newton_solver.analyses(), m_P.faces, m_P.target);
  }

private:
  static Flow_stopping::Rules stopping_rules(const Discrete_lie_flow_options& opt)
  {
    Flow_stopping::Rules r = Flow_stopping::rules_of(opt);
    r.stall = Flow_stopping::HARD_STEPS;
    return r;
  }

  /// The opening is done: polish, unless the flat D_area is still far from
  /// 2 and the opening has not yet switched to the spherical areas
  /// (`Sphere_flow_settings::spherical_opening_above`).
  void hand_over()
  {
    if(spherical_areas_due()) use_spherical_areas();
    else m_force_polish = true;
  }

  /// Whether the opening, on cone areas, is still far enough from the
  /// targets to go on with the spherical areas instead of ending.
  bool spherical_areas_due() const
  {
    return !m_spherical && m_settings.spherical_opening_above > 0 && m_D > m_settings.spherical_opening_above;
  }

  /// The opening goes on with the spherical areas as its element.
  void use_spherical_areas()
  {
    m_spherical = true;
    m_after_crawl = false;
    m_rising = m_crawling = m_crawling_far = 0;
    m_best_cone_D = m_D;
    m_limiters.clear();
    clear_pairs();
    m_p_prev.clear();
    m_E = evaluate(m_p, m_u, m_w);
    m_stopping.restart(m_E);
  }

  /// The phase's energy at `x`: D_area of the cone areas `a` in the opening
  /// (of the spherical areas once it switched to them); the polish energy
  /// of the flat areas `a` and the cone areas `b` after.
  double evaluate(const std::vector<Vec3>& x, std::vector<double>& a, std::vector<double>& b) const
  {
    if(!m_polish) {
      if(m_spherical) spherical_areas_sphere(x, m_P.faces, a);
      else cone_areas_sphere(x, m_P.faces, a);
      return m_energy.value(a);
    }
    signed_areas_sphere(x, m_P.faces, a);
    cone_areas_sphere(x, m_P.faces, b);
    return m_polish_energy.value(a) + m_kappa * m_polish_energy.value(b);
  }

  /// The tangential gradient of the phase's energy.
  void gradient()
  {
    if(m_polish) {
      m_polish_energy.derivatives(m_u, m_dE);
      m_polish_energy.derivatives(m_w, m_dE_cone);
      for(double& x : m_dE_cone) x *= m_kappa;
      polish_position_gradient(m_p, m_P.faces, m_dE, m_dE_cone, m_g);
    } else {
      m_energy.derivatives(m_u, m_dE);
      if(m_spherical) spherical_position_gradient(m_p, m_P.faces, m_dE, m_g);
      else cone_position_gradient(m_p, m_P.faces, m_dE, m_g);
    }
    project_to_tangent(m_p, m_g);
  }

  void clear_pairs() { m_pairs_s.clear(); m_pairs_y.clear(); m_rho.clear(); }

  void newton_direction(const Sparse_matrix& K, Flow_outcome& out)
  {
    clear_pairs();
    const Tangent_frames T(m_p);
    m_polish_energy.curvatures(m_u, m_curvature);
    m_polish_energy.curvatures(m_w, m_curvature_cone);
    for(double& x : m_curvature_cone) x *= m_kappa;
    Eigen::VectorXd b(Eigen::Index(2 * m_n)), x;
    for(std::size_t v = 0; v < m_n; ++v) {
      const std::array<double, 2> c = T.coordinates(v, m_g[v]);
      b[Eigen::Index(2 * v)] = -c[0];
      b[Eigen::Index(2 * v + 1)] = -c[1];
    }
    // A factorisation that fails (H is only semidefinite: rotations change
    // no area) is retried with a larger ε, as in the plane.
    bool solved = false;
    for(int attempt = 0; attempt < 6 && !solved; ++attempt) {
      double ratio = 1;
      const Sparse_matrix* A;
      {
        Scoped_timer timer(out.seconds_assembly);
        A = &m_newton_matrix.assemble(2 * m_n, [&](auto&& add) {
          sphere_gauss_newton_contributions(m_p, m_P.faces, m_curvature, m_curvature_cone, T, K, m_eps, ratio, add);
        });
      }
      Scoped_timer timer(out.seconds_solve);
      solved = m_newton_solver.factorize(*A) && m_newton_solver.solve(b, x);
      if(!solved) m_eps *= 10;
    }
    if(solved) for(std::size_t v = 0; v < m_n; ++v) m_d[v] = T.vector(v, x[Eigen::Index(2 * v)], x[Eigen::Index(2 * v + 1)]);
    else { out.solver_failed = true; for(std::size_t v = 0; v < m_n; ++v) m_d[v] = {{ -m_g[v][0], -m_g[v][1], -m_g[v][2] }}; }
  }

  /// Curvature pairs of the last accepted steps: L-BFGS on top of the
  /// Sobolev metric (K⁻¹ is the initial inverse Hessian of the two-loop recursion).
  void update_pairs()
  {
    if(m_D > m_settings.lbfgs_below) { clear_pairs(); return; }
    if(m_p_prev.empty()) return;
    std::vector<Vec3> s_k(m_n), y_k(m_n);
    double sy = 0;
    for(std::size_t v = 0; v < m_n; ++v) {
      s_k[v] = sub(m_p[v], m_p_prev[v]);
      y_k[v] = sub(m_g[v], m_g_prev[v]);
      sy += dot(s_k[v], y_k[v]);
    }
    if(!(sy > 0) || m_settings.lbfgs_memory == 0) return;
    m_pairs_s.push_back(std::move(s_k));
    m_pairs_y.push_back(std::move(y_k));
    m_rho.push_back(1 / sy);
    if(m_pairs_s.size() > m_settings.lbfgs_memory) {
      m_pairs_s.erase(m_pairs_s.begin());
      m_pairs_y.erase(m_pairs_y.begin());
      m_rho.erase(m_rho.begin());
    }
  }

  void sobolev_direction(const Sparse_matrix& K, Flow_outcome& out)
  {
    update_pairs();
    std::vector<Vec3> q = m_g;
    std::vector<double> alpha(m_pairs_s.size());
    for(std::size_t i = m_pairs_s.size(); i-- > 0;) {
      double a = 0;
      for(std::size_t v = 0; v < m_n; ++v) a += dot(m_pairs_s[i][v], q[v]);
      alpha[i] = a * m_rho[i];
      for(std::size_t v = 0; v < m_n; ++v) for(int j = 0; j < 3; ++j) q[v][j] -= alpha[i] * m_pairs_y[i][v][j];
    }
    {
      Scoped_timer timer(out.seconds_solve);
      // A short step moved the mesh little: the last factorisation still
      // preconditions well (`Sphere_flow_settings::reuse_factor_below`).
      const bool reuse = m_factored && !m_reused && !m_polish && m_n >= m_settings.large_from && m_lambda_prev < m_settings.reuse_factor_below;
      bool solved = reuse || m_solver.factorize(K);
      m_factored = solved;
      m_reused = reuse;
      if(reuse) --out.factorizations;
      if(solved) {
        // x, y and z in one solve: one pass over the factor for the three.
        Eigen::MatrixXd b(Eigen::Index(m_n), 3), x;
        for(std::size_t v = 0; v < m_n; ++v)
          for(int c = 0; c < 3; ++c) b(Eigen::Index(v), c) = q[v][std::size_t(c)];
        solved = m_solver.solve(b, x);
        if(solved)
          for(std::size_t v = 0; v < m_n; ++v)
            for(int c = 0; c < 3; ++c) m_d[v][std::size_t(c)] = x(Eigen::Index(v), c);
      }
      if(!solved) {
        out.solver_failed = true;
        m_d = q;
      }
    }
    for(std::size_t i = 0; i < m_pairs_s.size(); ++i) {
      double b = 0;
      for(std::size_t v = 0; v < m_n; ++v) b += dot(m_pairs_y[i][v], m_d[v]);
      b *= m_rho[i];
      for(std::size_t v = 0; v < m_n; ++v) for(int j = 0; j < 3; ++j) m_d[v][j] += (alpha[i] - b) * m_pairs_s[i][v][j];
    }
    for(Vec3& x : m_d) x = {{ -x[0], -x[1], -x[2] }};
    project_to_tangent(m_p, m_d);
  }

  /// The global step moved the smooth modes; sweeps take the grid-scale ones.
  void relax(Flow_outcome& out)
  {
    if(m_around.first.size() != m_n + 1) m_around = Vertex_faces(m_n, m_P.faces);
    const std::vector<std::size_t> active =
      vertices_to_relax(m_P.faces, m_polish_energy, m_u, m_n, m_settings.relaxation_threshold);
    const double mu = step_fraction(m_opt);
    const bool large = m_n >= m_settings.large_from;
    const bool parallel = large && m_settings.relaxation_threshold == 0 && m_settings.sweep_parts > 1;
    if(parallel && m_partition.interior.empty()) m_partition = Sweep_partition(m_P.xyz, m_P.faces, m_settings.sweep_parts);
    const std::size_t sweeps = large ? (std::min)(m_settings.relaxation_sweeps, m_settings.large_relaxation_sweeps) : m_settings.relaxation_sweeps;
    m_trial = m_p; // the committed map, kept in case the sweeps' rounding misleads them
    for(std::size_t k = 0; k < sweeps && !active.empty(); ++k) {
      const Relaxation_outcome r =
        parallel ? relax_sphere_vertices(m_P.faces, m_around, m_polish_energy, m_kappa, mu, m_partition, sweep_threads(), m_p, m_u, m_w)
                 : relax_sphere_vertices(m_P.faces, m_around, m_polish_energy, m_kappa, mu, active, m_p, m_u, m_w);
      out.rejected_by_exact_check += r.refused_by_exact_check;
    }
    m_E = evaluate(m_p, m_u, m_w); // drop the sweeps' incremental rounding
    if(!std::isfinite(m_E)) { // a face the sweeps saw positive is not once recomputed: undo
      m_p.swap(m_trial);
      m_E = evaluate(m_p, m_u, m_w);
    }
  }

  /// The threads of the parallel sweeps (`Discrete_lie_flow_sphere_options::threads`).
  int sweep_threads() const
  {
    if(m_opt.sphere.threads > 0) return m_opt.sphere.threads;
    const unsigned h = std::thread::hardware_concurrency();
    return h == 0 ? 1 : (h > 8 ? 8 : int(h));
  }

  /// The opening's local sweeps (see `Sphere_flow_settings::local_sweep_memory`).
  void relax_around_repeated_limiter(const Flow_step& step, Flow_outcome& out)
  {
    const int f = step.limiting;
    const bool repeated = f >= 0 && step.lambda < m_settings.crawl_step && m_D > m_settings.local_sweep_above &&
                          std::size_t(std::count(m_limiters.begin(), m_limiters.end(), f)) + 1 >= m_settings.local_sweep_repeats &&
                          m_D - flat_d_area(m_p, m_P.faces, m_P.target) < m_settings.local_sweep_progress * m_D;
    if(m_settings.local_sweep_memory > 0) {
      m_limiters.push_back(f);
      if(m_limiters.size() > m_settings.local_sweep_memory) m_limiters.erase(m_limiters.begin());
    }
    if(!repeated || m_settings.relaxation_sweeps == 0) return;
    if(spherical_areas_due()) {
      // The first stall far from the targets: change the element, not the vertices.
      use_spherical_areas();
      return;
    }
    if(m_around.first.size() != m_n + 1) m_around = Vertex_faces(m_n, m_P.faces);
    const std::vector<Face>& F = m_P.faces;
    std::vector<std::size_t> active(F[std::size_t(f)].begin(), F[std::size_t(f)].end());
    std::vector<char> seen(m_n, 0);
    for(std::size_t v : active) seen[v] = 1;
    for(std::size_t ring = 0, begin = 0; ring < m_settings.local_sweep_rings; ++ring) {
      const std::size_t end = active.size();
      for(std::size_t i = begin; i < end; ++i)
        for(std::size_t j = m_around.first[active[i]]; j < m_around.first[active[i] + 1]; ++j)
          for(int k = 0; k < 3; ++k) {
            const std::size_t w = std::size_t(F[m_around.of[j].first][k]);
            if(!seen[w]) { seen[w] = 1; active.push_back(w); }
          }
      begin = end;
    }
    signed_areas_sphere(m_p, F, m_flat);
    // The sweeps lower the D_area of the cone areas (m_u holds them unless
    // the opening switched to the spherical areas, which agree with them
    // to second order on small faces).
    if(m_spherical) cone_areas_sphere(m_p, F, m_w);
    std::vector<double>& cone = m_spherical ? m_w : m_u;
    m_trial = m_p;
    const double mu = step_fraction(m_opt);
    for(std::size_t k = 0; k < m_settings.relaxation_sweeps; ++k) {
      const Relaxation_outcome r = relax_sphere_vertices(F, m_around, m_cone_energy, 1, mu, active, m_p, m_flat, cone, 0);
      out.rejected_by_exact_check += r.refused_by_exact_check;
      if(r.moved == 0) break;
    }
    m_E = evaluate(m_p, m_u, m_w); // drop the sweeps' incremental rounding
    if(!std::isfinite(m_E)) {
      m_p.swap(m_trial);
      m_E = evaluate(m_p, m_u, m_w);
    }
  }

  const Sphere_problem& m_P;
  std::vector<Vec3>& m_p;
  const Discrete_lie_flow_options& m_opt;
  const Sphere_flow_settings m_settings;
  const std::size_t m_n;
  Area_barrier_energy m_energy;
  const Weighted_area_energy m_polish_energy;
  const Weighted_area_energy m_cone_energy; // m_energy, with the running sums of the sweeps
  const double m_kappa;
  Pattern_reusing_solver<EigenSolver> m_solver;
  EigenSolver m_newton_eigen_solver; // its own symbolic analysis: 2n unknowns
  Pattern_reusing_solver<EigenSolver> m_newton_solver;
  Fixed_pattern_matrix m_sobolev, m_newton_matrix;
  double m_eps;
  std::vector<double> m_curvature, m_curvature_cone;
  Vertex_faces m_around;
  Sweep_partition m_partition; // built at the first parallel sweep
  // u: the energy's areas (cone areas in the opening, flat ones in the
  // polish); w: the cone areas of the polish.
  std::vector<double> m_u, m_w, m_dE, m_dE_cone, m_u_trial, m_w_trial, m_rho, m_flat;
  std::vector<Vec3> m_p_prev, m_g_prev;
  std::vector<std::vector<Vec3> > m_pairs_s, m_pairs_y;
  std::vector<Vec3> m_g, m_d, m_trial;
  bool m_polish = false, m_force_polish = false, m_newton = false;
  bool m_spherical = false; // the opening's element: the spherical areas, not the cone areas
  bool m_after_crawl = false; // the polish was started by crawl_far_steps short steps
  double m_best_cone_D = infinite_step();
  std::size_t m_rising = 0, m_crawling = 0, m_crawling_far = 0;
  std::vector<int> m_limiters; // the faces that limited the last opening steps
  double m_E = 0, m_E_trial = 0, m_D = 0, m_slope = 0;
  double m_lambda_prev = infinite_step();
  bool m_factored = false, m_reused = false; // the Sobolev factorisation: there, and used twice
  std::vector<double> m_mean_history;
  const Density_levels m_levels;
};

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
