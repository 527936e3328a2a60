// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Algorithm 1 of the paper as printed, on the unit sphere, as a policy of the flow
// driver: (2) Delaunay flips of the flowing mesh; (3) h_Ω, the vertex area
// elements of the flowing mesh, and h_M, the targets lumped once on the
// input triangles (1), scaled to the integral of h_Ω (the print scales h_Ω
// to ∫h_M instead, which scales g by a constant); (4) the Neumann Poisson problem
// Δg = h_M − h_Ω; (5) the vertex gradients ∇g; (6) λ = μ·min_t λ̃_t (Eq. 5),
// or a fixed step; (7) φ += λ∇g; (8) until ‖h_M − h_Ω‖² < ε. No line search,
// no collapse guard, no plateau test: a step that folds or degenerates a
// flowing face (exact predicate) ends the run as COLLAPSED. Where the print
// is corrected: doc/paper_errata.md.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_SPHERE_LITERAL_FLOW_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_SPHERE_LITERAL_FLOW_H

#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/area_elements.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/certification.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/critical_step.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/flow/flow_driver.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/sparse_solver.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/sphere/sphere_directions.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/sphere/sphere_edge_flips.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/sphere/sphere_problem.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/flow/literal_rules.h>

#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// Algorithm 1 on the unit sphere, from the positively oriented unit vectors
/// `p`: ∇g less its normal part (§5.3), points re-normalised after the step,
/// λ̃_t the exact root of the orientation cubic (doc/paper_errata.md,
/// "Sphere"). On return, `p` is the last iterate.
template <class EigenSolver>
class Sphere_literal_flow : public Literal_flow_base<EigenSolver>
{
  typedef Literal_flow_base<EigenSolver> Base;
  using Base::m_n;
  using Base::m_tri;
  using Base::m_u;

public:
  Sphere_literal_flow(const Sphere_problem& P, std::vector<Vec3>& p, const Discrete_lie_flow_options& opt,
                      EigenSolver& eigen_solver)
    : Base(p.size(), P.xyz, P.faces, P.target, opt, eigen_solver), m_p(p), m_d(p.size())
  {}

  bool start(Flow_outcome& out)
  {
    signed_areas_sphere(m_p, m_tri.faces, m_u);
    out.initial_d_area = this->d_area_now();
    after_move(out);
    return true;
  }

  Direction_status direction(Flow_outcome& out)
  {
    Sparse_matrix L;
    {
      Scoped_timer timer(out.seconds_assembly);
      L = sphere_sobolev_matrix(m_p, m_tri.faces, 0.);
    }
    std::vector<double> g;
    if(!this->solve_potential(L, out, g)) return Direction_status::SOLVER_FAILED;
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
    step.lambda = this->step_of(step.critical);
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
    if(!Base::certify_trial(count_orientations_sphere(m_trial, m_tri.faces), out)) return;
    step.collapsed = false;
    step.accepted = true;
  }

  void commit(Flow_step& step, Flow_outcome& out)
  {
    m_p.swap(m_trial);
    step.flips = after_move(out);
  }

  std::size_t non_delaunay_edges() const { return count_non_delaunay_edges_sphere(m_tri, m_p); }

private:
  std::size_t after_move(Flow_outcome& out)
  {
    const std::size_t flips = make_delaunay_sphere(m_tri, m_p, [this](int f) { this->retarget(f); }, this->most_flips());
    out.flips += flips;
    signed_areas_sphere(m_p, m_tri.faces, m_u);
    this->measure();
    return flips;
  }

  std::vector<Vec3>& m_p;
  std::vector<Vec3> m_d, m_trial;
};

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
