// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Algorithm 1 of the paper as printed, on the plane and on the sphere, as
// policies of the flow driver: (2) Delaunay flips of the flowing mesh;
// (3) h_Ω, the vertex area elements of the flowing mesh, scaled to the
// integral of h_M, the targets lumped once on the input triangles (1);
// (4) the Neumann Poisson problem Δg = h_M − h_Ω; (5) the vertex gradients
// ∇g; (6) λ = μ·min_t λ̃_t (Eq. 5), or a fixed step; (7) φ += λ∇g; (8) until
// ‖h_M − h_Ω‖² < ε. No line search, no collapse guard, no plateau test: a
// step that folds or degenerates a flowing face (exact predicate) ends the
// run as COLLAPSED. Where the print is corrected: doc/paper_errata.md.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_LITERAL_FLOW_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_LITERAL_FLOW_H

#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/area_elements.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/boundary_curve.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/certification.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/cotangent_laplacian.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/critical_step.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/disk_problem.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/edge_flips.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/flow_driver.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/planar_dofs.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/sparse_solver.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/sphere_directions.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/sphere_edge_flips.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/sphere_problem.h>

#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// The literal mode's μ when the caller gives none: the top of the paper's
/// range 0.2–0.8 (§5.4).
constexpr double literal_default_mu = 0.8;

/// The literal mode's stop tests: its own stop rule (`converged()`), the
/// iteration cap and collapse only.
inline Flow_stopping::Rules literal_stopping_rules(const Discrete_lie_flow_options& opt)
{
  Flow_stopping::Rules r = Flow_stopping::rules_of(opt);
  r.plateau = false;
  r.stall = Flow_stopping::NO_STALL_TEST;
  return r;
}

/// Step 6: λ = μ·λ_crit (Eq. 5), or the caller's fixed step.
inline double literal_step(const Discrete_lie_flow_options& opt, double critical)
{
  return opt.fixed_step > 0 ? opt.fixed_step : step_fraction(opt, literal_default_mu) * critical;
}

/// A step that moves no vertex by more than this fraction of the domain's
/// size has collapsed: the critical step went to the rounding level.
constexpr double literal_least_motion = 1e-12;

/// Algorithm 1 on the plane, from the positively oriented `uv`: boundary
/// vertices keep the tangential part of ∇g and slide along `curve`. On
/// return, `uv` is the last iterate (every flowing face positive) and the
/// outcome holds its Delaunay triangulation.
template <class EigenSolver>
class Planar_literal_flow : public Flow_policy_base
{
public:
  Planar_literal_flow(const Disk_problem& P, std::vector<Vec2>& uv, Boundary_curve& curve,
                      const Discrete_lie_flow_options& opt, EigenSolver& eigen_solver)
    : Flow_policy_base(literal_stopping_rules(opt)), m_uv(uv), m_curve(curve), m_opt(opt), m_n(uv.size()),
      m_dofs(uv.size(), P.boundary, curve), m_solver(eigen_solver), m_tri(P.faces),
      m_targets(P.xyz, P.faces, P.target), m_target(P.target), m_basis(std::size_t(m_dofs.size))
  {
    // Step 1: h_M = f_*(ω_M), with the density on it (Eq. 6), once.
    lump_on_vertices(m_n, P.faces, P.target, m_hM);
  }

  bool start(Flow_outcome& out)
  {
    signed_areas_2(m_uv, m_tri.faces, m_u);
    out.initial_d_area = d_area_of(m_u, m_target);
    double area = 0;
    for(double a : m_u) area += a;
    m_size = std::sqrt(area);
    after_move(out);
    return true;
  }

  /// Step 8: ‖h_M − h_Ω‖² < ε on the current (flipped) iterate.
  bool converged() const { return m_mismatch < m_opt.paper.residual_threshold; }

  /// Steps 3–5: L g = h_Ω − h_M with L the cotangent stiffness (L = −Δ;
  /// doc/paper_errata.md, "Sign"), g_0 = 0; ∇g per face, area-weighted at the
  /// vertices; the border keeps its tangential part.
  Direction_status direction(Flow_outcome& out)
  {
    Sparse_matrix L;
    {
      Scoped_timer timer(out.seconds_assembly);
      L = cotangent_stiffness(m_uv, m_tri.faces);
    }
    std::vector<double> g;
    if(!solve_pinned_poisson(L, m_hO, m_hM, m_solver, out, g)) return Direction_status::SOLVER_FAILED;
    Scoped_timer timer(out.seconds_step);
    if(!potential_gradient_direction(m_uv, m_tri.faces, m_u, g, m_dofs, m_curve, m_basis, m_d))
      return Direction_status::NO_DESCENT;
    planar_velocity(m_n, m_dofs, m_basis, m_d, m_vel);
    return Direction_status::DESCENT;
  }

  /// Step 6 (Eq. 5 with the corrected coefficients of Eq. 4).
  void bound(Flow_step& step)
  {
    const std::vector<Face>& F = m_tri.faces;
    step.critical = smallest_critical_step(F.size(), [&](std::size_t t, double) {
      return critical_step_2(m_uv[F[t][0]], m_uv[F[t][1]], m_uv[F[t][2]], m_vel[F[t][0]], m_vel[F[t][1]], m_vel[F[t][2]]);
    }, step.limiting);
    step.lambda = literal_step(m_opt, step.critical);
  }

  /// Step 7, or the documented failure: the step is taken as it is, and
  /// refused (collapse) if a flowing face is not positive after it, a border
  /// vertex runs off its piece of border, or no vertex moves.
  void search(Flow_step& step, Flow_outcome& out)
  {
    if(!std::isfinite(step.lambda)) return; // Eq. 5 gives no step: stalled
    step.collapsed = true;
    if(!planar_trial(m_uv, m_dofs, m_basis, m_d, step.lambda, m_curve, m_trial)) return;
    double moved = 0;
    for(std::size_t v = 0; v < m_n; ++v)
      moved = (std::max)(moved, (std::max)(std::abs(m_trial[v][0] - m_uv[v][0]), std::abs(m_trial[v][1] - m_uv[v][1])));
    if(!(moved > literal_least_motion * m_size)) return;
    const Orientation_count oc = count_orientations_2(m_trial, m_tri.faces);
    if(!oc.all_positive()) {
      ++out.rejected_by_exact_check;
      out.collapse_faces = oc.inverted + oc.degenerate;
      return;
    }
    step.collapsed = false;
    step.accepted = true;
  }

  void commit(Flow_step& step, Flow_outcome& out)
  {
    for(std::size_t v = 0; v < m_n; ++v)
      if(m_dofs.boundary_of[v] >= 0 && m_dofs.count[v] > 0)
        m_curve.commit(std::size_t(m_dofs.boundary_of[v]), step.lambda * m_d[m_dofs.first[v]]);
    m_uv.swap(m_trial);
    step.flips = after_move(out);
  }

  double d_area() const { return m_d_area; }
  double progress() const { return m_d_area; }
  double residual() const { return area_residual(m_n, m_tri.faces, m_u, m_target); }
  /// ‖h_M − h_Ω‖² of the current iterate (the stop rule's value).
  double mismatch() const { return m_mismatch; }

  void finish(Flow_outcome& out)
  {
    out.final_d_area = m_d_area;
    out.final_residual = residual();
    out.symbolic_analyses = m_solver.analyses();
    out.domain_faces = m_tri.faces;
    out.domain_target = m_target;
  }

private:
  /// Step 2 and the measures of the new iterate; the number of flips.
  std::size_t after_move(Flow_outcome& out)
  {
    const std::size_t flips = m_tri.make_delaunay(m_uv, [&](int f) {
      m_target[std::size_t(f)] = m_targets(m_tri.faces[std::size_t(f)]); }, 100 * m_tri.faces.size() + 100);
    out.flips += flips;
    signed_areas_2(m_uv, m_tri.faces, m_u);
    m_d_area = d_area_of(m_u, m_target);
    lump_on_vertices(m_n, m_tri.faces, m_u, m_hO);
    m_mismatch = normalized_mismatch(m_hO, m_hM);
    return flips;
  }

  std::vector<Vec2>& m_uv;
  Boundary_curve& m_curve;
  const Discrete_lie_flow_options& m_opt;
  const std::size_t m_n;
  Planar_dofs m_dofs;
  Pattern_reusing_solver<EigenSolver> m_solver;
  Flip_triangulation m_tri;
  const Flowing_targets m_targets;
  std::vector<double> m_target, m_hM, m_hO, m_u;
  std::vector<Vec2> m_basis, m_vel, m_trial;
  Eigen::VectorXd m_d;
  double m_d_area = 0, m_mismatch = 0, m_size = 1;
};

/// Algorithm 1 on the unit sphere, from the positively oriented unit vectors
/// `p`: ∇g less its normal part (§5.3), points re-normalised after the step,
/// λ̃_t the exact root of the orientation cubic (doc/paper_errata.md,
/// "Sphere"). On return, `p` is the last iterate.
template <class EigenSolver>
class Sphere_literal_flow : public Flow_policy_base
{
public:
  Sphere_literal_flow(const Sphere_problem& P, std::vector<Vec3>& p, const Discrete_lie_flow_options& opt,
                      EigenSolver& eigen_solver)
    : Flow_policy_base(literal_stopping_rules(opt)), m_p(p), m_opt(opt), m_n(p.size()), m_solver(eigen_solver),
      m_tri(P.faces), m_targets(P.xyz, P.faces, P.target), m_target(P.target), m_d(p.size())
  {
    lump_on_vertices(m_n, P.faces, P.target, m_hM);
  }

  bool start(Flow_outcome& out)
  {
    signed_areas_sphere(m_p, m_tri.faces, m_u);
    out.initial_d_area = d_area_of(m_u, m_target);
    after_move(out);
    return true;
  }

  bool converged() const { return m_mismatch < m_opt.paper.residual_threshold; }

  Direction_status direction(Flow_outcome& out)
  {
    Sparse_matrix L;
    {
      Scoped_timer timer(out.seconds_assembly);
      L = sphere_sobolev_matrix(m_p, m_tri.faces, 0.);
    }
    std::vector<double> g;
    if(!solve_pinned_poisson(L, m_hO, m_hM, m_solver, out, g)) return Direction_status::SOLVER_FAILED;
    Scoped_timer timer(out.seconds_step);
    std::vector<double> wsum(m_n, 0.);
    std::fill(m_d.begin(), m_d.end(), Vec3{{ 0, 0, 0 }});
    for(std::size_t t = 0; t < m_tri.faces.size(); ++t) {
      const Face& f = m_tri.faces[t];
      const std::size_t a = std::size_t(f[0]), b = std::size_t(f[1]), c = std::size_t(f[2]);
      const Vec3 gt = p1_gradient_3(m_p[a], m_p[b], m_p[c], g[a], g[b], g[c]);
      for(int k = 0; k < 3; ++k) {
        for(int j = 0; j < 3; ++j) m_d[std::size_t(f[k])][j] += m_u[t] * gt[j];
        wsum[std::size_t(f[k])] += m_u[t];
      }
    }
    bool moves = false;
    for(std::size_t v = 0; v < m_n; ++v)
      for(int j = 0; j < 3; ++j) m_d[v][j] /= wsum[v];
    project_to_tangent(m_p, m_d);
    for(std::size_t v = 0; v < m_n && !moves; ++v) moves = m_d[v][0] != 0 || m_d[v][1] != 0 || m_d[v][2] != 0;
    return moves ? Direction_status::DESCENT : Direction_status::NO_DESCENT;
  }

  void bound(Flow_step& step)
  {
    const std::vector<Face>& F = m_tri.faces;
    step.critical = smallest_critical_step(F.size(), [&](std::size_t t, double) {
      const std::size_t a = std::size_t(F[t][0]), b = std::size_t(F[t][1]), c = std::size_t(F[t][2]);
      return critical_step_sphere(m_p[a], m_p[b], m_p[c], m_d[a], m_d[b], m_d[c]);
    }, step.limiting);
    step.lambda = literal_step(m_opt, step.critical);
  }

  void search(Flow_step& step, Flow_outcome& out)
  {
    if(!std::isfinite(step.lambda)) return;
    step.collapsed = true;
    m_trial.resize(m_n);
    double moved = 0;
    for(std::size_t v = 0; v < m_n; ++v) {
      m_trial[v] = normalized(Vec3{{ m_p[v][0] + step.lambda * m_d[v][0], m_p[v][1] + step.lambda * m_d[v][1],
                                     m_p[v][2] + step.lambda * m_d[v][2] }});
      for(int j = 0; j < 3; ++j) moved = (std::max)(moved, std::abs(m_trial[v][j] - m_p[v][j]));
    }
    if(!(moved > literal_least_motion)) return;
    const Orientation_count oc = count_orientations_sphere(m_trial, m_tri.faces);
    if(!oc.all_positive()) {
      ++out.rejected_by_exact_check;
      out.collapse_faces = oc.inverted + oc.degenerate;
      return;
    }
    step.collapsed = false;
    step.accepted = true;
  }

  void commit(Flow_step& step, Flow_outcome& out)
  {
    m_p.swap(m_trial);
    step.flips = after_move(out);
  }

  double d_area() const { return m_d_area; }
  double progress() const { return m_d_area; }
  double residual() const { return area_residual(m_n, m_tri.faces, m_u, m_target); }
  double mismatch() const { return m_mismatch; }
  std::size_t non_delaunay_edges() const { return count_non_delaunay_edges_sphere(m_tri, m_p); }

  void finish(Flow_outcome& out)
  {
    out.final_d_area = m_d_area;
    out.final_residual = residual();
    out.symbolic_analyses = m_solver.analyses();
    out.domain_faces = m_tri.faces;
    out.domain_target = m_target;
  }

private:
  std::size_t after_move(Flow_outcome& out)
  {
    const std::size_t flips = make_delaunay_sphere(m_tri, m_p, [&](int f) {
      m_target[std::size_t(f)] = m_targets(m_tri.faces[std::size_t(f)]); }, 100 * m_tri.faces.size() + 100);
    out.flips += flips;
    signed_areas_sphere(m_p, m_tri.faces, m_u);
    m_d_area = d_area_of(m_u, m_target);
    lump_on_vertices(m_n, m_tri.faces, m_u, m_hO);
    m_mismatch = normalized_mismatch(m_hO, m_hM);
    return flips;
  }

  std::vector<Vec3>& m_p;
  const Discrete_lie_flow_options& m_opt;
  const std::size_t m_n;
  Pattern_reusing_solver<EigenSolver> m_solver;
  Flip_triangulation m_tri;
  const Flowing_targets m_targets;
  std::vector<double> m_target, m_hM, m_hO, m_u;
  std::vector<Vec3> m_d, m_trial;
  double m_d_area = 0, m_mismatch = 0;
};

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
