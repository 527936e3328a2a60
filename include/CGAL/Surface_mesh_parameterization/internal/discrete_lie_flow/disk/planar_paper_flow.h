// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The paper's flow (Algorithm 1) as a policy of the flow driver: Delaunay
// flips of the flowing domain mesh, Neumann Poisson solve L h = A_Ω − A_M
// with the cotangent stiffness of the flowing mesh, area-weighted vertex
// gradients, boundary sliding, and the adaptive step below the smallest
// critical root, certified on the flowing triangulation by exact predicates
// plus a degeneracy guard. Where it departs from the printed algorithm:
// doc/paper_mode.md.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_PLANAR_PAPER_FLOW_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_PLANAR_PAPER_FLOW_H

#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/area_elements.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/disk/boundary_curve.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/certification.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/cotangent_laplacian.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/critical_step.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/disk/disk_problem.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/edge_flips.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/flow/flow_driver.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/disk/planar_dofs.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/sparse_solver.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// Internal knobs of the paper flow, with the measured defaults
/// (doc/paper_mode.md). `Paper_flow_settings::plain()` is the paper's step
/// as written: λ = min(λ_cap, μ·λ_crit) along the Poisson velocities.
struct Paper_flow_settings
{
  /// Step length within the critical bound: 0 takes the paper's
  /// λ = min(λ_cap, μ·λ_crit); n > 0 takes the lowest D_area among n samples
  /// λ_hi·2^(−k/2), λ_hi = min(`line_search_cap`·λ_cap, 0.95·λ_crit), or
  /// μ·λ_crit when the caller sets μ. The Poisson step is no descent
  /// direction of D_area near the end, so a fixed fraction of λ_crit
  /// overshoots there, and λ_cap = 1 is too short where the flow has room.
  std::size_t line_search = 8;
  double line_search_upper = 0.95;
  double line_search_cap = 4;
  /// Collapse guard: up to `guard_rounds` times, the faces that the step
  /// would collapse before λ = `guard_step` while their area is already
  /// below their target get their area rate projected to zero (the smallest
  /// change of their vertices' velocities). Without it an interior vertex is
  /// driven onto a border edge, or two vertices merge along a shrinking edge,
  /// and that face sets λ_crit → 0. 0 rounds: the paper's velocities.
  std::size_t guard_rounds = 60;
  double guard_step = std::numeric_limits<double>::infinity();
  /// Plateau test: at least this relative improvement over the window
  /// (the larger of this and the option's).
  double plateau_tolerance = 3e-4;
  /// Slow tail: D_area − 2 must also shrink by at least `tail_rate` of itself
  /// over `tail_window` iterations; slower, halving it would take more than
  /// 130 iterations (doc/paper_mode.md, "stop rules"). The window is long
  /// because the best iterate improves in steps between flat stretches.
  double tail_rate = 0.1;
  std::size_t tail_window = 20;

  static Paper_flow_settings plain()
  {
    Paper_flow_settings s;
    s.line_search = 0;
    s.guard_rounds = 0;
    s.plateau_tolerance = 0;
    s.tail_rate = 0;
    return s;
  }
};

/// The collapse guard (Paper_flow_settings): projects the dof direction `d`
/// so that the faces it drives to collapse while they are already too small
/// keep their area to first order; `vel` is updated.
inline void guard_collapses(const std::vector<Vec2>& uv, const std::vector<Face>& faces, const std::vector<double>& u,
                            const std::vector<double>& target, const Planar_dofs& dofs, const std::vector<Vec2>& basis,
                            const Paper_flow_settings& settings, Eigen::VectorXd& d, std::vector<Vec2>& vel)
{
  double U = 0, T = 0;
  for(std::size_t t = 0; t < faces.size(); ++t) { U += u[t]; T += target[t]; }
  std::vector<std::pair<double, std::size_t> > hits;
  // After the first round only faces with a changed vertex can change.
  std::vector<char> changed(uv.size(), 1), next(uv.size(), 0);
  for(std::size_t round = 0; round < settings.guard_rounds; ++round) {
    hits.clear();
    for(std::size_t t = 0; t < faces.size(); ++t) {
      const Face& f = faces[t];
      if(!changed[f[0]] && !changed[f[1]] && !changed[f[2]]) continue;
      if(!((u[t] / U) < (target[t] / T))) continue; // only faces below their target are guarded
      const double r = critical_step_2(uv[f[0]], uv[f[1]], uv[f[2]], vel[f[0]], vel[f[1]], vel[f[2]]);
      if(r < settings.guard_step) hits.emplace_back(r, t);
    }
    if(hits.empty()) return;
    std::sort(hits.begin(), hits.end());
    for(const auto& hit : hits) {
      const Face& f = faces[hit.second];
      // ∂(2A)/∂p_k = J (p_{k+1} − p_{k+2}) with J the rotation by −π/2.
      double rate = 0, norm2 = 0;
      std::array<std::array<double, 2>, 3> g;
      for(int k = 0; k < 3; ++k) {
        const Vec2 &b = uv[f[(k + 1) % 3]], &c = uv[f[(k + 2) % 3]];
        const Vec2 grad{{ b[1] - c[1], c[0] - b[0] }};
        const int v = f[k];
        g[k] = {{ 0, 0 }};
        for(int j = 0; j < dofs.count[v]; ++j) {
          const int a = dofs.first[v] + j;
          g[k][j] = grad[0] * basis[a][0] + grad[1] * basis[a][1];
          rate += g[k][j] * d[a];
          norm2 += g[k][j] * g[k][j];
        }
      }
      if(rate >= 0 || norm2 <= 0) continue;
      for(int k = 0; k < 3; ++k) {
        const int v = f[k];
        next[v] = 1;
        for(int j = 0; j < dofs.count[v]; ++j) d[dofs.first[v] + j] -= rate / norm2 * g[k][j];
        vel[v] = Vec2{{ 0, 0 }};
        for(int j = 0; j < dofs.count[v]; ++j) {
          const int a = dofs.first[v] + j;
          vel[v][0] += d[a] * basis[a][0];
          vel[v][1] += d[a] * basis[a][1];
        }
      }
    }
    changed.swap(next);
    std::fill(next.begin(), next.end(), 0);
  }
}


/// The paper's flow as a policy of `run_flow()` (flow_driver.h), from the
/// positively oriented `uv`. On return, `uv` is the best iterate (lowest
/// D_area on its Delaunay flowing triangulation), and the outcome holds that
/// triangulation and its targets; the reported D_area and stop reason are
/// those of the returned map.
template <class EigenSolver>
class Planar_paper_flow : public Flow_policy_base
{
public:
  Planar_paper_flow(const Disk_problem& P, std::vector<Vec2>& uv, Boundary_curve& curve,
                    const Discrete_lie_flow_options& opt, EigenSolver& eigen_solver,
                    const Paper_flow_settings& settings)
    : Flow_policy_base(stopping_rules(opt, settings)), m_P(P), m_uv(uv), m_curve(curve), m_opt(opt), m_settings(settings), m_n(uv.size()),
      m_dofs(uv.size(), P.boundary, curve), m_solver(eigen_solver), m_tri(P.faces),
      m_targets(P.xyz, P.faces, P.target), m_target(P.target), m_basis(std::size_t(m_dofs.size)), m_vel(uv.size())
  {
    lump_on_vertices(m_n, P.faces, P.target, m_literal_AM);
  }

  /// Every iterate is measured on its own Delaunay triangulation, the one
  /// the next solve uses and the one returned with it.
  bool start(Flow_outcome& out)
  {
    signed_areas_2(m_uv, m_tri.faces, m_u);
    out.initial_d_area = d_area_of(m_u, m_target);
    if(make_delaunay(out) > 0) signed_areas_2(m_uv, m_tri.faces, m_u);
    m_d_area = m_best = d_area_of(m_u, m_target);
    keep_best();
    m_stopping.restart(m_best);
    return true;
  }

  bool converged() const { return m_best - 2 <= m_opt.tolerance; }

  /// The Poisson potential h of L h = A_Ω − A_M and the area-weighted mean of
  /// its face gradients at the vertices; boundary vertices keep the tangential part.
  Direction_status direction(Flow_outcome& out)
  {
    Sparse_matrix L;
    {
      Scoped_timer timer(out.seconds_assembly);
      lump_on_vertices(m_n, m_tri.faces, m_u, m_AO);
      if(m_opt.paper.lump_targets_on_flowing_faces) lump_on_vertices(m_n, m_tri.faces, m_target, m_AM);
      else m_AM = m_literal_AM;
      L = cotangent_stiffness(m_uv, m_tri.faces);
    }
    std::vector<double> h;
    if(!solve_pinned_poisson(L, m_AO, m_AM, m_solver, out, h)) return Direction_status::SOLVER_FAILED;
    Scoped_timer timer(out.seconds_step);
    potential_gradient_direction(m_uv, m_tri.faces, m_u, h, m_dofs, m_curve, m_basis, m_d);
    planar_velocity(m_n, m_dofs, m_basis, m_d, m_vel);
    if(m_opt.fixed_step <= 0 && m_settings.guard_rounds > 0)
      guard_collapses(m_uv, m_tri.faces, m_u, m_target, m_dofs, m_basis, m_settings, m_d, m_vel);
    return Direction_status::DESCENT;
  }

  void bound(Flow_step& step)
  {
    step.critical = planar_critical_step(m_uv, m_tri.faces, m_vel, step.limiting);
    step.lambda = paper_first_step(m_opt, step.critical);
  }

  void search(Flow_step& step, Flow_outcome& out)
  {
    bool accepted = false;
    if(m_opt.fixed_step <= 0 && m_settings.line_search > 0) accepted = line_search(step, out);
    // Shrink until every flowing face is positive (exact) and none collapses.
    for(; !accepted && step.halvings <= m_opt.max_backtracks; ++step.halvings, step.lambda *= 0.5) {
      if(!std::isfinite(admissible_d_area(step.lambda))) continue;
      if(!certified(out)) continue;
      accepted = true;
      break;
    }
    // A fixed step that would fold is the paper's "collapse".
    step.accepted = accepted && !(m_opt.fixed_step > 0 && step.halvings > 0);
  }

  void commit(Flow_step& step, Flow_outcome& out)
  {
    commit_border_step(m_dofs, step.lambda, m_d, m_curve);
    m_uv.swap(m_trial);
    step.flips = make_delaunay(out);
    signed_areas_2(m_uv, m_tri.faces, m_u);
    m_d_area = d_area_of(m_u, m_target);
    if(m_d_area < m_best) { m_best = m_d_area; keep_best(); }
  }

  double d_area() const { return m_d_area; }
  double progress() const { return m_best; }
  double residual() const { return area_residual(m_n, m_tri.faces, m_u, m_target); }

  void finish(Flow_outcome& out)
  {
    m_uv = m_best_uv;
    signed_areas_2(m_uv, m_best_faces, m_u);
    out.final_d_area = d_area_of(m_u, m_best_target);
    set_final_domain(out, area_residual(m_n, m_best_faces, m_u, m_best_target), m_solver.analyses(), m_best_faces,
                     m_best_target);
  }

private:
  /// A plateau tolerance of 0 turns both plateau tests off (the paper's Table 2).
  static Flow_stopping::Rules stopping_rules(const Discrete_lie_flow_options& opt, const Paper_flow_settings& settings)
  {
    Flow_stopping::Rules r = Flow_stopping::rules_of(opt);
    r.plateau = opt.plateau_tolerance > 0;
    r.plateau_tolerance = (std::max)(opt.plateau_tolerance, settings.plateau_tolerance);
    r.tail_rate = opt.plateau_tolerance > 0 ? settings.tail_rate : 0;
    r.tail_window = settings.tail_window;
    r.stall = Flow_stopping::SAME_LIMITING_FACE;
    return r;
  }

  std::size_t make_delaunay(Flow_outcome& out)
  {
    if(!m_opt.paper.delaunay_flips) return 0;
    const std::size_t flips = m_tri.make_delaunay(m_uv, [&](int f) {
      m_target[std::size_t(f)] = m_targets(m_tri.faces[std::size_t(f)]); }, 100 * m_tri.faces.size() + 100);
    out.flips += flips;
    return flips;
  }

  void keep_best()
  {
    m_best_uv = m_uv;
    m_best_faces = m_tri.faces;
    m_best_target = m_target;
  }

  /// D_area of the trial position at λ when every flowing face is positive
  /// and none collapses below the degeneracy guard (in doubles; the exact
  /// check follows); +∞ if it is not admissible.
  double admissible_d_area(double lambda)
  {
    if(!planar_trial(m_uv, m_dofs, m_basis, m_d, lambda, m_curve, m_trial)) return std::numeric_limits<double>::infinity();
    signed_areas_2(m_trial, m_tri.faces, m_u_trial);
    double U = 0, T = 0;
    for(std::size_t t = 0; t < m_u_trial.size(); ++t) {
      if(!(m_u_trial[t] > 0)) return std::numeric_limits<double>::infinity();
      U += m_u_trial[t]; T += m_target[t];
    }
    for(std::size_t t = 0; t < m_u_trial.size(); ++t)
      if((m_u_trial[t] / U) < m_opt.paper.degeneracy_ratio * (m_target[t] / T)) return std::numeric_limits<double>::infinity();
    return d_area_of(m_u_trial, m_target);
  }

  bool certified(Flow_outcome& out)
  {
    if(certified_trial_2(m_trial, m_tri.faces)) return true;
    ++out.rejected_by_exact_check;
    return false;
  }

  /// The lowest D_area among samples below the critical bound, certified in
  /// increasing order of D_area. When none is certified, the halvings go on
  /// from half the sample of highest D_area.
  bool line_search(Flow_step& step, Flow_outcome& out)
  {
    std::vector<std::pair<double, double> > samples; // (D_area, λ)
    // A μ given by the caller bounds the samples instead of 0.95.
    const double upper = step_fraction(m_opt, m_settings.line_search_upper);
    double l = (std::min)(m_settings.line_search_cap * m_opt.paper.step_cap, upper * step.critical);
    for(std::size_t k = 0; k < m_settings.line_search; ++k, l *= std::sqrt(0.5)) {
      const double e = admissible_d_area(l);
      if(std::isfinite(e)) samples.emplace_back(e, l);
    }
    std::sort(samples.begin(), samples.end());
    for(const auto& s : samples) {
      admissible_d_area(s.second);
      if(certified(out)) { step.lambda = s.second; return true; }
    }
    if(!samples.empty()) step.lambda = samples.back().second * 0.5;
    return false;
  }

  const Disk_problem& m_P;
  std::vector<Vec2>& m_uv;
  Boundary_curve& m_curve;
  const Discrete_lie_flow_options& m_opt;
  const Paper_flow_settings m_settings;
  const std::size_t m_n;
  Planar_dofs m_dofs;
  Pattern_reusing_solver<EigenSolver> m_solver;
  Flip_triangulation m_tri;
  const Flowing_targets m_targets;
  std::vector<double> m_target, m_literal_AM, m_u, m_AO, m_AM, m_u_trial;
  double m_d_area = 0, m_best = 0;
  std::vector<Vec2> m_best_uv, m_trial;
  std::vector<Face> m_best_faces;
  std::vector<double> m_best_target;
  std::vector<Vec2> m_basis, m_vel;
  Eigen::VectorXd m_d;
};

/// Runs the paper's flow from the positively oriented `uv`; `flowing`
/// receives the returned triangulation (Planar_paper_flow).
template <class EigenSolver>
Flow_outcome paper_disk_flow(const Disk_problem& P, std::vector<Vec2>& uv, Boundary_curve& curve,
                             const Discrete_lie_flow_options& opt, EigenSolver& eigen_solver,
                             std::vector<Face>& flowing,
                             const Paper_flow_settings& settings = Paper_flow_settings())
{
  Planar_paper_flow<EigenSolver> flow(P, uv, curve, opt, eigen_solver, settings);
  Flow_outcome out = run_flow(flow, opt);
  flowing = out.domain_faces;
  return out;
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
