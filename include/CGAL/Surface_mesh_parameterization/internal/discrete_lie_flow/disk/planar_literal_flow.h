// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Algorithm 1 of the paper as printed, on the plane, as a policy of the flow
// driver: (2) Delaunay flips of the flowing mesh; (3) h_Ω, the vertex area
// elements of the flowing mesh, and h_M, the targets lumped once on the
// input triangles (1), scaled to the integral of h_Ω (the print scales h_Ω
// to ∫h_M instead, which scales g by a constant); (4) the Neumann Poisson problem
// Δg = h_M − h_Ω; (5) the vertex gradients ∇g; (6) λ = μ·min_t λ̃_t (Eq. 5),
// or a fixed step; (7) φ += λ∇g; (8) until ‖h_M − h_Ω‖² < ε. No line search,
// no collapse guard, no plateau test: a step that folds or degenerates a
// flowing face (exact predicate) ends the run as COLLAPSED. Where the print
// is corrected: doc/paper_errata.md.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_PLANAR_LITERAL_FLOW_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_PLANAR_LITERAL_FLOW_H

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
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/flow/literal_rules.h>

#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// Algorithm 1 on the plane, from the positively oriented `uv`: boundary
/// vertices keep the tangential part of ∇g and slide along `curve`. On
/// return, `uv` is the last iterate (every flowing face positive) and the
/// outcome holds its Delaunay triangulation.
template <class EigenSolver>
class Planar_literal_flow : public Literal_flow_base<EigenSolver>
{
  typedef Literal_flow_base<EigenSolver> Base;
  using Base::m_n;
  using Base::m_tri;
  using Base::m_u;

public:
  Planar_literal_flow(const Disk_problem& P, std::vector<Vec2>& uv, Boundary_curve& curve,
                      const Discrete_lie_flow_options& opt, EigenSolver& eigen_solver)
    : Base(uv.size(), P.xyz, P.faces, P.target, opt, eigen_solver), m_uv(uv), m_curve(curve),
      m_dofs(uv.size(), P.boundary, curve), m_basis(std::size_t(m_dofs.size))
  {}

  bool start(Flow_outcome& out)
  {
    signed_areas_2(m_uv, m_tri.faces, m_u);
    out.initial_d_area = this->d_area_now();
    double area = 0;
    for(double a : m_u) area += a;
    m_size = std::sqrt(area);
    after_move(out);
    return true;
  }

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
    if(!this->solve_potential(L, out, g)) return Direction_status::SOLVER_FAILED;
    Scoped_timer timer(out.seconds_step);
    if(!potential_gradient_direction(m_uv, m_tri.faces, m_u, g, m_dofs, m_curve, m_basis, m_d))
      return Direction_status::NO_DESCENT;
    planar_velocity(m_n, m_dofs, m_basis, m_d, m_vel);
    return Direction_status::DESCENT;
  }

  /// Step 6 (Eq. 5 with the corrected coefficients of Eq. 4).
  void bound(Flow_step& step)
  {
    step.critical = planar_critical_step(m_uv, m_tri.faces, m_vel, step.limiting);
    step.lambda = this->step_of(step.critical);
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
    if(!Base::certify_trial(count_orientations_2(m_trial, m_tri.faces), out)) return;
    step.collapsed = false;
    step.accepted = true;
  }

  void commit(Flow_step& step, Flow_outcome& out)
  {
    commit_border_step(m_dofs, step.lambda, m_d, m_curve);
    m_uv.swap(m_trial);
    step.flips = after_move(out);
  }

private:
  /// Step 2 and the measures of the new iterate; the number of flips.
  std::size_t after_move(Flow_outcome& out)
  {
    const std::size_t flips = m_tri.make_delaunay(m_uv, [this](int f) { this->retarget(f); }, this->most_flips());
    out.flips += flips;
    signed_areas_2(m_uv, m_tri.faces, m_u);
    this->measure();
    return flips;
  }

  std::vector<Vec2>& m_uv;
  Boundary_curve& m_curve;
  Planar_dofs m_dofs;
  std::vector<Vec2> m_basis, m_vel, m_trial;
  Eigen::VectorXd m_d;
  double m_size = 1;
};

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
