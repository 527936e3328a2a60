// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The paper's flow on tetrahedral meshes, as far as its formulas reach in 3D
// (its main theorem is dimension-free; its §7.2 leaves tet meshes as future
// work), as a policy of the flow driver: volume elements lumped at the
// vertices, the Poisson solve L h = V_Ω − V_M with the P1 stiffness of the
// current ball-side tets, volume-weighted vertex gradients of h (tangential
// to the sphere on the border, re-normalised after the step), and the
// adaptive step μ·(smallest positive root of the tets' cubics det(p + λv)),
// certified by the exact orientation of every tet. No flips: the paper's
// Delaunay flips have no fixed-connectivity analogue, the map stays on the
// caller's tets; the planar paper mode's collapse guard stands in for them
// where it can (optional; doc/volume.md, "Paper mode").

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_VOLUME_PAPER_FLOW_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_VOLUME_PAPER_FLOW_H

#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/certification.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/default_solver.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/flow/flow_driver.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/solver_threads.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/sparse_solver.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/volume/volume_flow.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/volume/volume_geometry.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/volume/volume_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// ∂(6 vol)/∂x_k of the tet (a, b, c, d) for its four corners k; the
/// gradient of the tet's barycentric coordinate φ_k is G[k] / det.
inline std::array<Vec3, 4> tet_corner_gradients(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d)
{
  const Vec3 e1 = sub(b, a), e2 = sub(c, a), e3 = sub(d, a);
  std::array<Vec3, 4> G;
  G[1] = cross(e2, e3);
  G[2] = cross(e3, e1);
  G[3] = cross(e1, e2);
  for(std::size_t i = 0; i < 3; ++i) G[0][i] = -(G[1][i] + G[2][i] + G[3][i]);
  return G;
}

/// The P1 stiffness (the 3D cotangent Laplacian) of the tets at `x`, by
/// contributions add(i, j, K_t[i][j]): K_t = vol_t ∇φᵀ∇φ, i.e.
/// K_t[j][k] = G_j · G_k / (6 det). Off the diagonal, summed over the tets
/// of an edge ij, this is −(1/6) Σ l_kl cot θ_kl (θ_kl the dihedral angle at
/// the opposite edge kl); both triangles of the symmetric matrix are given.
/// Positive semidefinite, the constants its kernel on a connected mesh of
/// positive tets.
template <class Add>
void volume_stiffness_contributions(const std::vector<Vec3>& x, const std::vector<Tet>& tets, Add&& add)
{
  for(const Tet& k : tets) {
    const Vec3 &a = x[std::size_t(k[0])], &b = x[std::size_t(k[1])], &c = x[std::size_t(k[2])], &d = x[std::size_t(k[3])];
    const std::array<Vec3, 4> G = tet_corner_gradients(a, b, c, d);
    const double s = 1 / (6 * tet_det(a, b, c, d));
    for(std::size_t i = 0; i < 4; ++i)
      for(std::size_t j = 0; j < 4; ++j) add(k[i], k[j], s * dot(G[i], G[j]));
  }
}

/// The P1 stiffness of the tets at `x` as a sparse matrix (n × n, both triangles).
inline Sparse_matrix volume_stiffness(const std::vector<Vec3>& x, const std::vector<Tet>& tets)
{
  std::vector<Eigen::Triplet<double> > trip;
  trip.reserve(16 * tets.size());
  volume_stiffness_contributions(x, tets, [&trip](int i, int j, double v) { trip.emplace_back(i, j, v); });
  Sparse_matrix K(Eigen::Index(x.size()), Eigen::Index(x.size()));
  K.setFromTriplets(trip.begin(), trip.end());
  K.makeCompressed();
  return K;
}

/// Per-tet values lumped to the vertices, a quarter to each corner.
inline void lump_tets_on_vertices(std::size_t n, const std::vector<Tet>& tets, const std::vector<double>& value,
                                  std::vector<double>& lumped)
{
  lumped.assign(n, 0.);
  for(std::size_t t = 0; t < tets.size(); ++t)
    for(int v : tets[t]) lumped[std::size_t(v)] += 0.25 * value[t];
}

/// The paper's volumetric flow as a policy of `run_flow()` (flow_driver.h):
/// `x` (every tet positive by the exact predicate, border points on the
/// unit sphere) is moved in place and holds on return the best iterate
/// (lowest D_vol). Every accepted iterate has every tet positive by the
/// exact predicate (and, with `star_shaped_border`, every border triangle
/// positive seen from the centre). Of the options it reads the tolerances,
/// μ, `star_shaped_border` and `paper_collapse_guard` (the cap and the
/// callback through volume_driver_options()); it has no conjugate gradients
/// and runs on one thread.
class Volume_paper_flow : public Flow_policy_base
{
public:
  Volume_paper_flow(std::vector<Vec3>& x, const std::vector<Tet>& tets, const std::vector<char>& on_border,
                    const std::vector<std::array<int, 3> >& border_faces, const std::vector<double>& target,
                    const Discrete_lie_flow_volume_options& O, const Volume_share_levels& levels,
                    const Discrete_lie_flow_options& opt)
    : Flow_policy_base(stopping_rules(opt)), m_x(x), m_tets(tets), m_on_border(on_border),
      m_border_faces(border_faces), m_target(target), m_O(O), m_levels(levels), m_opt(opt), m_energy(target), m_solver(m_factor),
      m_v(x.size()), m_trial(x.size())
  {
    lump_tets_on_vertices(x.size(), tets, target, m_VM);
    m_T = 0;
    for(double a : target) m_T += a;
  }

  bool start(Flow_outcome& out)
  {
    tet_dets(m_x, m_tets, m_u);
    m_E = m_energy.value(m_u, 0);
    out.initial_d_area = out.final_d_area = m_E;
    m_best = m_E;
    m_best_x = m_x;
    m_best_u = m_u;
    return std::isfinite(m_E);
  }

  bool converged() const
  {
    return m_best - 2 <= m_O.tolerance && level_share_error(m_levels, m_best_u) <= m_O.share_tolerance;
  }

  /// The Poisson potential h of L h = V_Ω − V_M (the closed domain's
  /// Neumann problem: h_0 = 0 pinned, the right-hand side scaled to sum to
  /// zero), then per vertex the volume-weighted mean of its tets' constant
  /// gradients of h, tangential to the sphere on the border. L is positive
  /// semidefinite: where V_Ω exceeds V_M, h peaks and the vertices converge
  /// along ∇h, which shrinks the volume there (the surface paper flows'
  /// convention, area for volume).
  Direction_status direction(Flow_outcome& out)
  {
    const std::size_t n = m_x.size();
    const Sparse_matrix* L = nullptr;
    {
      Scoped_timer timer(out.seconds_assembly);
      // In volumes (u_t = 6 vol_t): V_M's scale cancels in the solve, V_Ω's
      // sets h's, so that λ = 1 is the full first-order correction.
      lump_tets_on_vertices(n, m_tets, m_u, m_VO);
      for(double& v : m_VO) v /= 6;
      L = &m_K.assemble(n, [&](const auto& add) { volume_stiffness_contributions(m_x, m_tets, add); });
    }
    std::vector<double> h;
    if(!solve_pinned_poisson(*L, m_VO, m_VM, m_solver, out, h)) return Direction_status::SOLVER_FAILED;
    Scoped_timer timer(out.seconds_step);
    // ∇h_t = Σ_k h_k G_k / u_t, so 6 vol_t ∇h_t = Σ_k h_k G_k: summed over
    // the vertex's tets and divided by Σ_t u_t, the volume-weighted mean.
    std::fill(m_v.begin(), m_v.end(), Vec3{{ 0, 0, 0 }});
    m_wsum.assign(n, 0.);
    for(std::size_t t = 0; t < m_tets.size(); ++t) {
      const Tet& k = m_tets[t];
      const std::array<Vec3, 4> G = tet_corner_gradients(m_x[std::size_t(k[0])], m_x[std::size_t(k[1])],
                                                         m_x[std::size_t(k[2])], m_x[std::size_t(k[3])]);
      Vec3 g = {{ 0, 0, 0 }}; // vol_t ∇h_t, times 6
      for(std::size_t j = 0; j < 4; ++j)
        for(std::size_t c = 0; c < 3; ++c) g[c] += h[std::size_t(k[j])] * G[j][c];
      for(int v : k) {
        for(std::size_t c = 0; c < 3; ++c) m_v[std::size_t(v)][c] += g[c];
        m_wsum[std::size_t(v)] += m_u[t];
      }
    }
    double vmax = 0;
    for(std::size_t v = 0; v < n; ++v) {
      if(m_wsum[v] > 0)
        for(std::size_t c = 0; c < 3; ++c) m_v[v][c] /= m_wsum[v];
      tangential(v, m_v[v]);
      vmax = (std::max)(vmax, norm3(m_v[v]));
    }
    if(m_O.paper_collapse_guard) collapse_guard();
    return vmax > 0 ? Direction_status::DESCENT : Direction_status::NO_DESCENT;
  }

  /// The planar paper mode's collapse guard in 3D (doc/paper_mode.md): a tet
  /// already below its target share that the velocities shrink and would
  /// flatten at some λ gets its volume rate projected to zero by the
  /// smallest change of its four corners' velocities (border corners stay
  /// tangent); up to 60 rounds, since a projection can start a neighbour's
  /// collapse. Without it the tangential velocities flatten tets whose four
  /// corners lie on the sphere within a few steps (doc/volume.md, "Paper mode").
  void collapse_guard()
  {
    double U = 0;
    for(double u : m_u) U += u;
    for(std::size_t round = 0; round < 60; ++round) {
      std::size_t projected = 0;
      for(std::size_t t = 0; t < m_tets.size(); ++t) {
        if(!(m_u[t] / U < m_target[t] / m_T)) continue;
        const Tet& k = m_tets[t];
        const Vec3 &a = m_x[std::size_t(k[0])], &b = m_x[std::size_t(k[1])], &c = m_x[std::size_t(k[2])], &d = m_x[std::size_t(k[3])];
        const std::array<double, 4> cubic = tet_volume_cubic(a, b, c, d, m_v[std::size_t(k[0])], m_v[std::size_t(k[1])],
                                                             m_v[std::size_t(k[2])], m_v[std::size_t(k[3])]);
        const double rate = cubic[2]; // d det / dλ at λ = 0
        if(!(rate < -1e-12 * m_u[t]) ||
           !std::isfinite(smallest_positive_root(cubic[0], cubic[1], cubic[2], cubic[3])))
          continue;
        std::array<Vec3, 4> G = tet_corner_gradients(a, b, c, d);
        double gg = 0;
        for(std::size_t j = 0; j < 4; ++j) {
          tangential(std::size_t(k[j]), G[j]);
          gg += dot(G[j], G[j]);
        }
        if(!(gg > 0)) continue;
        const double alpha = rate / gg;
        for(std::size_t j = 0; j < 4; ++j)
          for(std::size_t i = 0; i < 3; ++i) m_v[std::size_t(k[j])][i] -= alpha * G[j][i];
        ++projected;
      }
      m_guarded += projected;
      if(projected == 0) break;
    }
  }

  /// Tets whose volume rate the collapse guard projected, over all iterations and rounds.
  std::size_t guarded() const { return m_guarded; }

  /// λ = min(1, μ·λ_crit), λ_crit the smallest positive root of the tets'
  /// cubics (and with a star-shaped border of the border triangles' seen
  /// from the centre).
  void bound(Flow_step& step)
  {
    step.critical = smallest_critical_step(m_tets.size(), [&](std::size_t t, double) {
      const Tet& k = m_tets[t];
      const std::size_t a = std::size_t(k[0]), b = std::size_t(k[1]), c = std::size_t(k[2]), d = std::size_t(k[3]);
      return critical_step_tet(m_x[a], m_x[b], m_x[c], m_x[d], m_v[a], m_v[b], m_v[c], m_v[d]);
    }, step.limiting);
    if(m_O.star_shaped_border)
      for(const auto& f : m_border_faces) {
        const std::size_t a = std::size_t(f[0]), b = std::size_t(f[1]), c = std::size_t(f[2]);
        step.critical = (std::min)(step.critical, critical_step_sphere(m_x[a], m_x[b], m_x[c], m_v[a], m_v[b], m_v[c]));
      }
    step.lambda = (std::min)(1., m_O.mu * step.critical);
    if(!std::isfinite(step.lambda)) step.lambda = 1;
  }

  /// Halves the step until every tet is positive, first by the doubles and
  /// a degeneracy guard (a tet's share may not fall below 1e-8 times its
  /// target share, nor, if the start already has it below, halve per step:
  /// the sphere's paper mode), then by the exact predicate. No energy test:
  /// the paper's step is not a descent step of D_vol; the best iterate is
  /// kept instead.
  void search(Flow_step& step, Flow_outcome& out)
  {
    for(; step.halvings <= m_opt.max_backtracks; ++step.halvings, step.lambda *= 0.5) {
      if(!trial(step.lambda)) continue;
      if(!certified()) {
        ++out.rejected_by_exact_check;
        continue;
      }
      step.accepted = true;
      return;
    }
  }

  /// The positions at step λ into m_trial, their dets into m_u_trial; false
  /// if a tet is not positive by the doubles or falls below the degeneracy guard.
  bool trial(double lambda)
  {
    const std::size_t n = m_x.size();
    double U = 0;
    for(double u : m_u) U += u;
    for(std::size_t v = 0; v < n; ++v) {
      const Vec3 y = {{ m_x[v][0] + lambda * m_v[v][0], m_x[v][1] + lambda * m_v[v][1], m_x[v][2] + lambda * m_v[v][2] }};
      m_trial[v] = m_on_border[v] ? normalized(y) : y;
    }
    tet_dets(m_trial, m_tets, m_u_trial);
    double U_trial = 0;
    bool ok = true;
    for(std::size_t t = 0; t < m_u_trial.size() && ok; ++t) { ok = m_u_trial[t] > 0; U_trial += m_u_trial[t]; }
    for(std::size_t t = 0; t < m_u_trial.size() && ok; ++t)
      ok = m_u_trial[t] / U_trial >= (std::min)(m_opt.paper.degeneracy_ratio * (m_target[t] / m_T), 0.5 * (m_u[t] / U));
    return ok;
  }

  /// m_trial certified by the exact predicate.
  bool certified() const
  {
    return !take_forced_trial_refusal() && count_bad_tets(m_trial, m_tets).not_positive() == 0 &&
           !(m_O.star_shaped_border && count_bad_border_faces(m_trial, m_border_faces) != 0);
  }

  void commit(const Flow_step&, Flow_outcome&)
  {
    m_x.swap(m_trial);
    m_u.swap(m_u_trial);
    m_E = m_energy.value(m_u, 0);
    if(m_E < m_best) {
      m_best = m_E;
      m_best_x = m_x;
      m_best_u = m_u;
    }
  }

  double d_area() const { return m_E; }      // the record's value: D_vol of the iterate
  double progress() const { return m_best; } // the stop tests watch the best D_vol
  double residual() const { return 0; }      // not part of the volumetric record
  double energy() const { return m_best; }
  std::size_t cg_iterations() const { return 0; } // no conjugate gradients

  void finish(Flow_outcome& out)
  {
    m_x = m_best_x;
    out.final_d_area = m_best;
    out.symbolic_analyses = m_solver.analyses();
  }

private:
  /// On the border, the component of w normal to the sphere at x_v removed.
  void tangential(std::size_t v, Vec3& w) const
  {
    if(!m_on_border[v]) return;
    const double r = dot(w, m_x[v]) / dot(m_x[v], m_x[v]);
    for(std::size_t c = 0; c < 3; ++c) w[c] -= r * m_x[v][c];
  }

  static Flow_stopping::Rules stopping_rules(const Discrete_lie_flow_options& opt)
  {
    Flow_stopping::Rules r = Flow_stopping::rules_of(opt);
    r.stall = Flow_stopping::SAME_LIMITING_FACE;
    return r;
  }

  std::vector<Vec3>& m_x;
  const std::vector<Tet>& m_tets;
  const std::vector<char>& m_on_border;
  const std::vector<std::array<int, 3> >& m_border_faces;
  const std::vector<double>& m_target;
  const Discrete_lie_flow_volume_options& m_O;
  const Volume_share_levels& m_levels;
  const Discrete_lie_flow_options& m_opt;
  Volume_energy m_energy;
  Default_spd_solver m_factor;
  Pattern_reusing_solver<Default_spd_solver> m_solver;
  Fixed_pattern_matrix m_K;
  std::vector<Vec3> m_v, m_trial, m_best_x;
  std::vector<double> m_u, m_u_trial, m_best_u, m_VO, m_VM, m_wsum;
  double m_T = 0, m_E = 0, m_best = 0;
  std::size_t m_guarded = 0;
};

/// Runs the paper's volumetric flow on positions `x` (every tet positive
/// by the exact predicate, border points on the unit sphere) by
/// `run_flow()`: until D_vol − 2 ≤ tolerance (and the levels' shares within
/// theirs), a plateau of the best D_vol, a stall (the same tet limiting 25
/// steps in a row below 1e-3) or the cap. `x` receives the best iterate.
inline Volume_flow_outcome run_volume_paper_flow(std::vector<Vec3>& x, const std::vector<Tet>& tets,
                                                 const std::vector<char>& on_border,
                                                 const std::vector<std::array<int, 3> >& border_faces,
                                                 const std::vector<double>& target,
                                                 const Discrete_lie_flow_volume_options& O,
                                                 const Volume_share_levels& levels = Volume_share_levels(),
                                                 std::vector<Volume_iteration>* history = nullptr)
{
  const Scoped_blas_threads blas(1, x.size()); // one small factorisation per iteration
  const Discrete_lie_flow_options opt =
    volume_driver_options(O, history, [](int f) { return f; }, [] { return std::size_t(0); });
  Volume_paper_flow flow(x, tets, on_border, border_faces, target, O, levels, opt);
  return run_volume_policy(flow, opt);
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
