// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The certified mode on the caller's connectivity, as a policy of the flow
// driver: DLF's Laplacian solve of the current domain mesh and its
// critical-root step, applied to the Sobolev gradient of the barrier energy
// E = D_area (of the log-ratio energy while far from the targets). Every
// accepted step keeps every input triangle positively oriented (exact
// predicate) and never raises E, so the last iterate is the best one and no
// face can collapse (each term w_t / r_t ≤ E bounds the area ratio r_t from
// below). doc/certified_mode.md describes the variants and their measurements.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_PLANAR_CERTIFIED_FLOW_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_PLANAR_CERTIFIED_FLOW_H

#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/area_barrier_energy.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/area_elements.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/disk/boundary_curve.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/certification.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/critical_step.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/density_levels.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/disk/disk_holes.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/disk/disk_problem.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/flow/flow_driver.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/disk/planar_dofs.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/disk/planar_gauss_newton.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/disk/planar_relaxation.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/disk/sobolev_direction.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// Internal knobs of the planar certified flow, with the measured defaults
/// (doc/certified_mode.md, "Measurements behind the defaults").
struct Planar_flow_settings
{
  /// Vertex-by-vertex relaxation sweeps after each step once D_area is
  /// below `relaxation_below` (planar_relaxation.h); a sweep that moves no
  /// vertex ends them. They take the grid-scale modes the global step leaves.
  std::size_t relaxation_sweeps = 10;
  double relaxation_below = 2.1;
  /// A sweep that lowers D_area by less than this fraction of what the
  /// iteration's global step did ends them, unless the sweeps left could
  /// bring D_area to the tolerance at its gain.
  double relaxation_least_gain = 0.05;
  /// From this many faces the sweeps visit the vertices region by region
  /// (`Sweep_partition` of `sweep_parts` regions of the Morton order), the
  /// regions' interiors on the threads of `Discrete_lie_flow_disk_options::threads`:
  /// the same map for any number of threads.
  std::size_t parallel_sweeps_from = 100000;
  std::size_t sweep_parts = 8;
  /// The direction becomes the regularised Gauss–Newton one
  /// (planar_gauss_newton.h) for good once D_area is below `newton_below`
  /// and an iteration took off less than `newton_when_slower` of D_area − 2
  /// (0: never). Its coupled factorisation costs 4–5 Sobolev ones, hence the
  /// slowness test.
  double newton_below = 2.05;
  double newton_when_slower = 0.5;
  /// Initial ε of the Gauss–Newton regularisation, relative to tr(H)/tr(S).
  double newton_regularization = 1e-2;
  /// While D_area is above `log_opening_above` (0: never) the direction is
  /// the Sobolev gradient of the log-ratio energy L (area_barrier_energy.h)
  /// and a step must lower L (Armijo) and not raise E.
  double log_opening_above = 2.1;
  /// With the coupled metric, the opening ends for good after a step that
  /// took off less than this fraction of D_area − 2: L's direction then
  /// hardly lowers E (steps halved down to 1e-15 on a spiral at D_area 2.12).
  double log_opening_least_gain = 1e-2;
  /// The Sobolev metric with its exact border block (border tangents couple
  /// x and y: one factorisation of 2·interior + border dofs, with 4–8× the
  /// fill of the split one) instead of the split metric's diagonal bound,
  /// from the start (`flow_disk()` sets it when the start's border spacing
  /// was far off) or for good once, above `newton_below`, D_area − 2 shrank
  /// by less than `coupled_when_slower` over `coupled_window` iterations
  /// (0: never). The diagonal bound moves each border vertex on its own: a
  /// border that must slide far and coherently (long seams) then crawls,
  /// its steps halved by the line search.
  bool coupled_metric = false;
  double coupled_when_slower = 0.5;
  std::size_t coupled_window = 10;
  /// The coupled metric's factorisation is kept for the next directions
  /// while a step takes off at least `coupled_reuse_gain` times the share
  /// of D_area − 2 that the step right after the factorisation took off,
  /// and for at most `coupled_reuse_age` directions (1: factorise every
  /// time). A metric of a nearby map is still positive definite, so its
  /// direction still descends; a solve costs a fraction of a factorisation
  /// (doc/certified_mode.md, "Long seams and thin disks").
  double coupled_reuse_gain = 0.7;
  std::size_t coupled_reuse_age = 8;
};

/// The planar certified flow as a policy of `run_flow()` (flow_driver.h).
/// `uv` (positively oriented) and `curve` are moved in place; the result is
/// always a certified map not worse than the start.
template <class EigenSolver>
class Planar_certified_flow : public Flow_policy_base
{
public:
  /// `analysed` (optional): `eigen_solver` wrapped, its last analysis made
  /// for a matrix of the interior stiffness's pattern (the Tutte system of
  /// the start, respace_border_by_area()); the flow then skips its own.
  Planar_certified_flow(const Disk_problem& P, std::vector<Vec2>& uv, Boundary_curve& curve,
                        const Discrete_lie_flow_options& opt, EigenSolver& eigen_solver,
                        const Planar_flow_settings& settings,
                        const Pattern_reusing_solver<EigenSolver>* analysed = nullptr)
    : Flow_policy_base(Flow_stopping::rules_of(opt)), m_P(P), m_uv(uv), m_curve(curve), m_opt(opt), m_settings(settings), m_n(uv.size()),
      m_dofs(uv.size(), P.boundary, curve), m_energy(P.target), m_log_energy(m_energy),
      m_sobolev(m_dofs.boundary_of, eigen_solver), m_newton_solver(m_newton_eigen_solver),
      m_newton_system(m_dofs.first, m_dofs.count, m_dofs.size), m_eps(settings.newton_regularization),
      m_basis(std::size_t(m_dofs.size)), m_tangent(uv.size()), m_around(0, std::vector<Face>()),
      m_levels(P.xyz, caller_part(P.faces, P), caller_part(P.target, P)), m_caller_energy(caller_part(P.target, P)),
      m_coupled(settings.coupled_metric)
  {
    if(analysed) m_sobolev.adopt_analysis(*analysed);
  }

  bool start(Flow_outcome& out)
  {
    signed_areas_2(m_uv, m_P.faces, m_u);
    m_E = m_energy.value(m_u);
    m_E_history.assign(1, m_E);
    out.initial_d_area = out.final_d_area = m_E;
    m_stopping.restart(m_E);
    return std::isfinite(m_E);
  }

  /// D_area within the tolerance, and the shares of the density's regions;
  /// with holes, both on the caller's faces too (the fill is not the
  /// caller's surface, and D_area of the filled disk may hide it).
  bool converged() const
  {
    if(!(m_E - 2 <= m_opt.tolerance)) return false;
    if(m_P.fill_faces == 0)
      return !(m_opt.certified.share_tolerance > 0) || m_levels.error(m_u) <= m_opt.certified.share_tolerance;
    const std::vector<double> u = caller_part(m_u, m_P);
    return m_caller_energy.value(u) - 2 <= m_opt.tolerance &&
           (!(m_opt.certified.share_tolerance > 0) || m_levels.error(u) <= m_opt.certified.share_tolerance);
  }

  /// The Sobolev gradient of E (of L in the opening), or the Gauss–Newton
  /// direction once the Sobolev flow is near the targets and slowing down.
  Direction_status direction(Flow_outcome& out)
  {
    const bool was_log_opening = m_log_opening;
    m_log_opening = !m_newton && !m_opening_over && m_settings.log_opening_above > 0 && m_E > m_settings.log_opening_above;
    if(was_log_opening && !m_log_opening) m_lambda_prev = infinite_step(); // another direction, another scale
    const std::size_t w = m_settings.coupled_window;
    if(!m_coupled && !m_newton && m_settings.coupled_when_slower > 0 && m_E > m_settings.newton_below &&
       m_E_history.size() > w && m_E - 2 > m_settings.coupled_when_slower * (m_E_history[m_E_history.size() - 1 - w] - 2))
      m_coupled = true;
    gradient();
    if(!m_newton && m_settings.newton_below > 0 && m_E < m_settings.newton_below &&
       m_E - 2 > m_settings.newton_when_slower * (m_E_before - 2))
      m_newton = true;
    if(m_newton) { ++out.factorizations; newton_direction(out); }
    else if(m_coupled) coupled_sobolev_direction(out); // counts its own
    else { ++out.factorizations; sobolev_direction(out); }
    m_slope = m_gr.dot(m_d);
    if(!(m_slope < 0)) { m_d = -m_gr; m_slope = -m_gr.squaredNorm(); }
    return m_slope < 0 ? Direction_status::DESCENT : Direction_status::NO_DESCENT;
  }

  void bound(Flow_step& step)
  {
    planar_velocity(m_n, m_dofs, m_basis, m_d, m_vel);
    step.critical = planar_critical_step(m_uv, m_P.faces, m_vel, step.limiting);
    step.lambda = certified_first_step(m_opt, m_newton, m_lambda_prev, step.critical);
  }

  /// Armijo backtracking; the exact predicate has the last word.
  void search(Flow_step& step, Flow_outcome& out)
  {
    for(; step.halvings <= m_opt.max_backtracks; ++step.halvings, step.lambda *= 0.5) {
      if(!planar_trial(m_uv, m_dofs, m_basis, m_d, step.lambda, m_curve, m_trial)) continue;
      signed_areas_2(m_trial, m_P.faces, m_u_trial);
      m_E_trial = m_energy.value(m_u_trial);
      if(m_log_opening ? !(m_E_trial <= m_E && m_log_energy.value(m_u_trial) <= m_L + 1e-4 * step.lambda * m_slope)
                       : !(m_E_trial <= m_E + 1e-4 * step.lambda * m_slope))
        continue;
      if(!certified_trial_2(m_trial, m_P.faces)) { ++out.rejected_by_exact_check; continue; }
      step.accepted = true;
      return;
    }
  }

  void commit(const Flow_step& step, Flow_outcome& out)
  {
    if(m_newton) m_eps = updated_regularization(m_eps, step.halvings);
    commit_border_step(m_dofs, step.lambda, m_d, m_curve);
    m_uv.swap(m_trial);
    m_u.swap(m_u_trial);
    if(m_coupled && m_log_opening && m_E - m_E_trial < m_settings.log_opening_least_gain * (m_E - 2))
      m_opening_over = true;
    m_E_before = m_E;
    m_E = m_E_trial;
    if(m_settings.relaxation_sweeps > 0 && m_E < m_settings.relaxation_below) relax(out);
    m_E_history.push_back(m_E);
    m_lambda_prev = step.lambda;
    out.final_d_area = m_E;
  }

  double d_area() const { return m_E; }
  double progress() const { return m_E; }
  double residual() const { return area_residual(m_n, m_P.faces, m_u, m_P.target); }

  void finish(Flow_outcome& out)
  {
    set_final_domain(out, residual(), m_sobolev.analyses() + m_newton_solver.analyses(), m_P.faces, m_P.target);
  }

private:
  /// ∂E/∂p (∂L/∂p in the opening), the dof basis, and ∂E/∂dof in `m_gr`.
  void gradient()
  {
    m_L = 0;
    if(m_log_opening) {
      m_log_energy.derivatives(m_u, m_dE);
      m_L = m_log_energy.value(m_u);
    } else {
      m_energy.derivatives(m_u, m_dE);
    }
    planar_position_gradient(m_uv, m_P.faces, m_dE, m_g);
    for(std::size_t v = 0; v < m_n; ++v)
      for(int j = 0; j < m_dofs.count[v]; ++j) m_basis[std::size_t(m_dofs.first[v] + j)] = m_dofs.basis(int(v), j, m_curve);
    m_gr.resize(m_dofs.size);
    for(std::size_t v = 0; v < m_n; ++v)
      for(int j = 0; j < m_dofs.count[v]; ++j) {
        const int a = m_dofs.first[v] + j;
        m_gr[a] = m_g[v][0] * m_basis[a][0] + m_g[v][1] * m_basis[a][1];
      }
  }

  void newton_direction(Flow_outcome& out)
  {
    m_energy.curvatures(m_u, m_curvature);
    bool solved = false;
    for(int attempt = 0; attempt < 6 && !solved; ++attempt) {
      const Sparse_matrix* A;
      {
        Scoped_timer timer(out.seconds_assembly);
        A = &m_newton_system.assemble(m_uv, m_P.faces, m_basis, m_curvature, m_eps);
      }
      Scoped_timer timer(out.seconds_solve);
      solved = m_newton_solver.factorize(*A) && m_newton_solver.solve(-m_gr, m_d);
      if(!solved) m_eps *= 10;
    }
    if(!solved) { out.solver_failed = true; m_d = -m_gr; }
  }

  /// d = −S⁻¹ g, S the Dirichlet energy of the current domain over the dofs
  /// (exact border block), factorised by the Gauss–Newton tail's solver.
  void coupled_sobolev_direction(Flow_outcome& out)
  {
    // The share of D_area − 2 the last step took off.
    const double gain = m_E_history.empty() ? 0 : (m_E_before - m_E) / (m_E_before - 2);
    if(m_coupled_age == 1) m_fresh_gain = gain;
    const bool fresh = m_coupled_age == 0 || m_coupled_age >= m_settings.coupled_reuse_age ||
                       !(gain >= m_settings.coupled_reuse_gain * m_fresh_gain);
    m_coupled_age = fresh ? 1 : m_coupled_age + 1;
    if(fresh) {
      const Sparse_matrix* S;
      {
        Scoped_timer timer(out.seconds_assembly);
        S = &m_newton_system.metric(m_uv, m_P.faces, m_basis);
      }
      ++out.factorizations;
      Scoped_timer timer(out.seconds_solve);
      if(!m_newton_solver.factorize(*S)) m_coupled_age = 0;
    }
    Scoped_timer timer(out.seconds_solve);
    if(m_coupled_age == 0 || !m_newton_solver.solve(-m_gr, m_d)) {
      out.solver_failed = true;
      m_coupled_age = 0;
      m_d = -m_gr;
    }
  }

  /// d = −M⁻¹ g, M the Dirichlet energy of the current domain.
  void sobolev_direction(Flow_outcome& out)
  {
    {
      Scoped_timer timer(out.seconds_assembly);
      m_sobolev.assemble(m_uv, m_P.faces);
    }
    Scoped_timer timer(out.seconds_solve);
    for(std::size_t v = 0; v < m_n; ++v)
      m_tangent[v] = (m_dofs.boundary_of[v] >= 0 && m_dofs.count[v] > 0) ? m_basis[std::size_t(m_dofs.first[v])] : Vec2{{ 0, 0 }};
    if(!m_sobolev.factorize() || !m_sobolev.solve(m_g, m_tangent, m_dv)) {
      out.solver_failed = true;
      m_d = -m_gr;
      return;
    }
    m_d.resize(m_dofs.size);
    for(std::size_t v = 0; v < m_n; ++v)
      for(int j = 0; j < m_dofs.count[v]; ++j) {
        const std::size_t a = std::size_t(m_dofs.first[v] + j);
        m_d[Eigen::Index(a)] = m_dv[v][0] * m_basis[a][0] + m_dv[v][1] * m_basis[a][1];
      }
  }

  /// The global step moved the smooth modes; sweeps take the grid-scale ones.
  void relax(Flow_outcome& out)
  {
    if(m_around.first.size() != m_n + 1) {
      m_around = Vertex_faces(m_n, m_P.faces);
      m_movable.assign(m_n, 1);
      for(std::size_t v = 0; v < m_n; ++v) // a floating border's vertices too
        if(m_dofs.boundary_of[v] >= 0) m_movable[v] = 0;
      if(m_P.faces.size() >= m_settings.parallel_sweeps_from)
        m_partition = Sweep_partition(morton_order(m_P.xyz), m_P.faces, m_settings.sweep_parts, &m_movable);
    }
    const int threads = disk_sweep_threads(m_opt, m_P.faces.size(), m_settings.parallel_sweeps_from);
    const double mu = step_fraction(m_opt);
    m_trial = m_uv; // the committed map, kept in case the sweeps' rounding misleads them
    // Sweeps pay where the global step is held back (a few stiff faces cap
    // it), or where they can end the flow in this iteration (the tolerance
    // within reach of the sweeps left at the last one's gain). Elsewhere a
    // sweep gains ~1% of what the step did and costs about as much as a
    // factorization: one sweep, for the grid-scale modes.
    const double least_gain = m_settings.relaxation_least_gain * (m_E_before - m_E);
    const double goal = 2 + m_opt.tolerance;
    double E_sweep = m_E;
    for(std::size_t k = 0; k < m_settings.relaxation_sweeps; ++k) {
      const Relaxation_outcome r =
        m_partition.interior.empty() ? relax_planar_vertices(m_P.faces, m_around, m_energy, mu, m_movable, m_uv, m_u)
                                     : relax_planar_vertices(m_P.faces, m_around, m_energy, mu, m_partition, threads, m_uv, m_u);
      out.rejected_by_exact_check += r.refused_by_exact_check;
      if(r.moved == 0) break;
      const double gain = E_sweep - r.energy;
      E_sweep = r.energy;
      const bool in_reach = E_sweep > goal && E_sweep - goal < double(m_settings.relaxation_sweeps - k - 1) * gain;
      if(gain < least_gain && !in_reach) break;
    }
    const double E = m_E;
    signed_areas_2(m_uv, m_P.faces, m_u); // drop the sweeps' incremental rounding
    m_E = m_energy.value(m_u);
    if(!std::isfinite(m_E)) { // a face the sweeps saw positive is not once recomputed: undo
      m_uv.swap(m_trial);
      signed_areas_2(m_uv, m_P.faces, m_u);
      m_E = E;
    }
  }

  const Disk_problem& m_P;
  std::vector<Vec2>& m_uv;
  Boundary_curve& m_curve;
  const Discrete_lie_flow_options& m_opt;
  const Planar_flow_settings m_settings;
  const std::size_t m_n;
  Planar_dofs m_dofs;
  Area_barrier_energy m_energy;
  Log_ratio_energy m_log_energy;
  Split_sobolev_direction<EigenSolver> m_sobolev;
  EigenSolver m_newton_eigen_solver; // its own symbolic analysis: coupled x and y
  Pattern_reusing_solver<EigenSolver> m_newton_solver;
  Planar_gauss_newton_system m_newton_system;
  double m_eps;
  bool m_newton = false, m_log_opening = false, m_opening_over = false;
  double m_E = 0, m_E_trial = 0, m_L = 0, m_slope = 0;
  double m_E_before = infinite_step(); // E before the last step: how much it took off
  double m_lambda_prev = infinite_step();
  std::vector<double> m_u, m_dE, m_u_trial, m_curvature;
  std::vector<Vec2> m_g, m_vel, m_trial, m_basis, m_tangent, m_dv;
  Eigen::VectorXd m_gr, m_d;
  Vertex_faces m_around;
  std::vector<char> m_movable;
  Sweep_partition m_partition; // large meshes: built with m_around
  const Density_levels m_levels;     // the caller's faces only
  const Area_barrier_energy m_caller_energy; // D_area of the caller's faces (holes)
  bool m_coupled;
  std::size_t m_coupled_age = 0; // directions since the coupled factorisation (0: none held)
  double m_fresh_gain = 0;
  std::vector<double> m_E_history; // E after each iteration, from the start
};

/// Runs the certified flow from the positively oriented `uv` (modified in
/// place; always a certified map not worse than the start).
template <class EigenSolver>
Flow_outcome certified_disk_flow(const Disk_problem& P, std::vector<Vec2>& uv, Boundary_curve& curve,
                                 const Discrete_lie_flow_options& opt, EigenSolver& eigen_solver,
                                 const Planar_flow_settings& settings = Planar_flow_settings())
{
  Planar_certified_flow<EigenSolver> flow(P, uv, curve, opt, eigen_solver, settings);
  return run_flow(flow, opt);
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
