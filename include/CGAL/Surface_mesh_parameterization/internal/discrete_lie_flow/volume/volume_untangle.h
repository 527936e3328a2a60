// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Untangling a folded start of the volumetric flow: Garanzha, Kaporin,
// Kudryavtseva, Protais, Ray and Sokolov's regularised barrier ("Foldover-free
// maps in 50 lines of code", ACM TOG 40(4), 2021). Per tet, with J the
// Jacobian from its reference shape (the input tet scaled to its target
// volume) and χ_ε(d) = (d + √(ε² + d²))/2, the energy is
// (1 − θ) tr(JᵀJ)/χ(det J)^{2/3} + θ (det J² + 1)/χ(det J); it is
// minimised by L-BFGS at fixed ε, and ε shrinks between rounds so that the
// smallest regularised determinant shrinks by 1 − σ (σ the round's relative
// energy drop, at least 0.1); L-BFGS's initial inverse Hessian is the
// inverse stiffness of the reference tets. The interior vertices move in
// space, the border vertices slide on the unit sphere. It stops as soon as
// every tet and every border triangle (seen from the centre) is positive by
// the exact predicate.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_VOLUME_UNTANGLE_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_VOLUME_UNTANGLE_H

#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/default_solver.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/volume/volume_flow.h>

#include <Eigen/Dense>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <deque>
#include <functional>
#include <limits>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

struct Untangle_outcome
{
  bool success = false;
  bool stopped = false; ///< the callback returned false
  std::size_t iterations = 0, rounds = 0;
  std::size_t regions = 0; ///< sub-problems solved (connected regions around folds, over the stages)
};

/// The untangling of one problem by L-BFGS on the regularised barrier at
/// decreasing ε (see the file comment): tets `tets` (the first `real_tets`
/// are the mesh's, the others cone tets on the fixed centre vertex, whose
/// reference shape is taken from `cone_reference`); `kind` per vertex: 0
/// interior, 1 on the sphere, 2 fixed.
class Volume_untangler
{
public:
  Volume_untangler(std::vector<Vec3>& x, const std::vector<Tet>& tets, std::size_t real_tets,
                   const std::vector<char>& kind, const std::vector<Vec3>& reference,
                   const std::vector<Vec3>& cone_reference, const std::vector<double>& target,
                   std::size_t max_iterations, const std::function<bool(const Volume_iteration&)>& callback)
    : m_start(Clock::now()), m_x(x), m_tets(tets), m_kind(kind), m_V(x.size()), m_T(tets.size()),
      m_max_iterations(max_iterations), m_callback(callback), m_A(m_T), m_detA(m_T), m_weight(m_T), m_dets(m_T),
      m_y(m_V)
  {
    reference_shapes(real_tets, reference, cone_reference, target);
    factor_stiffness();
  }

  /// Untangles `x` in place; on success with the polish, `x` is the last
  /// certified position of it.
  Untangle_outcome run()
  {
    m_E = evaluate(m_x, 1, nullptr); // fills the determinants
    double dmin = *std::min_element(m_dets.begin(), m_dets.end());
    const double mu0 = 0.1;
    // ε at most a tenth of the target determinant (1): with a larger ε the
    // energy hardly sees the small determinants, and the shape term, which
    // rewards shrinking, pushes the tets that are too small through zero.
    m_eps = (std::min)(0.1, dmin < mu0 ? 2 * std::sqrt(mu0 * (mu0 - dmin)) : 1e-3);
    // A round that accepts no step leaves x and, but for ε, everything as it
    // was: three in a row end the attempt (else the loop would not end).
    int idle_rounds = 0;
    while(m_out.iterations < m_max_iterations && idle_rounds < 3) {
      if(m_polishing) break;
      const std::size_t round_start = m_out.iterations;
      if(!round()) return m_out;
      idle_rounds = m_out.iterations == round_start ? idle_rounds + 1 : 0;
      // The next ε.
      evaluate(m_x, m_eps, nullptr);
      dmin = *std::min_element(m_dets.begin(), m_dets.end());
      const double sigma = (std::max)(0.1, 1 - m_E / m_E_round);
      const double mu = (1 - sigma) * Volume_energy::chi(dmin, m_eps);
      m_eps = (std::min)(0.1, dmin < mu ? 2 * std::sqrt(mu * (mu - dmin)) : 1e-10);
      if(m_polishing) break;
      if(dmin > 0 && certified(m_x)) { m_out.success = true; return m_out; }
    }
    if(m_polishing) {
      if(certified(m_x)) m_certified_x = m_x;
      m_x.swap(m_certified_x);
      return m_out;
    }
    m_out.success = certified(m_x);
    return m_out;
  }

private:
  typedef std::chrono::steady_clock Clock;
  enum Iteration_result { NEXT_ITERATION, END_ROUND, STOPPED };

  // Per tet: A = (s R)⁻¹ with R the reference edge matrix scaled so that
  // det(sR) is the target share of U.
  void reference_shapes(std::size_t real_tets, const std::vector<Vec3>& reference,
                        const std::vector<Vec3>& cone_reference, const std::vector<double>& target)
  {
    double U = 0, Tsum = 0;
    std::vector<double> u;
    tet_dets(m_x, m_tets, u);
    for(std::size_t t = 0; t < real_tets; ++t) U += u[t];
    for(std::size_t t = 0; t < m_T; ++t) Tsum += target[t];
    for(std::size_t t = 0; t < m_T; ++t) {
      const Tet& k = m_tets[t];
      const std::vector<Vec3>& P = t < real_tets ? reference : cone_reference;
      Eigen::Matrix3d R;
      for(int j = 0; j < 3; ++j)
        for(int c = 0; c < 3; ++c)
          R(c, j) = P[std::size_t(k[std::size_t(j + 1)])][std::size_t(c)] - P[std::size_t(k[0])][std::size_t(c)];
      const double share = target[t] / Tsum;
      const double s = std::cbrt(share * U / R.determinant());
      m_A[t] = (s * R).inverse();
      m_detA[t] = m_A[t].determinant();
      m_weight[t] = share;
    }
  }

  // The L-BFGS's initial inverse Hessian γ L⁻¹, L the stiffness of the
  // shape term at the reference: Σ_t weight_t B_t B_tᵀ, the rows of B_t the
  // gradients of the tet's barycentric coordinates in its scaled reference
  // (∇β_1…∇β_3 the rows of A, ∇β_0 minus their sum), one scalar matrix for
  // the three coordinates, the fixed vertices eliminated; factorised once.
  // On Mesh_3's graded meshes it makes the steps independent of the
  // element sizes, which plain L-BFGS's are not.
  void factor_stiffness()
  {
    m_dof.assign(m_V, -1);
    for(std::size_t v = 0; v < m_V; ++v) if(m_kind[v] != 2) m_dof[v] = m_ndof++;
    if(m_ndof == 0) return;
    std::vector<Eigen::Triplet<double> > entries;
    std::vector<double> diagonal(std::size_t(m_ndof), 0.);
    for(std::size_t t = 0; t < m_T; ++t) {
      const Tet& k = m_tets[t];
      Eigen::Matrix<double, 4, 3> B; // rows: ∇β_0 … ∇β_3
      B.block<3, 3>(1, 0) = m_A[t];
      B.row(0) = -(m_A[t].row(0) + m_A[t].row(1) + m_A[t].row(2));
      const Eigen::Matrix4d K = m_weight[t] * B * B.transpose();
      for(int a = 0; a < 4; ++a) {
        const int i = m_dof[std::size_t(k[std::size_t(a)])];
        if(i < 0) continue;
        for(int b = 0; b < 4; ++b) {
          const int j = m_dof[std::size_t(k[std::size_t(b)])];
          if(j >= 0 && j <= i) entries.emplace_back(i, j, K(a, b));
        }
        diagonal[std::size_t(i)] += K(a, a);
      }
    }
    for(int i = 0; i < m_ndof; ++i) entries.emplace_back(i, i, 1e-8 * diagonal[std::size_t(i)] + 1e-300);
    m_L.resize(m_ndof, m_ndof);
    m_L.setFromTriplets(entries.begin(), entries.end());
    m_stiffness.compute(m_L);
    m_preconditioned = m_stiffness.info() == Eigen::Success;
  }

  // dir ← P L⁻¹ P dir (P: the tangent planes of the border vertices).
  void apply_stiffness_inverse(std::vector<Vec3>& dir)
  {
    m_rhs.resize(m_ndof, 3);
    for(std::size_t v = 0; v < m_V; ++v)
      if(m_dof[v] >= 0) for(int c = 0; c < 3; ++c) m_rhs(m_dof[v], c) = dir[v][std::size_t(c)];
    const Eigen::MatrixXd sol = m_stiffness.solve(m_rhs);
    for(std::size_t v = 0; v < m_V; ++v)
      if(m_dof[v] >= 0) for(int c = 0; c < 3; ++c) dir[v][std::size_t(c)] = sol(m_dof[v], c);
      else dir[v] = {{ 0, 0, 0 }};
  }

  // sᵀ L s, for the scale of H₀ = γ L⁻¹: γ = sᵀLs / sᵀy (the curvature along
  // s over the stiffness's), without a second solve.
  double stiffness_norm(const std::vector<Vec3>& sk) const
  {
    Eigen::MatrixXd S(m_ndof, 3);
    for(std::size_t v = 0; v < m_V; ++v)
      if(m_dof[v] >= 0) for(int c = 0; c < 3; ++c) S(m_dof[v], c) = sk[v][std::size_t(c)];
    const Eigen::MatrixXd LS = m_L.selfadjointView<Eigen::Lower>() * S;
    return (S.array() * LS.array()).sum();
  }

  // Energy and gradient (per vertex, ambient) at fixed ε; the tets'
  // regularised determinants into m_dets.
  double evaluate(const std::vector<Vec3>& y, double eps, std::vector<Vec3>* grad)
  {
    double E = 0;
    if(grad) grad->assign(m_V, Vec3{{ 0, 0, 0 }});
    for(std::size_t t = 0; t < m_T; ++t) {
      const Tet& k = m_tets[t];
      const Vec3& a = y[std::size_t(k[0])];
      Eigen::Matrix3d X;
      for(int j = 0; j < 3; ++j)
        for(int c = 0; c < 3; ++c) X(c, j) = y[std::size_t(k[std::size_t(j + 1)])][std::size_t(c)] - a[std::size_t(c)];
      const Eigen::Matrix3d J = X * m_A[t];
      const double d = X.determinant() * m_detA[t];
      m_dets[t] = d;
      const double chi = Volume_energy::chi(d, eps), dchi = Volume_energy::dchi(d, eps);
      if(!(chi > 0)) return std::numeric_limits<double>::infinity();
      const double s = J.squaredNorm();
      const double c23 = std::cbrt(chi * chi);
      const double f = s / c23, g = (d * d + 1) / chi;
      E += m_weight[t] * ((1 - m_theta) * f + m_theta * g);
      if(!grad) continue;
      // ∂/∂X: shape 2 J Aᵀ / χ^{2/3}; determinant terms times ∂d/∂X = detA·cof(X).
      const double df_dd = -(2. / 3.) * s * dchi / (c23 * chi);
      const double dg_dd = 2 * d / chi - (d * d + 1) * dchi / (chi * chi);
      const double dd = m_weight[t] * ((1 - m_theta) * df_dd + m_theta * dg_dd) * m_detA[t];
      const Eigen::Matrix3d GS = m_weight[t] * (1 - m_theta) * 2 * J * m_A[t].transpose() / c23;
      const Vec3 e1 = {{ X(0, 0), X(1, 0), X(2, 0) }}, e2 = {{ X(0, 1), X(1, 1), X(2, 1) }}, e3 = {{ X(0, 2), X(1, 2), X(2, 2) }};
      const Vec3 cof[3] = { cross(e2, e3), cross(e3, e1), cross(e1, e2) };
      for(int j = 0; j < 3; ++j) {
        Vec3& gv = (*grad)[std::size_t(k[std::size_t(j + 1)])];
        Vec3& g0 = (*grad)[std::size_t(k[0])];
        for(int c = 0; c < 3; ++c) {
          const double v = GS(c, j) + dd * cof[j][std::size_t(c)];
          gv[std::size_t(c)] += v;
          g0[std::size_t(c)] -= v;
        }
      }
    }
    return E;
  }

  // The fixed vertices' components zeroed, the border's projected on the
  // tangent planes of the sphere at `y`.
  void project(const std::vector<Vec3>& y, std::vector<Vec3>& g) const
  {
    for(std::size_t v = 0; v < m_V; ++v)
      if(m_kind[v] == 2) {
        g[v] = {{ 0, 0, 0 }};
      } else if(m_kind[v]) {
        const Vec3 n = normalized(y[v]);
        const double k = dot(g[v], n);
        for(int c = 0; c < 3; ++c) g[v][std::size_t(c)] -= k * n[std::size_t(c)];
      }
  }

  static double inner(const std::vector<Vec3>& a, const std::vector<Vec3>& b)
  {
    double s = 0;
    for(std::size_t i = 0; i < a.size(); ++i) s += dot(a[i], b[i]);
    return s;
  }

  // Every determinant of the last evaluation positive, and every tet of `y`
  // by the exact predicate.
  bool certified(const std::vector<Vec3>& y) const
  {
    for(double d : m_dets) if(!(d > 0)) return false;
    return count_bad_tets(y, m_tets).not_positive() == 0;
  }

  // The L-BFGS direction from the gradient m_g (two-loop recursion, the
  // initial inverse Hessian γ L⁻¹ or the scalar γ), projected; the slope
  // gᵀd into `slope` (the gradient itself when that is not a descent).
  void direction(double& slope)
  {
    m_dir = m_g;
    std::vector<double> alpha(m_memory.size());
    for(std::size_t m = m_memory.size(); m-- > 0;) {
      const double rho = 1 / inner(m_memory[m].second, m_memory[m].first);
      alpha[m] = rho * inner(m_memory[m].first, m_dir);
      for(std::size_t i = 0; i < m_V; ++i)
        for(int c = 0; c < 3; ++c) m_dir[i][std::size_t(c)] -= alpha[m] * m_memory[m].second[i][std::size_t(c)];
    }
    if(m_preconditioned) {
      project(m_x, m_dir);
      apply_stiffness_inverse(m_dir);
      project(m_x, m_dir);
      if(!m_memory.empty()) {
        const double gamma = m_memory_sls.back() / inner(m_memory.back().first, m_memory.back().second);
        for(Vec3& v : m_dir) for(double& c : v) c *= gamma;
      }
    } else if(!m_memory.empty()) {
      const double gamma = inner(m_memory.back().first, m_memory.back().second) /
                           inner(m_memory.back().second, m_memory.back().second);
      for(Vec3& v : m_dir) for(double& c : v) c *= gamma;
    }
    for(std::size_t m = 0; m < m_memory.size(); ++m) {
      const double rho = 1 / inner(m_memory[m].second, m_memory[m].first);
      const double beta = rho * inner(m_memory[m].second, m_dir);
      for(std::size_t i = 0; i < m_V; ++i)
        for(int c = 0; c < 3; ++c) m_dir[i][std::size_t(c)] += (alpha[m] - beta) * m_memory[m].first[i][std::size_t(c)];
    }
    for(Vec3& v : m_dir) for(double& c : v) c = -c;
    project(m_x, m_dir);
    slope = inner(m_g, m_dir);
    if(!(slope < 0)) { // not a descent direction: the gradient
      m_memory.clear();
      m_memory_sls.clear();
      m_dir = m_g;
      for(Vec3& v : m_dir) for(double& c : v) c = -c;
      slope = inner(m_g, m_dir);
    }
  }

  // Backtracking from `step` to the Armijo condition (at most 40 halvings):
  // the trial into m_y and its energy into `E_new`; false if none passed.
  bool line_search(double slope, double& step, double& E_new)
  {
    for(int tries = 0; tries < 40; ++tries, step *= 0.5) {
      for(std::size_t v = 0; v < m_V; ++v) {
        const Vec3 p = {{ m_x[v][0] + step * m_dir[v][0], m_x[v][1] + step * m_dir[v][1], m_x[v][2] + step * m_dir[v][2] }};
        m_y[v] = m_kind[v] == 1 ? normalized(p) : p;
      }
      E_new = evaluate(m_y, m_eps, &m_g_new);
      if(E_new <= m_E + 1e-4 * step * slope) return true;
    }
    return false;
  }

  // The pair (s_k, y_k) of the accepted step into the memory (at most 8).
  void remember()
  {
    std::vector<Vec3> sk(m_V), yk(m_V);
    for(std::size_t v = 0; v < m_V; ++v) {
      sk[v] = sub(m_y[v], m_x[v]);
      yk[v] = sub(m_g_new[v], m_g[v]);
    }
    if(inner(sk, yk) > 1e-300) {
      if(m_preconditioned) {
        m_memory_sls.push_back(stiffness_norm(sk));
        if(m_memory_sls.size() > 8) m_memory_sls.pop_front();
      }
      m_memory.emplace_back(std::move(sk), std::move(yk));
      if(m_memory.size() > 8) m_memory.pop_front();
    }
  }

  // The callback's record of the iteration; false: stop.
  bool report(double step, std::size_t negative) const
  {
    if(!m_callback) return true;
    Volume_iteration I;
    I.iteration = m_out.iterations;
    I.step = step;
    I.d_vol = m_E;
    I.epsilon = m_eps;
    I.untangling = true;
    I.negative_tets = negative;
    I.seconds = std::chrono::duration<double>(Clock::now() - m_start).count();
    return m_callback(I);
  }

  // One L-BFGS iteration at the round's ε.
  Iteration_result iterate()
  {
    double slope = 0;
    direction(slope);
    double dmax = 0;
    for(const Vec3& v : m_dir) dmax = (std::max)(dmax, norm3(v));
    if(!(dmax > 0)) return END_ROUND;
    double step = (std::min)(1., 0.05 / dmax);
    if(m_memory.empty()) step = (std::min)(step, 0.01 / dmax);
    double E_new = m_E;
    if(!line_search(slope, step, E_new)) return END_ROUND;
    ++m_out.iterations;
    project(m_y, m_g_new);
    remember();
    m_x.swap(m_y);
    m_g.swap(m_g_new);
    const double drop = (m_E - E_new) / std::abs(m_E);
    m_E = E_new;
    std::size_t negative = 0;
    for(double d : m_dets) negative += (d <= 0);
    if(!report(step, negative)) { m_out.stopped = true; return STOPPED; }
    if(m_polishing) {
      if(m_out.iterations % 10 == 0 && certified(m_x)) m_certified_x = m_x;
      if(drop < 1e-5 || ++m_polished >= 200) return END_ROUND;
      return NEXT_ITERATION;
    }
    if(negative == 0 && certified(m_x)) {
      // Untangled. Then the pure barrier (ε = 0) from there for a while:
      // it moves every tet and border triangle away from flat, which
      // leaves the flow room to move.
      m_out.success = true;
      m_certified_x = m_x;
      m_polishing = true;
      m_eps = 0;
      m_E = evaluate(m_x, m_eps, &m_g);
      project(m_x, m_g);
      m_memory.clear();
      m_memory_sls.clear();
      return NEXT_ITERATION;
    }
    return drop < 1e-6 ? END_ROUND : NEXT_ITERATION;
  }

  // A round at fixed ε: at most 200 iterations from a fresh memory; the
  // round's starting energy into m_E_round. False when the callback stopped.
  bool round()
  {
    ++m_out.rounds;
    m_E = evaluate(m_x, m_eps, &m_g);
    project(m_x, m_g);
    m_E_round = m_E;
    m_memory.clear();
    m_memory_sls.clear();
    for(int it = 0; it < 200 && m_out.iterations < m_max_iterations; ++it) {
      const Iteration_result r = iterate();
      if(r == STOPPED) return false;
      if(r == END_ROUND) break;
    }
    return true;
  }

  const Clock::time_point m_start;
  std::vector<Vec3>& m_x;
  const std::vector<Tet>& m_tets;
  const std::vector<char>& m_kind;
  const std::size_t m_V, m_T;
  const std::size_t m_max_iterations;
  const std::function<bool(const Volume_iteration&)>& m_callback;
  const double m_theta = 0.25;
  std::vector<Eigen::Matrix3d> m_A;
  std::vector<double> m_detA, m_weight, m_dets;
  std::vector<int> m_dof;
  int m_ndof = 0;
  Default_spd_solver m_stiffness;
  Sparse_matrix m_L; // lower triangle
  bool m_preconditioned = false;
  Eigen::MatrixXd m_rhs;
  std::vector<Vec3> m_g, m_g_new, m_dir, m_y, m_certified_x;
  std::deque<std::pair<std::vector<Vec3>, std::vector<Vec3> > > m_memory; // (s_k, y_k)
  std::deque<double> m_memory_sls; // s_kᵀ L s_k
  double m_E = 0, m_E_round = 0, m_eps = 0;
  bool m_polishing = false;
  std::size_t m_polished = 0;
  Untangle_outcome m_out;
};

/// The untangling of a whole start by stages and regions (see
/// `untangle_volume()`): the folds' neighbourhoods, their connected regions,
/// each region's sub-problem solved by `Volume_untangler` with its
/// neighbours held.
class Volume_region_untangling
{
public:
  Volume_region_untangling(std::vector<Vec3>& x, const std::vector<Tet>& tets, const std::vector<char>& on_border,
                           const std::vector<std::array<int, 3> >& border_faces, const std::vector<Vec3>& reference,
                           const std::vector<double>& target, const std::function<bool(const Volume_iteration&)>& callback)
    : m_x(x), m_tets(tets), m_on_border(on_border), m_border_faces(border_faces), m_reference(reference),
      m_target(target), m_callback(callback), m_vertex_tets(x.size()), m_vertex_faces(x.size()),
      m_region(x.size(), -1), m_local(x.size(), -1), m_tet_taken(tets.size(), 0), m_face_taken(border_faces.size(), 0)
  {
    double Tsum = 0;
    for(double a : target) Tsum += a;
    m_cone_weight = 0.1 * Tsum / double((std::max)(border_faces.size(), std::size_t(1)));
    for(std::size_t t = 0; t < tets.size(); ++t)
      for(int v : tets[t]) m_vertex_tets[std::size_t(v)].push_back(int(t));
    for(std::size_t f = 0; f < border_faces.size(); ++f)
      for(int v : border_faces[f]) m_vertex_faces[std::size_t(v)].push_back(int(f));
  }

  Untangle_outcome run(std::size_t max_iterations)
  {
    for(int rings : { 1, 3, 6, 12, -1 }) {
      if(m_total.iterations >= max_iterations) break;
      if(!movable_vertices(rings)) { m_total.success = true; return m_total; }
      bool all_certified = true;
      for(const std::vector<int>& members : movable_regions()) {
        if(m_total.iterations >= max_iterations) { all_certified = false; break; }
        const Untangle_outcome out = untangle_region(members, max_iterations);
        if(out.stopped) { m_total.stopped = true; return m_total; }
        all_certified = all_certified && out.success;
      }
      if(all_certified) {
        m_total.success = true;
        return m_total;
      }
    }
    return m_total;
  }

private:
  // The folded tets' and cones' vertices, grown by `rings` rings (−1: every
  // vertex), into m_movable; false when nothing is folded.
  bool movable_vertices(int rings)
  {
    const std::size_t V = m_x.size();
    const std::vector<Vec3>& x = m_x;
    m_movable.assign(V, 0);
    std::vector<int> front;
    for(const Tet& k : m_tets)
      if(exact_tet_orientation(x[std::size_t(k[0])], x[std::size_t(k[1])], x[std::size_t(k[2])], x[std::size_t(k[3])]) != POSITIVE)
        for(int v : k) if(!m_movable[std::size_t(v)]) { m_movable[std::size_t(v)] = 1; front.push_back(v); }
    for(const auto& f : m_border_faces)
      if(exact_tet_orientation(m_o, x[std::size_t(f[0])], x[std::size_t(f[1])], x[std::size_t(f[2])]) != POSITIVE)
        for(int v : f) if(!m_movable[std::size_t(v)]) { m_movable[std::size_t(v)] = 1; front.push_back(v); }
    if(front.empty()) return false;
    if(rings < 0) std::fill(m_movable.begin(), m_movable.end(), 1);
    for(int r = 0; r < rings; ++r) {
      std::vector<int> next;
      for(int v : front)
        for(int t : m_vertex_tets[std::size_t(v)])
          for(int w : m_tets[std::size_t(t)])
            if(!m_movable[std::size_t(w)]) { m_movable[std::size_t(w)] = 1; next.push_back(w); }
      front.swap(next);
    }
    return true;
  }

  // The connected regions of movable vertices (two movable vertices of one
  // tet are in one region).
  std::vector<std::vector<int> > movable_regions()
  {
    const std::size_t V = m_x.size();
    std::fill(m_region.begin(), m_region.end(), -1);
    std::vector<std::vector<int> > regions;
    for(std::size_t s = 0; s < V; ++s) {
      if(!m_movable[s] || m_region[s] >= 0) continue;
      std::vector<int> members(1, int(s));
      m_region[s] = int(regions.size());
      for(std::size_t i = 0; i < members.size(); ++i)
        for(int t : m_vertex_tets[std::size_t(members[i])])
          for(int w : m_tets[std::size_t(t)])
            if(m_movable[std::size_t(w)] && m_region[std::size_t(w)] < 0) {
              m_region[std::size_t(w)] = m_region[s];
              members.push_back(w);
            }
      regions.push_back(std::move(members));
    }
    return regions;
  }

  // A region's sub-problem: the tets with a vertex in it, their vertices
  // (the others fixed), the border triangles with a vertex in it as cones on
  // a fixed centre vertex.
  struct Sub_problem
  {
    std::vector<int> global;
    std::vector<Tet> tets;
    std::vector<double> target;
    std::vector<Vec3> x, reference, cone_reference;
    std::vector<char> kind;
    std::size_t real_tets = 0;
  };

  int local_index(Sub_problem& P, int v)
  {
    if(m_local[std::size_t(v)] < 0) {
      m_local[std::size_t(v)] = int(P.global.size());
      P.global.push_back(v);
      P.x.push_back(m_x[std::size_t(v)]);
      P.reference.push_back(m_reference[std::size_t(v)]);
      P.kind.push_back(m_movable[std::size_t(v)] ? char(m_on_border[std::size_t(v)] ? 1 : 0) : char(2));
    }
    return m_local[std::size_t(v)];
  }

  void make_sub_problem(const std::vector<int>& members, Sub_problem& P)
  {
    std::vector<int> tet_ids, face_ids;
    for(int v : members)
      for(int t : m_vertex_tets[std::size_t(v)])
        if(!m_tet_taken[std::size_t(t)]) { m_tet_taken[std::size_t(t)] = 1; tet_ids.push_back(t); }
    std::sort(tet_ids.begin(), tet_ids.end()); // the input's order, for the sub-problem's fill-in
    for(int t : tet_ids) {
      const Tet& k = m_tets[std::size_t(t)];
      P.tets.push_back({{ local_index(P, k[0]), local_index(P, k[1]), local_index(P, k[2]), local_index(P, k[3]) }});
      P.target.push_back(m_target[std::size_t(t)]);
    }
    P.real_tets = P.tets.size();
    for(int v : members)
      for(int f : m_vertex_faces[std::size_t(v)])
        if(!m_face_taken[std::size_t(f)]) { m_face_taken[std::size_t(f)] = 1; face_ids.push_back(f); }
    std::sort(face_ids.begin(), face_ids.end());
    std::vector<std::array<int, 3> > faces;
    for(int fi : face_ids) {
      const auto& f = m_border_faces[std::size_t(fi)];
      faces.push_back({{ local_index(P, f[0]), local_index(P, f[1]), local_index(P, f[2]) }});
    }
    for(int t : tet_ids) m_tet_taken[std::size_t(t)] = 0;
    for(int f : face_ids) m_face_taken[std::size_t(f)] = 0;
    const int centre = int(P.x.size());
    P.x.push_back(m_o);
    P.reference.push_back(m_o);
    P.kind.push_back(2);
    P.cone_reference = P.x;
    for(const auto& f : faces) {
      P.tets.push_back({{ centre, f[0], f[1], f[2] }});
      P.target.push_back(m_cone_weight);
    }
  }

  // Untangles one region; its result, certified or not, is where the next
  // stage starts (the others did not move): success is checked on the whole.
  Untangle_outcome untangle_region(const std::vector<int>& members, std::size_t max_iterations)
  {
    Sub_problem P;
    make_sub_problem(members, P);
    // The callback counts the iterations of every region and stage.
    const std::size_t offset = m_total.iterations;
    std::function<bool(const Volume_iteration&)> counted;
    if(m_callback)
      counted = [&](const Volume_iteration& I) {
        Volume_iteration J = I;
        J.iteration += offset;
        return m_callback(J);
      };
    const Untangle_outcome out = Volume_untangler(P.x, P.tets, P.real_tets, P.kind, P.reference, P.cone_reference,
                                                  P.target, (std::min)(m_stage_cap, max_iterations - m_total.iterations),
                                                  counted).run();
    m_total.iterations += out.iterations;
    m_total.rounds += out.rounds;
    ++m_total.regions;
    for(std::size_t i = 0; i < P.global.size(); ++i) {
      m_x[std::size_t(P.global[i])] = P.x[i];
      m_local[std::size_t(P.global[i])] = -1;
    }
    return out;
  }

  std::vector<Vec3>& m_x;
  const std::vector<Tet>& m_tets;
  const std::vector<char>& m_on_border;
  const std::vector<std::array<int, 3> >& m_border_faces;
  const std::vector<Vec3>& m_reference;
  const std::vector<double>& m_target;
  const std::function<bool(const Volume_iteration&)>& m_callback;
  // A stage cut short hands a half-untangled region to the next one, where
  // ε starts afresh; long stages untangled triceratops and armadillo where
  // four of 3,000 iterations did not.
  const std::size_t m_stage_cap = 10000;
  const Vec3 m_o = {{ 0, 0, 0 }};
  double m_cone_weight = 0;
  std::vector<std::vector<int> > m_vertex_tets, m_vertex_faces;
  std::vector<int> m_region, m_local;
  std::vector<char> m_movable, m_tet_taken, m_face_taken;
  Untangle_outcome m_total;
};

/// Untangles `x` (see the file comment). `reference`: the input positions;
/// `target`: the tets' target weights. Returns success when every tet and
/// border triangle is positive (exact).
inline Untangle_outcome untangle_volume(std::vector<Vec3>& x, const std::vector<Tet>& tets,
                                        const std::vector<char>& on_border,
                                        const std::vector<std::array<int, 3> >& border_faces,
                                        const std::vector<Vec3>& reference, const std::vector<double>& target,
                                        std::size_t max_iterations,
                                        const std::function<bool(const Volume_iteration&)>& callback)
{
  // Folds are local: the vertices within k rings of a fold move, the rest
  // stay (k = 1, then 3, 6, 12, then every vertex; a stage starts where the
  // last one left off, from the folds left). The movable vertices fall into
  // connected regions (two movable vertices of one tet are in one region),
  // and each region is untangled on its own with its neighbours held: the
  // regions' energies share no term, so this is the same problem, but every
  // region gets its own steps, ε and stop. Together, the region hardest to
  // untangle held every other one at its small steps, and each of its
  // iterations cost all the regions (doc/volume.md, "The certified start at
  // 1M tetrahedra"). One ring first: at 1M tets the 3-ring regions of
  // nearby folds merged into regions of 55K and 126K tets, the 1-ring ones
  // stay below 24K and all untangled with their neighbours held. Tets and
  // cones outside every region keep their positive (exact) orientation:
  // every fold seeds a region. The border triangles enter as cone tets
  // (O, a, b, c) on a fixed vertex at the centre: their barrier keeps the
  // border star-shaped. Their reference is the start (the spherical map,
  // positive), their weight a small share.
  return Volume_region_untangling(x, tets, on_border, border_faces, reference, target, callback).run(max_iterations);
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
