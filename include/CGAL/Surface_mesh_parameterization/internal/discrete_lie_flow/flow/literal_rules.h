// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The rules Algorithm 1 of the paper shares on the plane and on the sphere:
// μ, the step λ = μ·λ_crit of Eq. 5 or a fixed step, the stop tests (its own
// rule ‖h_M − h_Ω‖² < ε, the cap and collapse only), what counts as no
// motion (a collapse), and the base of its two policies.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_LITERAL_RULES_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_LITERAL_RULES_H

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_options.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/area_elements.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/certification.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/edge_flips.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/sparse_solver.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/flow/flow_driver.h>

#include <cstddef>
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

/// What Algorithm 1's policies share on the plane and on the sphere: the
/// flowing triangulation and its targets (a face a flip creates gets ρ ×
/// its 3D triangle), h_M lumped once on the input triangles (step 1), the
/// measures of an iterate from its signed areas `m_u` (D_area, h_Ω and
/// the stop rule's ‖h_M − h_Ω‖², step 8), the exact check of a trial, and
/// the outcome at the end.
template <class EigenSolver>
class Literal_flow_base : public Flow_policy_base
{
public:
  Literal_flow_base(std::size_t n, const std::vector<Vec3>& xyz, const std::vector<Face>& faces,
                    const std::vector<double>& target, const Discrete_lie_flow_options& opt, EigenSolver& eigen_solver)
    : Flow_policy_base(literal_stopping_rules(opt)), m_opt(opt), m_n(n), m_solver(eigen_solver), m_tri(faces),
      m_targets(xyz, faces, target), m_target(target)
  {
    // Step 1: h_M = f_*(ω_M), with the density on it (Eq. 6), once.
    lump_on_vertices(m_n, faces, target, m_hM);
  }

  /// Step 8: ‖h_M − h_Ω‖² < ε on the current (flipped) iterate.
  bool converged() const { return m_mismatch < m_opt.paper.residual_threshold; }
  double d_area() const { return m_d_area; }
  double progress() const { return m_d_area; }
  double residual() const { return area_residual(m_n, m_tri.faces, m_u, m_target); }
  /// ‖h_M − h_Ω‖² of the current iterate (the stop rule's value).
  double mismatch() const { return m_mismatch; }

  void finish(Flow_outcome& out)
  {
    out.final_d_area = m_d_area;
    set_final_domain(out, residual(), m_solver.analyses(), m_tri.faces, m_target);
  }

protected:
  /// Step 4: the potential g of L g = h_Ω − h_M, g_0 = 0 (L = −Δ,
  /// doc/paper_errata.md, "Sign"); false when the solve fails.
  bool solve_potential(const Sparse_matrix& L, Flow_outcome& out, std::vector<double>& g)
  {
    return solve_pinned_poisson(L, m_hO, m_hM, m_solver, out, g);
  }
  /// Step 6 from the smallest critical step.
  double step_of(double critical) const { return literal_step(m_opt, critical); }
  /// D_area of the iterate whose signed areas are in `m_u`, on the current targets.
  double d_area_now() const { return d_area_of(m_u, m_target); }

  /// The target of the flowing face `f` a flip created.
  void retarget(int f) { m_target[std::size_t(f)] = m_targets(m_tri.faces[std::size_t(f)]); }
  /// The cap of the flips of one Delaunay pass.
  std::size_t most_flips() const { return 100 * m_tri.faces.size() + 100; }

  /// D_area, h_Ω and ‖h_M − h_Ω‖² of the iterate whose signed areas are in `m_u`.
  void measure()
  {
    m_d_area = d_area_now();
    lump_on_vertices(m_n, m_tri.faces, m_u, m_hO);
    m_mismatch = normalized_mismatch(m_hO, m_hM);
  }

  /// The exact check of a trial (`oc`, its flowing faces' orientations):
  /// a folded or degenerate face refuses the step, counted in `out`.
  static bool certify_trial(const Orientation_count& oc, Flow_outcome& out)
  {
    if(oc.all_positive()) return true;
    ++out.rejected_by_exact_check;
    out.collapse_faces = oc.inverted + oc.degenerate;
    return false;
  }

  const Discrete_lie_flow_options& m_opt;
  const std::size_t m_n;
  Pattern_reusing_solver<EigenSolver> m_solver;
  Flip_triangulation m_tri;
  const Flowing_targets m_targets;
  std::vector<double> m_target, m_hM, m_hO, m_u;
  double m_d_area = 0, m_mismatch = 0;
};

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
