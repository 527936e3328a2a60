// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The paper's flow (Algorithm 1): Delaunay flips of the flowing domain mesh,
// Neumann Poisson solve L h = A_Ω − A_M with the cotangent stiffness of the
// flowing mesh, area-weighted vertex gradients, boundary sliding, and the
// adaptive step below the smallest critical root, certified on the flowing
// triangulation by exact predicates plus a degeneracy guard.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_PAPER_FLOW_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_PAPER_FLOW_H

#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/certified_flow.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/edge_flips.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// Per-vertex density, the area-weighted mean of the incident faces'
/// ρ = target / area_M, used to weigh triangles created by flips.
inline std::vector<double> vertex_density(const Disk_problem& P)
{
  std::vector<double> num(P.xyz.size(), 0.), den(P.xyz.size(), 0.);
  for(std::size_t f = 0; f < P.faces.size(); ++f) {
    const Face& t = P.faces[f];
    const double a = triangle_area_3(P.xyz[t[0]], P.xyz[t[1]], P.xyz[t[2]]);
    for(int k = 0; k < 3; ++k) { num[t[k]] += P.target[f]; den[t[k]] += a; }
  }
  for(std::size_t v = 0; v < num.size(); ++v) num[v] = den[v] > 0 ? num[v] / den[v] : 1.;
  return num;
}

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
  /// 130 iterations. The tails of lion-head, mannequin-devil and blob shrink
  /// it by 5–15% per 20 iterations from D_area ≈ 2.02–2.06 on, and ran to
  /// 159–209 iterations for the last thousandths. The window is long because
  /// the best iterate improves in steps between flat stretches.
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

/// Runs the paper's flow from the positively oriented `uv`. On return, `uv`
/// is the best iterate (lowest D_area on its Delaunay flowing triangulation)
/// and `flowing` that triangulation; the reported D_area and stop reason are
/// those of the returned map.
template <class EigenSolver>
Flow_outcome paper_disk_flow(const Disk_problem& P, std::vector<Vec2>& uv, Boundary_curve& curve,
                             const Discrete_lie_flow_options& opt, EigenSolver& eigen_solver,
                             std::vector<Face>& flowing,
                             const Paper_flow_settings& settings = Paper_flow_settings())
{
  typedef std::chrono::steady_clock Clock;
  const Clock::time_point start = Clock::now();
  Flow_outcome out;
  const std::size_t n = uv.size();
  const double mu = opt.mu > 0 ? opt.mu : 0.8;
  Planar_dofs dofs(n, P.boundary, curve);
  Pattern_reusing_solver<EigenSolver> solver(eigen_solver);
  Flip_triangulation tri(P.faces);

  // Targets of the flowing faces: the input's as long as a face is unchanged,
  // ρ × the 3D triangle between its vertices once a flip created it.
  const std::vector<double> rho = vertex_density(P);
  std::vector<double> target = P.target;
  const double min_target = *std::min_element(P.target.begin(), P.target.end());
  auto target_of = [&](const Face& t) {
    const double a = triangle_area_3(P.xyz[t[0]], P.xyz[t[1]], P.xyz[t[2]]) * (rho[t[0]] + rho[t[1]] + rho[t[2]]) / 3;
    return (std::max)(a, 1e-3 * min_target); // guard flat 3D triangles
  };
  auto retarget = [&](int f) { target[std::size_t(f)] = target_of(tri.faces[std::size_t(f)]); };
  auto make_delaunay = [&]() -> std::size_t {
    if(!opt.delaunay_flips) return 0;
    const std::size_t flips = tri.make_delaunay(uv, [&](int f) { retarget(f); }, 100 * tri.faces.size() + 100);
    out.flips += flips;
    return flips;
  };
  std::vector<double> literal_AM;
  lump_on_vertices(n, P.faces, P.target, literal_AM);

  std::vector<double> u, AO, AM, u_trial;
  signed_areas_2(uv, tri.faces, u);
  out.initial_d_area = d_area_of(u, target);
  // Every iterate is measured on its own Delaunay triangulation, the one the
  // next solve uses and the one returned with it.
  if(make_delaunay() > 0) signed_areas_2(uv, tri.faces, u);
  double d_area = d_area_of(u, target);
  std::vector<Vec2> best_uv = uv, trial, best_trial;
  std::vector<Face> best_faces = tri.faces;
  std::vector<double> best_target = target;
  double best = d_area;
  std::vector<double> best_history(1, best);
  std::vector<Vec2> basis(std::size_t(dofs.size)), vel(n);
  int last_limiting = -1;
  std::size_t same_limiting = 0;

  // A trial position is admissible when every flowing face is positive and
  // none collapses below the degeneracy guard (in doubles; the exact check
  // follows); returns its D_area, +∞ if not admissible.
  auto admissible_d_area = [&](double lambda, const Eigen::VectorXd& d) {
    if(!planar_trial(uv, dofs, basis, d, lambda, curve, trial)) return std::numeric_limits<double>::infinity();
    signed_areas_2(trial, tri.faces, u_trial);
    double U = 0, T = 0;
    for(std::size_t t = 0; t < u_trial.size(); ++t) {
      if(!(u_trial[t] > 0)) return std::numeric_limits<double>::infinity();
      U += u_trial[t]; T += target[t];
    }
    for(std::size_t t = 0; t < u_trial.size(); ++t)
      if((u_trial[t] / U) < opt.degeneracy_ratio * (target[t] / T)) return std::numeric_limits<double>::infinity();
    return d_area_of(u_trial, target);
  };
  auto certified = [&]() {
    if(count_orientations_2(trial, tri.faces, true).all_positive()) return true;
    ++out.rejected_by_exact_check;
    return false;
  };

  out.stop_reason = Discrete_lie_flow_stop_reason::ITERATION_CAP;
  for(std::size_t it = 1; it <= opt.max_iterations; ++it) {
    if(best - 2 <= opt.tolerance) { out.stop_reason = Discrete_lie_flow_stop_reason::CONVERGED; break; }

    // Area elements and the Neumann Poisson problem L h = A_Ω − A_M.
    lump_on_vertices(n, tri.faces, u, AO);
    if(opt.lump_targets_on_flowing_faces) lump_on_vertices(n, tri.faces, target, AM);
    else AM = literal_AM;
    double so = 0, sm = 0;
    for(std::size_t i = 0; i < n; ++i) { so += AO[i]; sm += AM[i]; }
    Eigen::VectorXd rhs(Eigen::Index(n - 1));
    for(std::size_t i = 1; i < n; ++i) rhs[Eigen::Index(i - 1)] = AO[i] - AM[i] * so / sm;
    const Sparse_matrix L = cotangent_stiffness(uv, tri.faces);
    // Pin h_0 = 0: drop row and column 0 (the right-hand side sums to zero).
    const Sparse_matrix Lr = L.bottomRightCorner(Eigen::Index(n - 1), Eigen::Index(n - 1));
    Eigen::VectorXd h_red;
    ++out.factorizations;
    if(!solver.factorize(Lr) || !solver.solve(rhs, h_red)) {
      out.solver_failed = true;
      out.stop_reason = Discrete_lie_flow_stop_reason::STALLED;
      break;
    }
    std::vector<double> h(n, 0.);
    for(std::size_t i = 1; i < n; ++i) h[i] = h_red[Eigen::Index(i - 1)];

    // Vertex gradients: area-weighted mean of the faces' constant gradients.
    std::vector<Vec2> grad(n, Vec2{{ 0, 0 }});
    std::vector<double> wsum(n, 0.);
    for(std::size_t t = 0; t < tri.faces.size(); ++t) {
      const Face& f = tri.faces[t];
      const Vec2 gt = p1_gradient(uv[f[0]], uv[f[1]], uv[f[2]], h[f[0]], h[f[1]], h[f[2]]);
      for(int k = 0; k < 3; ++k) {
        grad[f[k]][0] += u[t] * gt[0];
        grad[f[k]][1] += u[t] * gt[1];
        wsum[f[k]] += u[t];
      }
    }
    // Displacement in dof form: boundary vertices keep the tangential part.
    Eigen::VectorXd d(dofs.size);
    for(std::size_t v = 0; v < n; ++v)
      for(int j = 0; j < dofs.count[v]; ++j) {
        const int a = dofs.first[v] + j;
        basis[std::size_t(a)] = dofs.basis(int(v), j, curve);
        d[a] = (grad[v][0] * basis[a][0] + grad[v][1] * basis[a][1]) / wsum[v];
      }
    planar_velocity(n, dofs, basis, d, vel);
    if(opt.fixed_step <= 0 && settings.guard_rounds > 0)
      guard_collapses(uv, tri.faces, u, target, dofs, basis, settings, d, vel);
    int limiting = -1;
    const double lambda_crit = smallest_critical_step(uv, tri.faces, vel, limiting);
    double lambda = opt.fixed_step > 0 ? opt.fixed_step : (std::min)(opt.step_cap, mu * lambda_crit);

    bool accepted = false;
    std::size_t halvings = 0;
    if(opt.fixed_step <= 0 && settings.line_search > 0) {
      // Line search: the lowest D_area among samples below the critical
      // bound, certified in increasing order of D_area.
      std::vector<std::pair<double, double> > samples; // (D_area, λ)
      // A μ given by the caller bounds the samples instead of 0.95.
      const double upper = opt.mu > 0 ? opt.mu : settings.line_search_upper;
      double l = (std::min)(settings.line_search_cap * opt.step_cap, upper * lambda_crit);
      for(std::size_t k = 0; k < settings.line_search; ++k, l *= std::sqrt(0.5)) {
        const double e = admissible_d_area(l, d);
        if(std::isfinite(e)) samples.emplace_back(e, l);
      }
      std::sort(samples.begin(), samples.end());
      for(const auto& s : samples) {
        admissible_d_area(s.second, d);
        if(certified()) { lambda = s.second; accepted = true; break; }
      }
      if(!accepted && !samples.empty()) lambda = samples.back().second * 0.5;
    }
    // Shrink until every flowing face is positive (exact) and none collapses.
    for(; !accepted && halvings <= opt.max_backtracks; ++halvings, lambda *= 0.5) {
      if(!std::isfinite(admissible_d_area(lambda, d))) continue;
      if(!certified()) continue;
      accepted = true;
      break;
    }
    // A fixed step that would fold is the paper's "collapse".
    if(!accepted || (opt.fixed_step > 0 && halvings > 0)) {
      out.stop_reason = Discrete_lie_flow_stop_reason::STALLED;
      break;
    }
    for(std::size_t v = 0; v < n; ++v)
      if(dofs.boundary_of[v] >= 0 && dofs.count[v] > 0) curve.commit(std::size_t(dofs.boundary_of[v]), lambda * d[dofs.first[v]]);
    uv.swap(trial);
    const std::size_t flips = make_delaunay();
    signed_areas_2(uv, tri.faces, u);
    d_area = d_area_of(u, target);
    out.iterations = it;
    if(d_area < best) { best = d_area; best_uv = uv; best_faces = tri.faces; best_target = target; }
    best_history.push_back(best);

    if(!record_iteration(opt, it, lambda, lambda_crit, limiting, d_area, halvings, flips,
                         std::chrono::duration<double>(Clock::now() - start).count(),
                         [&] { return area_residual(n, tri.faces, u, target); }, out))
      break;

    if(best - 2 <= opt.tolerance) { out.stop_reason = Discrete_lie_flow_stop_reason::CONVERGED; break; }
    // Stall: the same triangle limits the step again and again while the
    // step is far below the cap (a vertex driven onto an edge).
    if(limiting == last_limiting && lambda < 1e-3 * opt.step_cap) ++same_limiting; else same_limiting = 0;
    last_limiting = limiting;
    if(same_limiting >= opt.stall_window) { out.stop_reason = Discrete_lie_flow_stop_reason::STALLED; break; }
    // A plateau tolerance of 0 turns both plateau tests off (the paper's Table 2).
    if(opt.plateau_tolerance > 0 && best_history.size() > opt.plateau_window) {
      const double old = best_history[best_history.size() - 1 - opt.plateau_window];
      if(old - best < (std::max)(opt.plateau_tolerance, settings.plateau_tolerance) * (best - 1)) { out.stop_reason = Discrete_lie_flow_stop_reason::PLATEAU; break; }
    }
    if(opt.plateau_tolerance > 0 && settings.tail_rate > 0 && best_history.size() > settings.tail_window) {
      const double old = best_history[best_history.size() - 1 - settings.tail_window];
      if(old - best < settings.tail_rate * (best - 2)) { out.stop_reason = Discrete_lie_flow_stop_reason::PLATEAU; break; }
    }
  }
  uv = best_uv;
  flowing = best_faces;
  signed_areas_2(uv, flowing, u);
  out.final_d_area = d_area_of(u, best_target);
  out.final_residual = area_residual(n, flowing, u, best_target);
  out.symbolic_analyses = solver.analyses();
  return out;
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
