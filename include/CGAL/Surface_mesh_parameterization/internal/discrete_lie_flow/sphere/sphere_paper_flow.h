// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The paper's flow on the unit sphere (Algorithm 1 with its §5.3 gradient
// decomposition) as a policy of the flow driver: Delaunay flips of the
// flowing spherical triangulation, the Poisson solve L h = A_Ω − A_M with the
// cotangent stiffness of the flat triangles between the sphere points,
// area-weighted vertex gradients with their normal component removed,
// re-normalised points, and the adaptive step μ·(smallest positive root of
// the per-face orientation cubics), certified on the flowing triangulation by
// the exact orientation(O, p, q, r) plus a degeneracy guard. The choices of
// the planar paper mode carry over (targets lumped on the flowing faces, best
// iterate, D_area plateau, stall detector; doc/sphere_paper_mode.md).

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_SPHERE_PAPER_FLOW_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_SPHERE_PAPER_FLOW_H

#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/area_elements.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/certification.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/critical_step.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/flow/flow_driver.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/sparse_solver.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/sphere/sphere_directions.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/sphere/sphere_edge_flips.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/sphere/sphere_problem.h>

#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// The paper's spherical flow as a policy of `run_flow()` (flow_driver.h),
/// from the positively oriented unit vectors `p`. On return, `p` is the best
/// iterate (lowest D_area on the flowing triangulation, flat triangles
/// between the sphere points) and the outcome holds its triangulation,
/// flipped once more to be Delaunay where it stands. Every face of every
/// accepted flowing triangulation is positively oriented by the exact predicate.
template <class EigenSolver>
class Sphere_paper_flow : public Flow_policy_base
{
public:
  Sphere_paper_flow(const Sphere_problem& P, std::vector<Vec3>& p, const Discrete_lie_flow_options& opt,
                    EigenSolver& eigen_solver)
    : Flow_policy_base(stopping_rules(opt)), m_P(P), m_p(p), m_opt(opt), m_n(p.size()), m_solver(eigen_solver), m_tri(P.faces),
      m_max_flips(100 * P.faces.size() + 100), m_targets(P.xyz, P.faces, P.target), m_target(P.target),
      m_trial(p.size()), m_grad(p.size()), m_d(p.size()), m_wsum(p.size()), m_best_tri(P.faces)
  {
    lump_on_vertices(m_n, P.faces, P.target, m_literal_AM);
  }

  bool start(Flow_outcome& out)
  {
    signed_areas_sphere(m_p, m_tri.faces, m_u);
    m_d_area = m_best = d_area_of(m_u, m_target);
    out.initial_d_area = out.final_d_area = m_d_area;
    keep_best();
    return true;
  }

  bool converged() const { return m_best_converged; }

  /// Flips, then the Poisson potential h of L h = A_Ω − A_M (closed surface:
  /// pin h_0 = 0; the right-hand side sums to zero) and the area-weighted
  /// mean of its face gradients, less their normal component (§5.3).
  Direction_status direction(Flow_outcome& out)
  {
    Sparse_matrix L;
    {
      Scoped_timer timer(out.seconds_assembly);
      m_flips = 0;
      if(m_opt.paper.delaunay_flips) m_flips = make_delaunay_sphere(m_tri, m_p, [&](int f) { retarget(f); }, m_max_flips);
      out.flips += m_flips;
      if(m_flips > 0) signed_areas_sphere(m_p, m_tri.faces, m_u);
      lump_on_vertices(m_n, m_tri.faces, m_u, m_AO);
      if(m_opt.paper.lump_targets_on_flowing_faces) lump_on_vertices(m_n, m_tri.faces, m_target, m_AM);
      else m_AM = m_literal_AM;
      // The cotangent stiffness alone (no mass term).
      L = sphere_sobolev_matrix(m_p, m_tri.faces, 0.);
    }
    std::vector<double> h;
    if(!solve_pinned_poisson(L, m_AO, m_AM, m_solver, out, h)) return Direction_status::SOLVER_FAILED;
    Scoped_timer timer(out.seconds_step);
    std::fill(m_grad.begin(), m_grad.end(), Vec3{{ 0, 0, 0 }});
    std::fill(m_wsum.begin(), m_wsum.end(), 0.);
    for(std::size_t t = 0; t < m_tri.faces.size(); ++t) {
      const Face& f = m_tri.faces[t];
      const std::size_t a = std::size_t(f[0]), b = std::size_t(f[1]), c = std::size_t(f[2]);
      const Vec3 gt = p1_gradient_3(m_p[a], m_p[b], m_p[c], h[a], h[b], h[c]);
      for(int k = 0; k < 3; ++k) {
        Vec3& gv = m_grad[std::size_t(f[k])];
        for(int j = 0; j < 3; ++j) gv[j] += m_u[t] * gt[j];
        m_wsum[std::size_t(f[k])] += m_u[t];
      }
    }
    for(std::size_t v = 0; v < m_n; ++v)
      for(int j = 0; j < 3; ++j) m_d[v][j] = m_grad[v][j] / m_wsum[v];
    project_to_tangent(m_p, m_d);
    return Direction_status::DESCENT;
  }

  void bound(Flow_step& step)
  {
    step.flips = m_flips;
    const std::vector<Face>& F = m_tri.faces;
    step.critical = smallest_critical_step(F.size(), [&](std::size_t t, double) {
      const std::size_t a = std::size_t(F[t][0]), b = std::size_t(F[t][1]), c = std::size_t(F[t][2]);
      return critical_step_sphere(m_p[a], m_p[b], m_p[c], m_d[a], m_d[b], m_d[c]);
    }, step.limiting);
    step.lambda = paper_first_step(m_opt, step.critical);
  }

  /// Shrinks until every flowing face is positive (exact) and none collapses:
  /// a face's share of the sphere may not fall below `degeneracy_ratio` times
  /// its target share, nor, if the start already has it below, halve per step.
  void search(Flow_step& step, Flow_outcome& out)
  {
    double U = 0, T = 0;
    for(std::size_t t = 0; t < m_u.size(); ++t) { U += m_u[t]; T += m_target[t]; }
    bool accepted = false;
    for(; step.halvings <= m_opt.max_backtracks; ++step.halvings, step.lambda *= 0.5) {
      const double lambda = step.lambda;
      for(std::size_t v = 0; v < m_n; ++v)
        m_trial[v] = normalized(Vec3{{ m_p[v][0] + lambda * m_d[v][0], m_p[v][1] + lambda * m_d[v][1], m_p[v][2] + lambda * m_d[v][2] }});
      signed_areas_sphere(m_trial, m_tri.faces, m_u_trial);
      double U_trial = 0;
      bool ok = true;
      for(std::size_t t = 0; t < m_u_trial.size() && ok; ++t) { ok = m_u_trial[t] > 0; U_trial += m_u_trial[t]; }
      for(std::size_t t = 0; t < m_u_trial.size() && ok; ++t)
        ok = (m_u_trial[t] / U_trial) >= (std::min)(m_opt.paper.degeneracy_ratio * (m_target[t] / T), 0.5 * (m_u[t] / U));
      if(!ok) continue;
      if(!certified_trial_sphere(m_trial, m_tri.faces)) { ++out.rejected_by_exact_check; continue; }
      accepted = true;
      break;
    }
    // A fixed step that would fold is the paper's "collapse".
    step.accepted = accepted && !(m_opt.fixed_step > 0 && step.halvings > 0);
  }

  void commit(const Flow_step&, Flow_outcome&)
  {
    m_p.swap(m_trial);
    m_u.swap(m_u_trial);
    m_d_area = d_area_of(m_u, m_target);
    if(m_d_area < m_best) { m_best = m_d_area; keep_best(); }
    m_best_iterate = (std::min)(m_best_iterate, m_d_area);
  }

  double d_area() const { return m_d_area; }
  /// The iterates' own best: the first flips change the targets, so the
  /// start's D_area (on the input triangulation) may stay the lowest for a
  /// while as the flow descends.
  double progress() const { return m_best_iterate; }
  double residual() const { return area_residual(m_n, m_tri.faces, m_u, m_target); }

  void finish(Flow_outcome& out)
  {
    m_p = m_best_p;
    flip_best_once_more(out);
    m_non_delaunay_edges = count_non_delaunay_edges_sphere(m_best_tri, m_p);
    signed_areas_sphere(m_p, m_best_tri.faces, m_u);
    out.final_d_area = d_area_of(m_u, m_best_target);
    set_final_domain(out, area_residual(m_n, m_best_tri.faces, m_u, m_best_target), m_solver.analyses(),
                     m_best_tri.faces, m_best_target);
  }

  std::size_t non_delaunay_edges() const { return m_non_delaunay_edges; }

private:
  static Flow_stopping::Rules stopping_rules(const Discrete_lie_flow_options& opt)
  {
    Flow_stopping::Rules r = Flow_stopping::rules_of(opt);
    r.stall = Flow_stopping::SAME_LIMITING_FACE;
    return r;
  }

  void retarget(int f) { m_target[std::size_t(f)] = m_targets(m_tri.faces[std::size_t(f)]); }

  void keep_best()
  {
    m_best_p = m_p;
    m_best_tri = m_tri;
    m_best_target = m_target;
    m_best_converged = m_best - 2 <= m_opt.tolerance &&
                       (!(m_opt.sphere.log_area_tolerance > 0) ||
                        flat_mean_abs_log_ratio(m_p, m_tri.faces, m_target) <= m_opt.sphere.log_area_tolerance);
  }

  /// The best triangulation was made Delaunay for the positions before its
  /// step; flip once more so that the returned one is Delaunay where it is,
  /// unless that raises D_area − 2 by more than half: on a start compressed
  /// to the rounding level, in-circle decisions are rounding noise (the
  /// measurements: doc/sphere_paper_mode.md). The best iterate is then
  /// returned unflipped, its non-Delaunay edges counted.
  void flip_best_once_more(Flow_outcome& out)
  {
    if(!m_opt.paper.delaunay_flips) return;
    Flip_triangulation flipped = m_best_tri;
    std::vector<double> flipped_target = m_best_target;
    const std::size_t last = make_delaunay_sphere(flipped, m_p, [&](int f) {
      flipped_target[std::size_t(f)] = m_targets(flipped.faces[std::size_t(f)]); }, m_max_flips);
    signed_areas_sphere(m_p, flipped.faces, m_u);
    const double D_flipped = d_area_of(m_u, flipped_target);
    if(last > 0 && D_flipped - 2 <= 1.5 * (m_best - 2)) {
      out.flips += last;
      m_best_tri = std::move(flipped);
      m_best_target.swap(flipped_target);
    }
  }

  const Sphere_problem& m_P;
  std::vector<Vec3>& m_p;
  const Discrete_lie_flow_options& m_opt;
  const std::size_t m_n;
  Pattern_reusing_solver<EigenSolver> m_solver;
  Flip_triangulation m_tri;
  const std::size_t m_max_flips;
  const Flowing_targets m_targets;
  std::vector<double> m_target, m_literal_AM, m_u, m_AO, m_AM, m_u_trial;
  std::vector<Vec3> m_best_p, m_trial, m_grad, m_d;
  std::vector<double> m_wsum;
  Flip_triangulation m_best_tri;
  std::vector<double> m_best_target;
  double m_d_area = 0, m_best = 0, m_best_iterate = infinite_step();
  bool m_best_converged = false;
  std::size_t m_flips = 0, m_non_delaunay_edges = 0;
};

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
