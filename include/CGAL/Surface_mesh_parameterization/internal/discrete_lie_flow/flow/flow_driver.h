// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The one loop of every flow (planar and spherical; certified, paper and literal):
// direction; bound by the smallest critical root; search with exact
// certification; commit; post-step (flips or relaxation sweeps); record;
// stop. What differs between the flows lives in their policies, one folder
// per wing (disk/, sphere/, volume/: the certified, paper and literal
// policies of each); the loop and the policy interface are described in
// doc/design.md, "The flow driver", the folders in doc/architecture.md.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_FLOW_DRIVER_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_FLOW_DRIVER_H

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_options.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/geometry.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/sparse_solver.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// What a flow run reports besides the positions.
struct Flow_outcome
{
  Discrete_lie_flow_stop_reason stop_reason = Discrete_lie_flow_stop_reason::NOT_RUN;
  std::size_t iterations = 0;
  double initial_d_area = 0;  ///< on the certified triangulation
  double final_d_area = 0;
  double final_residual = 0;
  std::size_t flips = 0;      ///< paper mode: edge flips in total
  std::size_t rejected_by_exact_check = 0; ///< trial steps the doubles accepted and the exact predicate refused
  std::size_t collapse_faces = 0; ///< literal mode: flowing faces the refused step folded or degenerated
  std::size_t factorizations = 0, symbolic_analyses = 0;
  bool solver_failed = false;
  /// Time split of the iterations (seconds): assembly, factorisation + solve, step search and post-step.
  double seconds_assembly = 0, seconds_solve = 0, seconds_step = 0;
  std::vector<Discrete_lie_flow_iteration> history;
  /// The final domain triangulation (the input's, or the flowing one of the
  /// paper mode) and the targets the flow used on it.
  std::vector<Face> domain_faces;
  std::vector<double> domain_target;
};

/// What a surface policy's finish() hands the outcome: the final residual,
/// its solvers' symbolic analyses, and the triangulation it ended on (the
/// caller's, or the flipped one) with the targets it used there.
inline void set_final_domain(Flow_outcome& out, double residual, std::size_t analyses, const std::vector<Face>& faces,
                             const std::vector<double>& target)
{
  out.final_residual = residual;
  out.symbolic_analyses = analyses;
  out.domain_faces = faces;
  out.domain_target = target;
}

/// Adds the time spent in its scope to a counter of the outcome.
class Scoped_timer
{
public:
  explicit Scoped_timer(double& total) : m_total(total), m_start(Clock::now()) {}
  ~Scoped_timer() { m_total += std::chrono::duration<double>(Clock::now() - m_start).count(); }
  Scoped_timer(const Scoped_timer&) = delete;
  Scoped_timer& operator=(const Scoped_timer&) = delete;

private:
  typedef std::chrono::steady_clock Clock;
  double& m_total;
  Clock::time_point m_start;
};

/// One iteration's step, filled by the policy as the driver goes.
struct Flow_step
{
  double critical = infinite_step(); ///< smallest critical root along the direction
  int limiting = -1;                 ///< the face that attains it
  double lambda = 0;                 ///< the step tried, then accepted
  std::size_t halvings = 0;          ///< step halvings before acceptance
  std::size_t flips = 0;             ///< edge flips of this iteration (paper modes)
  bool accepted = false;
  bool collapsed = false;            ///< not accepted because the step collapses the mesh (literal mode)
};

/// What a policy's direction phase found.
enum class Direction_status
{
  DESCENT,       ///< a descent direction is ready
  NO_DESCENT,    ///< the gradient vanishes: nothing left to gain
  SOLVER_FAILED  ///< the linear solve failed and the policy has no fallback
};

/// The stop tests every flow shares, on the sequence of a progress value
/// (an energy, or the best D_area so far) recorded after each iteration.
class Flow_stopping
{
public:
  enum Stall { NO_STALL_TEST, SAME_LIMITING_FACE, HARD_STEPS };

  struct Rules
  {
    /// Plateau: the progress value x improved by less than
    /// `plateau_tolerance` · (x − 1) over `plateau_window` iterations.
    bool plateau = true;
    std::size_t plateau_window = 10;
    double plateau_tolerance = 1e-4;
    /// Slow tail (0: off): x − 2 shrank by less than `tail_rate` of itself
    /// over `tail_window` iterations.
    double tail_rate = 0;
    std::size_t tail_window = 0;
    /// Plateau in a row (0: off), the certified volumetric flow's rule: one
    /// iteration's relative gain (x_prev − x)/(x − 2) below
    /// `row_tolerance` for `row_window` iterations in a row, counted afresh
    /// after any larger gain.
    std::size_t row_window = 0;
    double row_tolerance = 0;
    /// Stall: the same face limits `stall_window` consecutive steps shorter
    /// than `stall_step`, or as many steps need 20 halvings or more.
    Stall stall = NO_STALL_TEST;
    std::size_t stall_window = 25;
    double stall_step = 0;
  };

  /// The rules of the options: a plateau of their window and tolerance, and
  /// their stall window; no slow tail and no stall test until a flow sets them.
  static Rules rules_of(const Discrete_lie_flow_options& opt)
  {
    Rules r;
    r.plateau_window = opt.plateau_window;
    r.plateau_tolerance = opt.plateau_tolerance;
    r.stall_window = opt.stall_window;
    r.stall_step = 1e-3 * opt.paper.step_cap;
    return r;
  }

  explicit Flow_stopping(const Rules& rules) : m_rules(rules) {}

  /// The rules of the plateau in a row alone, over `window` iterations of
  /// relative gain below `tolerance` (no window plateau, no stall test).
  static Rules plateau_in_a_row(std::size_t window, double tolerance)
  {
    Rules r;
    r.plateau = false;
    r.row_window = window;
    r.row_tolerance = tolerance;
    return r;
  }

  /// Restarts the progress sequence from `x0` (the start, or a new phase of the flow).
  void restart(double x0) { m_history.assign(1, x0); m_row = 0; }

  /// Records the iteration's progress value; the reason to stop, or
  /// `ITERATION_CAP` to go on.
  Discrete_lie_flow_stop_reason after(const Flow_step& step, double x)
  {
    typedef Discrete_lie_flow_stop_reason R;
    m_history.push_back(x);
    const bool flat_row = in_a_row(x);
    if(stalled(step)) return R::STALLED;
    if(m_rules.plateau && m_history.size() > m_rules.plateau_window &&
       back(m_rules.plateau_window) - x < m_rules.plateau_tolerance * (x - 1))
      return R::PLATEAU;
    if(m_rules.tail_rate > 0 && m_history.size() > m_rules.tail_window &&
       back(m_rules.tail_window) - x < m_rules.tail_rate * (x - 2))
      return R::PLATEAU;
    if(flat_row) return R::PLATEAU;
    return R::ITERATION_CAP;
  }

private:
  double back(std::size_t k) const { return m_history[m_history.size() - 1 - k]; }

  // The plateau in a row: counts the iterations of small relative gain.
  bool in_a_row(double x)
  {
    if(m_rules.row_window == 0 || m_history.size() < 2) return false;
    const double gain = (back(1) - x) / (std::max)(x - 2, 1e-300);
    m_row = gain < m_rules.row_tolerance ? m_row + 1 : 0;
    return m_row >= m_rules.row_window;
  }

  bool stalled(const Flow_step& step)
  {
    if(m_rules.stall == SAME_LIMITING_FACE) {
      // A vertex driven onto an edge: the same triangle limits the step again
      // and again while the step is far below the cap.
      m_count = (step.limiting == m_last_limiting && step.lambda < m_rules.stall_step) ? m_count + 1 : 0;
      m_last_limiting = step.limiting;
    } else if(m_rules.stall == HARD_STEPS) {
      // The step keeps collapsing. An absolute threshold on λ would be wrong:
      // tiny steps can still lower the energy a lot.
      m_count = step.halvings >= 20 ? m_count + 1 : 0;
    } else {
      return false;
    }
    return m_count >= m_rules.stall_window;
  }

  Rules m_rules;
  std::vector<double> m_history;
  int m_last_limiting = -1;
  std::size_t m_count = 0;
  std::size_t m_row = 0;
};

/// The fraction μ of the smallest critical root that a step may take: the
/// caller's, or the flow's measured default.
inline double step_fraction(const Discrete_lie_flow_options& opt, double fallback = 0.8)
{
  return opt.mu > 0 ? opt.mu : fallback;
}

/// What every policy shares: its stop tests, and a plateau that ends the
/// flow (a policy with phases hides `on_plateau()`).
class Flow_policy_base
{
public:
  explicit Flow_policy_base(const Flow_stopping::Rules& rules) : m_stopping(rules) {}
  Flow_stopping& stopping() { return m_stopping; }
  bool on_plateau() { return true; }

protected:
  Flow_stopping m_stopping;
};

/// The first trial step of the certified flows: a fixed step if the caller
/// set one, else at most μ·λ_crit and at most 4 times the last accepted step
/// (1, the full model step, for Gauss–Newton); 1 when both bounds are infinite.
inline double certified_first_step(const Discrete_lie_flow_options& opt, bool newton, double previous, double critical)
{
  const double lambda = opt.fixed_step > 0 ? opt.fixed_step
                                           : (std::min)(newton ? 1. : 4 * previous, step_fraction(opt) * critical);
  return std::isfinite(lambda) ? lambda : 1;
}

/// The paper's step: a fixed step if the caller set one, else
/// λ = min(λ_cap, μ·λ_crit).
inline double paper_first_step(const Discrete_lie_flow_options& opt, double critical)
{
  return opt.fixed_step > 0 ? opt.fixed_step : (std::min)(opt.paper.step_cap, step_fraction(opt) * critical);
}

/// Levenberg–Marquardt update of a Gauss–Newton regularisation after an
/// accepted step: trust the model more after a full step, less after halvings.
inline double updated_regularization(double eps, std::size_t halvings)
{
  return halvings == 0 ? (std::max)(eps / 4, 1e-8) : (halvings >= 2 ? (std::min)(eps * 4, 1e4) : eps);
}

/// Smallest critical root over `faces` for `root(face index, bound so far)`;
/// `limiting` receives its face. The bound lets a root function skip faces
/// that provably cannot invert before it.
/// The Poisson step of the paper's flows: L h = a − b·Σa/Σb, with L the
/// full cotangent stiffness (its kernel: the constants) and h_0 = 0 pinned by
/// dropping row and column 0 (the right-hand side sums to zero). Counts and
/// times the factorisation; false if it or the solve fails.
template <class Solver>
bool solve_pinned_poisson(const Sparse_matrix& L, const std::vector<double>& a, const std::vector<double>& b,
                          Solver& solver, Flow_outcome& out, std::vector<double>& h)
{
  const std::size_t n = a.size();
  double sa = 0, sb = 0;
  for(std::size_t i = 0; i < n; ++i) { sa += a[i]; sb += b[i]; }
  Eigen::VectorXd rhs(Eigen::Index(n - 1)), x;
  for(std::size_t i = 1; i < n; ++i) rhs[Eigen::Index(i - 1)] = a[i] - b[i] * sa / sb;
  const Sparse_matrix Lr = L.bottomRightCorner(Eigen::Index(n - 1), Eigen::Index(n - 1));
  Scoped_timer timer(out.seconds_solve);
  ++out.factorizations;
  if(!solver.factorize(Lr) || !solver.solve(rhs, x)) return false;
  h.assign(n, 0.);
  for(std::size_t i = 1; i < n; ++i) h[i] = x[Eigen::Index(i - 1)];
  return true;
}

template <class Root>
double smallest_critical_step(std::size_t faces, const Root& root, int& limiting)
{
  double best = infinite_step();
  limiting = -1;
  for(std::size_t t = 0; t < faces; ++t) {
    const double r = root(t, best);
    if(r < best) { best = r; limiting = int(t); }
  }
  return best;
}

/// One iteration's record for the history and the callback. The residual (a
/// pass over the faces) is computed only when someone reads it. False when
/// the callback asks to stop.
template <class Residual>
bool record_iteration(const Discrete_lie_flow_options& opt, std::size_t iteration, const Flow_step& step,
                      double d_area, double seconds, const Residual& residual, Flow_outcome& out)
{
  Discrete_lie_flow_iteration info;
  info.iteration = iteration;
  info.step = step.lambda;
  info.critical_step = step.critical;
  info.limiting_face = step.limiting;
  info.d_area = d_area;
  info.backtracks = step.halvings;
  info.flips = step.flips;
  info.seconds = seconds;
  if(opt.record_history || opt.callback) info.residual = residual();
  if(opt.record_history) out.history.push_back(info);
  return !(opt.callback && !opt.callback(info));
}

/// Runs the flow of `policy` (doc/design.md, "The flow driver"):
///
/// - `start(out)`: measures the start; false if it cannot be flowed;
/// - `converged()`: the targets are reached;
/// - `direction(out)`: the descent direction (assembly, factorisation, solve);
/// - `bound(step)`: the smallest critical root along it, and its face;
/// - `search(step, out)`: the step, certified by the exact predicate;
/// - `commit(step, out)`: moves to the accepted trial, then flips or sweeps;
/// - `d_area()`, `residual()`: of the current iterate, for the record;
/// - `stopping()`, `progress()`, `on_plateau()`: the stop tests, the value
///   they watch, and whether a plateau ends the flow or a phase;
/// - `finish(out)`: the final iterate, metrics and triangulation.
template <class Policy>
Flow_outcome run_flow(Policy& policy, const Discrete_lie_flow_options& opt)
{
  typedef std::chrono::steady_clock Clock;
  typedef Discrete_lie_flow_stop_reason R;
  const Clock::time_point start = Clock::now();
  Flow_outcome out;
  if(!policy.start(out)) {
    out.stop_reason = R::STALLED;
    return out;
  }
  out.stop_reason = policy.converged() ? R::CONVERGED : R::ITERATION_CAP;
  for(std::size_t it = 1; it <= opt.max_iterations && out.stop_reason == R::ITERATION_CAP; ++it) {
    const Direction_status direction = policy.direction(out);
    if(direction == Direction_status::NO_DESCENT) { out.stop_reason = R::CONVERGED; break; }
    if(direction == Direction_status::SOLVER_FAILED) {
      out.solver_failed = true;
      out.stop_reason = R::STALLED;
      break;
    }
    Flow_step step;
    {
      Scoped_timer timer(out.seconds_step);
      policy.bound(step);
      policy.search(step, out);
      if(step.accepted) policy.commit(step, out);
    }
    if(!step.accepted) { out.stop_reason = step.collapsed ? R::COLLAPSED : R::STALLED; break; }
    out.iterations = it;
    if(!record_iteration(opt, it, step, policy.d_area(), std::chrono::duration<double>(Clock::now() - start).count(),
                         [&] { return policy.residual(); }, out)) {
      out.stop_reason = R::INTERRUPTED;
      break;
    }
    if(policy.converged()) { out.stop_reason = R::CONVERGED; break; }
    out.stop_reason = policy.stopping().after(step, policy.progress());
    if(out.stop_reason == R::PLATEAU && !policy.on_plateau()) out.stop_reason = R::ITERATION_CAP;
  }
  policy.finish(out);
  return out;
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
