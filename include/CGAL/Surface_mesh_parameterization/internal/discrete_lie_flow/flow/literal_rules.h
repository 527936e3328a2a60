// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The rules Algorithm 1 of the paper shares on the plane and on the sphere:
// μ, the step λ = μ·λ_crit of Eq. 5 or a fixed step, the stop tests (its own
// rule ‖h_M − h_Ω‖² < ε, the cap and collapse only) and what counts as no
// motion (a collapse).

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_LITERAL_RULES_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_LITERAL_RULES_H

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_options.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/flow/flow_driver.h>

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

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
