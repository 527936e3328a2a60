// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The certified volumetric flow: D_vol, the barrier energy of the tets'
// volume ratios, descended along a regularised Gauss–Newton direction (the
// interior vertices move freely, the border vertices slide on the unit
// sphere), every step bounded by the tets' critical cubics and certified by
// the exact predicate. Volume_energy's regularised denominator
// χ_ε(u) = (u + √(ε² + u²))/2 (Garanzha et al.) serves the untangling of the
// start (volume_untangle.h); the flow itself runs at ε = 0. The unknowns and
// their blocks are in volume_dofs.h, the conjugate gradients' coarse level
// in volume_coarse_level.h, the tets' cubics in volume_geometry.h.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_VOLUME_FLOW_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_VOLUME_FLOW_H

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_report.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_volume_options.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/certification.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/default_solver.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/flow/flow_driver.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/morton_order.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/parallel_ranges.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/solver_threads.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/volume/volume_coarse_level.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/volume/volume_dofs.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/volume/volume_geometry.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/volume/volume_mesh.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// One iteration of a volumetric flow, as callbacks and histories see it.
typedef Discrete_lie_flow_volume_iteration Volume_iteration;

/// The density levels a flow holds to their shares besides D_vol
/// (set_volume_levels(), volume_run.h): the level (0, 1, ...) of every tet
/// (empty: none) and every level's prescribed share of the volume.
struct Volume_share_levels
{
  std::vector<int> level;
  std::vector<double> share;
};

// The flows' fixed settings, not options: the relative residual of the
// inexact Gauss–Newton solve (the floor of the forcing term, the whole
// tolerance without it), the forcing term's upper bound, and the plateau
// rule: stop when (E_prev − E)/(E − 2) stays below `volume_plateau` for
// `volume_plateau_window` iterations in a row (`Flow_stopping::plateau_in_a_row()`).
const double volume_cg_tolerance = 1e-3;
const double volume_cg_forcing_max = 0.5;
const double volume_plateau = 1e-4;
const std::size_t volume_plateau_window = 8;

/// The largest relative error of the levels' shares, |achieved/prescribed − 1|;
/// `achieved` receives the achieved shares.
inline double level_share_error(const Volume_share_levels& levels, const std::vector<double>& u,
                                std::vector<double>* achieved = nullptr)
{
  const std::vector<int>& level = levels.level;
  const std::vector<double>& prescribed = levels.share;
  if(level.empty()) return 0;
  std::vector<double> a(prescribed.size(), 0.);
  double A = 0;
  for(std::size_t t = 0; t < u.size(); ++t) { a[std::size_t(level[t])] += u[t]; A += u[t]; }
  double e = 0;
  for(std::size_t k = 0; k < a.size(); ++k) {
    a[k] /= A;
    if(prescribed[k] > 0) e = (std::max)(e, std::abs(a[k] / prescribed[k] - 1));
  }
  if(achieved) achieved->swap(a);
  return e;
}

/// The driver's options of a volumetric flow, the same for both policies:
/// the options' cap and μ, and a callback that turns the driver's record
/// into the volumetric one for `history` and the options' callback.
/// `tet_of(face)`: the caller's tet of the driver's limiting face (−1 for
/// none); `cg_of()`: the iteration's conjugate-gradient steps.
template <class TetOf, class CgOf>
Discrete_lie_flow_options volume_driver_options(const Discrete_lie_flow_volume_options& O,
                                                std::vector<Volume_iteration>* history, TetOf tet_of, CgOf cg_of)
{
  Discrete_lie_flow_options opt;
  opt.max_iterations = O.max_iterations;
  opt.mu = O.mu;
  if(history || O.callback)
    opt.callback = [&O, history, tet_of, cg_of](const Discrete_lie_flow_iteration& info) {
      Volume_iteration I;
      I.iteration = info.iteration;
      I.step = info.step;
      I.critical_step = info.critical_step;
      I.limiting_tet = tet_of(info.limiting_face);
      I.d_vol = info.d_area;
      I.cg_iterations = cg_of();
      I.seconds = info.seconds;
      if(history) history->push_back(I);
      return !(O.callback && !O.callback(I));
    };
  return opt;
}

/// The engine's outcome.
struct Volume_flow_outcome
{
  Discrete_lie_flow_stop_reason stop_reason = Discrete_lie_flow_stop_reason::NOT_RUN;
  std::size_t iterations = 0;
  std::size_t rejected_by_exact_check = 0;
  std::size_t cg_iterations = 0;
  double energy = 0;
};

/// Runs the volumetric policy `flow` by `run_flow()`: the driver's counts,
/// the policy's conjugate-gradient steps and final D_vol.
template <class Policy>
Volume_flow_outcome run_volume_policy(Policy& flow, const Discrete_lie_flow_options& opt)
{
  const Flow_outcome o = run_flow(flow, opt);
  Volume_flow_outcome out;
  out.stop_reason = o.stop_reason;
  out.iterations = o.iterations;
  out.rejected_by_exact_check = o.rejected_by_exact_check;
  out.cg_iterations = flow.cg_iterations();
  out.energy = flow.energy();
  return out;
}

/// The energy E = 1 + U Σ_t c_t / χ(u_t), c_t = (target_t / Σ target)², U = Σ u_t;
/// with χ(u) = u it is D_vol = Σ w_t (r_t + 1/r_t), w_t = target_t / Σ target,
/// r_t = (u_t/U)/w_t, whose minimum 2 is reached when every tet has its share.
class Volume_energy
{
public:
  /// `sum_order` (empty: 0, 1, ...): the order in which the sums over the
  /// tets visit them, so that a renumbered copy of a mesh gets the very
  /// values of the original (locality_order()).
  explicit Volume_energy(const std::vector<double>& target, std::vector<int> sum_order = std::vector<int>())
    : m_c(target.size()), m_order(std::move(sum_order))
  {
    double T = 0;
    for(std::size_t o = 0; o < target.size(); ++o) T += target[at(o)];
    for(std::size_t t = 0; t < target.size(); ++t) m_c[t] = (target[t] / T) * (target[t] / T);
  }
  static double chi(double u, double eps) { return eps > 0 ? 0.5 * (u + std::sqrt(eps * eps + u * u)) : u; }
  static double dchi(double u, double eps) { return eps > 0 ? 0.5 * (1 + u / std::sqrt(eps * eps + u * u)) : 1.; }

  /// E(u); +∞ when ε = 0 and a tet is not positive.
  double value(const std::vector<double>& u, double eps) const
  {
    double U = 0, K = 0;
    for(std::size_t o = 0; o < u.size(); ++o) {
      const std::size_t t = at(o);
      const double x = chi(u[t], eps);
      if(!(x > 0)) return std::numeric_limits<double>::infinity();
      U += u[t];
      K += m_c[t] / x;
    }
    return U > 0 ? 1 + U * K : std::numeric_limits<double>::infinity();
  }
  /// ∂E/∂u_t and the Gauss–Newton curvature 2 U c_t χ′² / χ³ of every tet.
  void derivatives(const std::vector<double>& u, double eps, std::vector<double>& dE, std::vector<double>& w) const
  {
    double U = 0, K = 0;
    for(std::size_t o = 0; o < u.size(); ++o) { const std::size_t t = at(o); U += u[t]; K += m_c[t] / chi(u[t], eps); }
    dE.resize(u.size());
    w.resize(u.size());
    for(std::size_t t = 0; t < u.size(); ++t) {
      const double x = chi(u[t], eps), dx = dchi(u[t], eps);
      dE[t] = K - U * m_c[t] * dx / (x * x);
      w[t] = 2 * U * m_c[t] * dx * dx / (x * x * x);
    }
  }
private:
  std::size_t at(std::size_t o) const { return m_order.empty() ? o : std::size_t(m_order[o]); }
  std::vector<double> m_c;
  std::vector<int> m_order;
};

/// The certified volumetric flow as a policy of `run_flow()` (flow_driver.h;
/// doc/design.md, "The flow driver"). `x` (every tet positive by the exact
/// predicate, border points on the unit sphere) is moved in place;
/// `sum_order` orders the energy's sums (Volume_energy). Of the options it
/// reads the tolerances, μ, the conjugate gradients' settings,
/// `cholesky_every`, `threads` and `star_shaped_border` (the cap and the
/// callback through volume_driver_options()); the rest is the run's.
class Volume_certified_flow : public Flow_policy_base
{
public:
  Volume_certified_flow(std::vector<Vec3>& x, const std::vector<Tet>& tets, const std::vector<char>& on_border,
                        const std::vector<std::array<int, 3> >& border_faces, const std::vector<double>& target,
                        const Discrete_lie_flow_volume_options& O, const Volume_share_levels& levels,
                        std::vector<int> sum_order = std::vector<int>())
    : Flow_policy_base(Flow_stopping::plateau_in_a_row(volume_plateau_window, volume_plateau)), m_x(x), m_tets(tets),
      m_on_border(on_border), m_border_faces(border_faces), m_O(O), m_levels(levels),
      m_energy(target, std::move(sum_order)),
      m_dofs(on_border, false), m_grad(tets.size()), m_gv(x.size()), m_x_trial(x.size()), m_M(x.size()),
      m_threads(volume_flow_threads(O.threads, tets.size())), m_coarse(O.coarse_aggregate)
  {
    // Every vertex's corners (4t + j), in increasing t: the per-vertex sums
    // then add the tets' terms in one order whatever the number of threads.
    m_corner_start.assign(x.size() + 1, 0);
    for(const Tet& k : tets)
      for(int j = 0; j < 4; ++j) ++m_corner_start[std::size_t(k[std::size_t(j)]) + 1];
    for(std::size_t v = 0; v < x.size(); ++v) m_corner_start[v + 1] += m_corner_start[v];
    m_corners.resize(4 * tets.size());
    std::vector<std::size_t> next(m_corner_start.begin(), m_corner_start.end() - 1);
    for(std::size_t t = 0; t < tets.size(); ++t)
      for(int j = 0; j < 4; ++j) m_corners[next[std::size_t(tets[t][std::size_t(j)])]++] = int(4 * t + std::size_t(j));
  }

  double progress() const { return m_E; }
  double d_area() const { return m_E; }  // the record's value: D_vol
  double residual() const { return 0; }  // not part of the volumetric record
  double energy() const { return m_E; }
  std::size_t cg_iterations() const { return m_cg_total; }
  std::size_t last_cg_iterations() const { return m_cg; }

  int threads() const { return m_threads; }

  /// For tests, after direction(): the coarse matrix times ec, and
  /// Pᵀ H P ec by the matrix-free product (equal up to rounding when the
  /// coarse assembly is right); false without a coarse level.
  bool coarse_products(const Eigen::VectorXd& ec, Eigen::VectorXd& by_matrix, Eigen::VectorXd& by_products)
  {
    if(m_coarse.aggregates() == 0 || ec.size() != Eigen::Index(3 * m_coarse.aggregates())) return false;
    by_matrix = m_coarse.product(ec);
    Eigen::VectorXd s = Eigen::VectorXd::Zero(m_dofs.size()), hs;
    m_coarse.prolong_add(m_dofs, ec, s, m_threads);
    apply(s, hs);
    m_coarse.restrict(m_dofs, hs, by_products, m_threads);
    return true;
  }
  std::size_t aggregates() const { return m_coarse.aggregates(); }
  /// The coarse matrix's last factorisation succeeded.
  bool coarse_factorized() const { return m_coarse.ok(); }

  bool start(Flow_outcome&)
  {
    dets(m_x, m_u);
    m_E = m_energy.value(m_u, 0);
    m_stopping.restart(m_E);
    return std::isfinite(m_E);
  }

  bool converged() const
  {
    return m_E - 2 <= m_O.tolerance && level_share_error(m_levels, m_u) <= m_O.share_tolerance;
  }

  /// The gradient and the Gauss–Newton blocks, then the inexact solve.
  Direction_status direction(Flow_outcome& out)
  {
    {
      Scoped_timer timer(out.seconds_assembly);
      assemble();
    }
    if(m_O.cg_forcing) forcing();
    Scoped_timer timer(out.seconds_solve);
    solve();
    return Direction_status::DESCENT;
  }

  /// Step bound: the critical cubic of every tet (and with a star-shaped
  /// border of every border triangle seen from the centre), and no vertex
  /// moving by more than a tenth of the ball's radius.
  void bound(Flow_step& step)
  {
    // Per range the first smallest root; the ranges in order keep the first
    // tet of the smallest root whatever the number of threads.
    std::vector<double> range_crit(std::size_t(m_threads), infinite_step());
    std::vector<int> range_limiting(std::size_t(m_threads), -1);
    parallel_ranges(m_tets.size(), m_threads, [&](std::size_t begin, std::size_t end, std::size_t range) {
      double crit = infinite_step();
      int limiting = -1;
      for(std::size_t t = begin; t < end; ++t) {
        const Tet& k = m_tets[t];
        const std::size_t a = std::size_t(k[0]), b = std::size_t(k[1]), c = std::size_t(k[2]), e = std::size_t(k[3]);
        const double r = critical_step_tet(m_x[a], m_x[b], m_x[c], m_x[e], m_d[a], m_d[b], m_d[c], m_d[e]);
        if(r < crit) { crit = r; limiting = int(t); }
      }
      range_crit[range] = crit;
      range_limiting[range] = limiting;
    });
    double crit = infinite_step();
    int limiting = -1;
    for(std::size_t r = 0; r < range_crit.size(); ++r)
      if(range_crit[r] < crit) { crit = range_crit[r]; limiting = range_limiting[r]; }
    // Re-normalising the points scales them by positive factors: the sign
    // of det[a, b, c] is kept.
    if(m_O.star_shaped_border)
      for(const auto& f : m_border_faces) {
        const std::size_t a = std::size_t(f[0]), b = std::size_t(f[1]), c = std::size_t(f[2]);
        crit = (std::min)(crit, critical_step_sphere(m_x[a], m_x[b], m_x[c], m_d[a], m_d[b], m_d[c]));
      }
    double dmax = 0;
    for(const Vec3& e : m_d) dmax = (std::max)(dmax, norm3(e));
    step.critical = crit;
    step.limiting = limiting;
    step.lambda = (std::min)((std::min)(1., m_O.mu * crit), dmax > 0 ? 0.1 / dmax : 1.);
  }

  /// Halves the step until the energy drops and the exact predicate finds
  /// every tet positive; when no step is accepted, the direction is solved
  /// again with 10 times the damping (more gradient-like), up to 1e6.
  void search(Flow_step& step, Flow_outcome& out)
  {
    for(;;) {
      for(step.halvings = 0; step.halvings < 40 && step.lambda > 0; ++step.halvings, step.lambda *= 0.5) {
        const double lambda = step.lambda;
        parallel_ranges(m_x.size(), m_threads, [&](std::size_t begin, std::size_t end, std::size_t) {
          for(std::size_t v = begin; v < end; ++v) {
            const Vec3 y = {{ m_x[v][0] + lambda * m_d[v][0], m_x[v][1] + lambda * m_d[v][1],
                              m_x[v][2] + lambda * m_d[v][2] }};
            m_x_trial[v] = m_on_border[v] ? normalized(y) : y;
          }
        });
        dets(m_x_trial, m_u_trial);
        m_E_trial = m_energy.value(m_u_trial, 0);
        if(!(m_E_trial < m_E)) continue;
        if(take_forced_trial_refusal() || !all_positive(m_x_trial) ||
           (m_O.star_shaped_border && count_bad_border_faces(m_x_trial, m_border_faces) != 0)) {
          ++out.rejected_by_exact_check;
          continue;
        }
        step.accepted = true;
        return;
      }
      if(!(m_lambda < 1e6)) return; // stalled
      m_lambda *= 10;
      ++m_pass;
      solve();
      bound(step);
    }
  }

  /// A short step: the quadratic model is poor there; lean towards the
  /// (preconditioned) gradient.
  void commit(const Flow_step& step, Flow_outcome&)
  {
    m_lambda = step.lambda >= 1 ? (std::max)(m_lambda / 3, 1e-8) : (std::min)(m_lambda * (step.lambda < 0.1 ? 10 : 2), 1e6);
    m_x.swap(m_x_trial);
    m_u.swap(m_u_trial);
    m_E = m_E_trial;
    ++m_pass;
  }

  void finish(Flow_outcome&) {}

private:
  void assemble()
  {
    m_dofs.update_frames(m_x);
    m_energy.derivatives(m_u, 0, m_dE, m_w);
    parallel_ranges(m_tets.size(), m_threads, [&](std::size_t begin, std::size_t end, std::size_t) {
      for(std::size_t t = begin; t < end; ++t) {
        const Tet& k = m_tets[t];
        const Vec3& a = m_x[std::size_t(k[0])];
        const Vec3 e1 = sub(m_x[std::size_t(k[1])], a), e2 = sub(m_x[std::size_t(k[2])], a), e3 = sub(m_x[std::size_t(k[3])], a);
        std::array<Vec3, 4>& G = m_grad[t]; // ∂(6u)/∂x_k
        G[1] = cross(e2, e3);
        G[2] = cross(e3, e1);
        G[3] = cross(e1, e2);
        for(int c = 0; c < 3; ++c) G[0][std::size_t(c)] = -(G[1][std::size_t(c)] + G[2][std::size_t(c)] + G[3][std::size_t(c)]);
      }
    });
    // Gathered per vertex over its corners in increasing t.
    parallel_ranges(m_x.size(), m_threads, [&](std::size_t begin, std::size_t end, std::size_t) {
      for(std::size_t v = begin; v < end; ++v) {
        Vec3 acc = {{ 0, 0, 0 }};
        std::array<double, 6> m = {{ 0, 0, 0, 0, 0, 0 }};
        for(std::size_t i = m_corner_start[v]; i < m_corner_start[v + 1]; ++i) {
          const std::size_t t = std::size_t(m_corners[i]) / 4;
          const Vec3& h = m_grad[t][std::size_t(m_corners[i]) % 4];
          const double w = m_w[t];
          for(int c = 0; c < 3; ++c) acc[std::size_t(c)] += m_dE[t] * h[std::size_t(c)];
          m[0] += w * h[0] * h[0]; m[1] += w * h[1] * h[1]; m[2] += w * h[2] * h[2];
          m[3] += w * h[0] * h[1]; m[4] += w * h[0] * h[2]; m[5] += w * h[1] * h[2];
        }
        m_gv[v] = acc;
        m_M[v] = m;
      }
    });
    m_dofs.restrict(m_gv, m_g);
  }

  /// H s = Σ_t w_t G_t (G_t · s) + λ·diag (matrix-free).
  void apply(const Eigen::VectorXd& in, Eigen::VectorXd& y)
  {
    m_dofs.expand(in, m_d);
    m_hv.resize(m_x.size());
    m_yt.resize(m_tets.size());
    parallel_ranges(m_tets.size(), m_threads, [&](std::size_t begin, std::size_t end, std::size_t) {
      for(std::size_t t = begin; t < end; ++t) {
        const Tet& k = m_tets[t];
        const std::array<Vec3, 4>& G = m_grad[t];
        double y_t = 0;
        for(int j = 0; j < 4; ++j) y_t += dot(G[std::size_t(j)], m_d[std::size_t(k[std::size_t(j)])]);
        m_yt[t] = y_t * m_w[t];
      }
    });
    parallel_ranges(m_x.size(), m_threads, [&](std::size_t begin, std::size_t end, std::size_t) {
      for(std::size_t v = begin; v < end; ++v) {
        Vec3 o = {{ 0, 0, 0 }};
        for(std::size_t i = m_corner_start[v]; i < m_corner_start[v + 1]; ++i) {
          const std::size_t t = std::size_t(m_corners[i]) / 4;
          const Vec3& h = m_grad[t][std::size_t(m_corners[i]) % 4];
          const double y_t = m_yt[t];
          o[0] += y_t * h[0]; o[1] += y_t * h[1]; o[2] += y_t * h[2];
        }
        m_hv[v] = o;
      }
    });
    m_dofs.restrict(m_hv, y);
    m_dofs.apply_regularization(m_M, m_lambda, in, y);
  }

  /// Six times the tets' signed volumes at `x` (doubles).
  void dets(const std::vector<Vec3>& x, std::vector<double>& u) const
  {
    u.resize(m_tets.size());
    parallel_ranges(m_tets.size(), m_threads, [&](std::size_t begin, std::size_t end, std::size_t) {
      for(std::size_t t = begin; t < end; ++t) {
        const Tet& k = m_tets[t];
        u[t] = tet_det(x[std::size_t(k[0])], x[std::size_t(k[1])], x[std::size_t(k[2])], x[std::size_t(k[3])]);
      }
    });
  }

  /// Every tet positive at `x` by the exact predicate.
  bool all_positive(const std::vector<Vec3>& x) const
  {
    std::vector<char> bad(std::size_t(m_threads), 0);
    parallel_ranges(m_tets.size(), m_threads, [&](std::size_t begin, std::size_t end, std::size_t range) {
      for(std::size_t t = begin; t < end && !bad[range]; ++t) {
        const Tet& k = m_tets[t];
        if(exact_tet_orientation(x[std::size_t(k[0])], x[std::size_t(k[1])], x[std::size_t(k[2])],
                                 x[std::size_t(k[3])]) != POSITIVE)
          bad[range] = 1;
      }
    });
    for(char b : bad) if(b) return false;
    return true;
  }

  /// The Gauss–Newton matrix, lower triangle: per tet w_t (P G_a)(P G_b)ᵀ
  /// for its corners a, b (P the vertex's dof frame), and the
  /// regularisation of apply_regularization; factorised.
  void factorize()
  {
    m_triplets.clear();
    for(std::size_t t = 0; t < m_tets.size(); ++t) {
      const Tet& k = m_tets[t];
      double c[4][3];
      int m[4], o[4];
      for(int j = 0; j < 4; ++j) {
        m[j] = m_dofs.components(std::size_t(k[std::size_t(j)]), m_grad[t][std::size_t(j)], c[j]);
        o[j] = m_dofs.offset(std::size_t(k[std::size_t(j)]));
      }
      for(int a = 0; a < 4; ++a)
        for(int b = 0; b < 4; ++b)
          for(int i = 0; i < m[a]; ++i)
            for(int l = 0; l < m[b]; ++l)
              if(o[a] + i >= o[b] + l) m_triplets.emplace_back(o[a] + i, o[b] + l, m_w[t] * c[a][i] * c[b][l]);
    }
    for(std::size_t v = 0; v < m_x.size(); ++v) {
      double c[3];
      const int m = m_dofs.components(v, Vec3{{ 0, 0, 0 }}, c);
      const double reg = m_lambda * (m_M[v][0] + m_M[v][1] + m_M[v][2]) / 3;
      for(int i = 0; i < m; ++i) m_triplets.emplace_back(m_dofs.offset(v) + i, m_dofs.offset(v) + i, reg);
    }
    const int n = m_dofs.size();
    m_H.resize(n, n);
    m_H.setFromTriplets(m_triplets.begin(), m_triplets.end());
    if(!m_analyzed) { m_factor.analyzePattern(m_H); m_analyzed = true; }
    m_factor.factorize(m_H);
    m_factored = m_factor.info() == Eigen::Success;
    m_factor_pass = m_pass;
  }

  /// Eisenstat and Walker's choice 2 (γ = 0.9, α = 2) with its safeguard,
  /// between volume_cg_tolerance and volume_cg_forcing_max.
  void forcing()
  {
    const double g = m_g.norm();
    if(m_g_prev > 0) {
      double eta = 0.9 * (g / m_g_prev) * (g / m_g_prev);
      const double safe = 0.9 * m_eta * m_eta;
      if(safe > 0.1) eta = (std::max)(eta, safe);
      m_eta = (std::min)((std::max)(eta, volume_cg_tolerance), volume_cg_forcing_max);
    } else {
      m_eta = volume_cg_forcing_max;
    }
    m_g_prev = g;
  }

  /// Preconditioned conjugate gradients from 0 on the damped Gauss–Newton
  /// system; the direction m_d per vertex.
  void solve()
  {
    m_dofs.block_inverse(m_M, m_lambda, m_Minv);
    if(m_O.cholesky_every > 0 && (m_pass - m_factor_pass >= m_O.cholesky_every || !m_factored)) factorize();
    if(m_O.coarse_aggregate > 0 && !m_factored) m_coarse.factorize(m_tets, m_dofs, m_grad, m_w, m_M, m_lambda);
    // The vector operations in parallel, the dot products per fixed block
    // of vertices (their dofs are contiguous): they do not depend on the
    // number of threads.
    const int n = m_dofs.size();
    const std::size_t V = m_x.size();
    m_s = Eigen::VectorXd::Zero(n);
    m_r = -m_g;
    m_z.resize(n);
    m_p.resize(n);
    auto dofs = [&](std::size_t vb, std::size_t ve) {
      return std::make_pair(Eigen::Index(m_dofs.offset_or_size(vb)), Eigen::Index(m_dofs.offset_or_size(ve)));
    };
    auto each_dof = [&](const auto& f) {
      parallel_ranges(std::size_t(n), m_threads, [&](std::size_t b, std::size_t e, std::size_t) {
        for(std::size_t i = b; i < e; ++i) f(Eigen::Index(i));
      });
    };
    // z = M⁻¹ r; returns (r·z, r·r).
    auto precondition = [&]() {
      if(m_factored) {
        m_z = m_factor.solve(m_r);
      } else {
        parallel_ranges(V, m_threads, [&](std::size_t vb, std::size_t ve, std::size_t) {
          m_dofs.apply_block(m_Minv, m_r, m_z, vb, ve);
        });
        if(m_coarse.ok()) m_coarse.correct(m_dofs, m_r, m_z, m_threads);
      }
      return blocked_sums<2>(V, m_threads, [&](std::size_t vb, std::size_t ve, std::array<double, 2>& a) {
        const auto d = dofs(vb, ve);
        for(Eigen::Index i = d.first; i < d.second; ++i) {
          a[0] += m_r[i] * m_z[i];
          a[1] += m_r[i] * m_r[i];
        }
      });
    };
    std::array<double, 2> sums = precondition();
    m_p = m_z;
    double rz = sums[0], rr = sums[1];
    const double r0 = std::sqrt(rr);
    std::size_t cg = 0;
    const double tolerance = m_O.cg_forcing ? m_eta : volume_cg_tolerance;
    for(; cg < m_O.cg_max_iterations && std::sqrt(rr) > tolerance * r0; ++cg) {
      apply(m_p, m_q);
      const double pq = blocked_sums<1>(V, m_threads, [&](std::size_t vb, std::size_t ve, std::array<double, 1>& a) {
        const auto d = dofs(vb, ve);
        for(Eigen::Index i = d.first; i < d.second; ++i) a[0] += m_p[i] * m_q[i];
      })[0];
      if(!(pq > 0)) break;
      const double alpha = rz / pq;
      each_dof([&](Eigen::Index i) { m_s[i] += alpha * m_p[i]; m_r[i] -= alpha * m_q[i]; });
      sums = precondition();
      const double beta = sums[0] / rz;
      rz = sums[0];
      rr = sums[1];
      each_dof([&](Eigen::Index i) { m_p[i] = m_z[i] + beta * m_p[i]; });
    }
    m_cg = cg;
    m_cg_total += cg;
    // No curvature information: the preconditioned gradient.
    if(cg == 0 || !m_s.allFinite()) m_dofs.apply_block(m_Minv, -m_g, m_s);
    m_dofs.expand(m_s, m_d);
  }

  std::vector<Vec3>& m_x;
  const std::vector<Tet>& m_tets;
  const std::vector<char>& m_on_border;
  const std::vector<std::array<int, 3> >& m_border_faces;
  const Discrete_lie_flow_volume_options& m_O;
  const Volume_share_levels& m_levels;
  Volume_energy m_energy;
  Volume_dofs m_dofs;
  std::vector<double> m_u, m_dE, m_w, m_u_trial;
  std::vector<std::array<Vec3, 4> > m_grad;
  std::vector<Vec3> m_gv, m_d, m_x_trial, m_hv;
  std::vector<double> m_yt; // per tet: w_t (G_t · s), in the product
  std::vector<std::array<double, 6> > m_M;
  std::vector<std::array<double, 9> > m_Minv;
  int m_threads = 1;
  std::vector<std::size_t> m_corner_start; // per vertex, into m_corners
  std::vector<int> m_corners;              // 4t + j: corner j of tet t
  double m_eta = 0.5, m_g_prev = 0;        // the forcing term, the last gradient's norm
  Volume_coarse_level m_coarse; // the two-level preconditioner's coarse space
  Eigen::VectorXd m_g, m_s, m_r, m_z, m_p, m_q;
  double m_E = 0, m_E_trial = 0;
  double m_lambda = 1e-3; // Levenberg–Marquardt damping
  // The Cholesky preconditioner (the pattern does not change between iterations).
  std::vector<Eigen::Triplet<double> > m_triplets;
  Sparse_matrix m_H;
  Default_spd_solver m_factor;
  bool m_analyzed = false, m_factored = false;
  std::size_t m_pass = 0, m_factor_pass = 0; // direction solves so far, and at the last factorisation
  std::size_t m_cg = 0, m_cg_total = 0;
};

/// A renumbering of the vertices along a Morton (Z-order) curve of the
/// points `x`, and of the tets by their first vertex in that order: the
/// flow's passes over tets and vertices then touch memory that lies close
/// together (on Mesh_3's numbering a million tets' products ran about 3
/// times slower). `vertex_to_new[v]` is v's new index, `tet_order[i]` the
/// old index of the new tet i.
inline void locality_order(const std::vector<Vec3>& x, const std::vector<Tet>& tets, std::vector<int>& vertex_to_new,
                           std::vector<int>& tet_order)
{
  const std::vector<std::size_t> order = morton_order(x);
  vertex_to_new.resize(x.size());
  for(std::size_t i = 0; i < order.size(); ++i) vertex_to_new[order[i]] = int(i);
  std::vector<std::pair<int, int> > first(tets.size());
  for(std::size_t t = 0; t < tets.size(); ++t) {
    int m = vertex_to_new[std::size_t(tets[t][0])];
    for(std::size_t j = 1; j < 4; ++j) m = (std::min)(m, vertex_to_new[std::size_t(tets[t][j])]);
    first[t] = std::make_pair(m, int(t));
  }
  std::sort(first.begin(), first.end());
  tet_order.resize(tets.size());
  for(std::size_t i = 0; i < first.size(); ++i) tet_order[i] = first[i].second;
}

/// Runs the flow on positions `x` (border points on the unit sphere) until
/// D_vol − 2 ≤ tolerance (and the levels' shares within theirs), a
/// plateau, a stall or the cap, by `run_flow()`. x must be positive
/// everywhere by the exact predicate; it stays so (and so do the border
/// triangles seen from the centre with `O.star_shaped_border`).
inline Volume_flow_outcome run_volume_flow(std::vector<Vec3>& x, const std::vector<Tet>& tets,
                                           const std::vector<char>& on_border,
                                           const std::vector<std::array<int, 3> >& border_faces,
                                           const std::vector<double>& target,
                                           const Discrete_lie_flow_volume_options& O,
                                           const Volume_share_levels& levels = Volume_share_levels(),
                                           std::vector<Volume_iteration>* history = nullptr)
{
  // The coarse level's factorisations (a few thousand unknowns) gain nothing
  // from BLAS threads, whose spinning between calls takes the cores from
  // the flow's own threads (perf: sched_yield); the whole Gauss–Newton
  // matrix of cholesky_every keeps the automatic setting.
  const Scoped_blas_threads blas(O.cholesky_every > 0 ? 0 : 1, x.size());
  // The flow runs on a renumbered copy (locality_order()); x is written back.
  std::vector<int> to_new, tet_order;
  locality_order(x, tets, to_new, tet_order);
  std::vector<Vec3> xn(x.size());
  std::vector<char> on_border_n(x.size());
  for(std::size_t v = 0; v < x.size(); ++v) {
    xn[std::size_t(to_new[v])] = x[v];
    on_border_n[std::size_t(to_new[v])] = on_border[v];
  }
  std::vector<Tet> tets_n(tets.size());
  std::vector<double> target_n(tets.size());
  Volume_share_levels levels_n = levels;
  for(std::size_t i = 0; i < tets.size(); ++i) {
    const std::size_t t = std::size_t(tet_order[i]);
    for(std::size_t j = 0; j < 4; ++j) tets_n[i][j] = to_new[std::size_t(tets[t][j])];
    target_n[i] = target[t];
    if(!levels.level.empty()) levels_n.level[i] = levels.level[t];
  }
  std::vector<std::array<int, 3> > faces_n(border_faces.size());
  for(std::size_t f = 0; f < border_faces.size(); ++f)
    for(std::size_t j = 0; j < 3; ++j) faces_n[f][j] = to_new[std::size_t(border_faces[f][j])];
  struct Write_back
  {
    std::vector<Vec3>& x; const std::vector<Vec3>& xn; const std::vector<int>& to_new;
    ~Write_back() { for(std::size_t v = 0; v < x.size(); ++v) x[v] = xn[std::size_t(to_new[v])]; }
  } write_back{ x, xn, to_new };
  // The energy's sums in the original order: D_vol the same, bit for bit, as
  // computed on the caller's numbering.
  std::vector<int> sum_order(tets.size());
  for(std::size_t i = 0; i < tets.size(); ++i) sum_order[std::size_t(tet_order[i])] = int(i);
  Volume_certified_flow flow(xn, tets_n, on_border_n, faces_n, target_n, O, levels_n, std::move(sum_order));
  // The driver records the surface flows' iteration; the volumetric one
  // adds the conjugate-gradient steps, its tets in the caller's order.
  const Discrete_lie_flow_options opt = volume_driver_options(
    O, history, [&tet_order](int f) { return f >= 0 ? tet_order[std::size_t(f)] : -1; },
    [&flow] { return flow.last_cg_iterations(); });
  return run_volume_policy(flow, opt);
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
