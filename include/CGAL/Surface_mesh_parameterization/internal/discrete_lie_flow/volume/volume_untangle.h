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

/// The untangling on tets `tets` (the first `real_tets` are the mesh's,
/// the others cone tets on the fixed centre vertex, whose reference shape is
/// taken from `cone_reference`).
inline Untangle_outcome untangle_volume_impl(std::vector<Vec3>& x, const std::vector<Tet>& tets, std::size_t real_tets,
                                             const std::vector<char>& on_border,
                                             const std::vector<std::array<int, 3> >& border_faces,
                                             const std::vector<Vec3>& reference,
                                             const std::vector<Vec3>& cone_reference, const std::vector<double>& target,
                                             std::size_t max_iterations,
                                             const std::function<bool(const Volume_iteration&)>& callback)
{
  typedef std::chrono::steady_clock Clock;
  const Clock::time_point start = Clock::now();
  const std::size_t V = x.size(), T = tets.size();
  const double theta = 0.25;
  Untangle_outcome out;
  // Per tet: A = (s R)⁻¹ with R the reference edge matrix scaled so that det(sR) is the target share of U.
  std::vector<Eigen::Matrix3d> A(T);
  std::vector<double> detA(T), weight(T);
  {
    double U = 0, Tsum = 0;
    std::vector<double> u;
    tet_dets(x, tets, u);
    for(std::size_t t = 0; t < real_tets; ++t) U += u[t];
    for(std::size_t t = 0; t < T; ++t) Tsum += target[t];
    for(std::size_t t = 0; t < T; ++t) {
      const Tet& k = tets[t];
      const std::vector<Vec3>& P = t < real_tets ? reference : cone_reference;
      Eigen::Matrix3d R;
      for(int j = 0; j < 3; ++j)
        for(int c = 0; c < 3; ++c)
          R(c, j) = P[std::size_t(k[std::size_t(j + 1)])][std::size_t(c)] - P[std::size_t(k[0])][std::size_t(c)];
      const double share = target[t] / Tsum;
      const double s = std::cbrt(share * U / R.determinant());
      A[t] = (s * R).inverse();
      detA[t] = A[t].determinant();
      weight[t] = share;
    }
  }
  // The L-BFGS's initial inverse Hessian γ L⁻¹, L the stiffness of the
  // shape term at the reference: Σ_t weight_t B_t B_tᵀ, the rows of B_t the
  // gradients of the tet's barycentric coordinates in its scaled reference
  // (∇β_1…∇β_3 the rows of A, ∇β_0 minus their sum), one scalar matrix for
  // the three coordinates, the fixed vertices eliminated; factorised once.
  // On Mesh_3's graded meshes it makes the steps independent of the
  // element sizes, which plain L-BFGS's are not.
  std::vector<int> dof(V, -1);
  int ndof = 0;
  for(std::size_t v = 0; v < V; ++v) if(on_border[v] != 2) dof[v] = ndof++;
  Default_spd_solver stiffness;
  Sparse_matrix L; // lower triangle
  bool preconditioned = false;
  if(ndof > 0) {
    std::vector<Eigen::Triplet<double> > entries;
    std::vector<double> diagonal(std::size_t(ndof), 0.);
    for(std::size_t t = 0; t < T; ++t) {
      const Tet& k = tets[t];
      Eigen::Matrix<double, 4, 3> B; // rows: ∇β_0 … ∇β_3
      B.block<3, 3>(1, 0) = A[t];
      B.row(0) = -(A[t].row(0) + A[t].row(1) + A[t].row(2));
      const Eigen::Matrix4d K = weight[t] * B * B.transpose();
      for(int a = 0; a < 4; ++a) {
        const int i = dof[std::size_t(k[std::size_t(a)])];
        if(i < 0) continue;
        for(int b = 0; b < 4; ++b) {
          const int j = dof[std::size_t(k[std::size_t(b)])];
          if(j >= 0 && j <= i) entries.emplace_back(i, j, K(a, b));
        }
        diagonal[std::size_t(i)] += K(a, a);
      }
    }
    for(int i = 0; i < ndof; ++i) entries.emplace_back(i, i, 1e-8 * diagonal[std::size_t(i)] + 1e-300);
    L.resize(ndof, ndof);
    L.setFromTriplets(entries.begin(), entries.end());
    stiffness.compute(L);
    preconditioned = stiffness.info() == Eigen::Success;
  }
  // dir ← P L⁻¹ P dir (P: the tangent planes of the border vertices).
  Eigen::MatrixXd rhs;
  auto apply_stiffness_inverse = [&](std::vector<Vec3>& dir) {
    rhs.resize(ndof, 3);
    for(std::size_t v = 0; v < V; ++v)
      if(dof[v] >= 0) for(int c = 0; c < 3; ++c) rhs(dof[v], c) = dir[v][std::size_t(c)];
    const Eigen::MatrixXd sol = stiffness.solve(rhs);
    for(std::size_t v = 0; v < V; ++v)
      if(dof[v] >= 0) for(int c = 0; c < 3; ++c) dir[v][std::size_t(c)] = sol(dof[v], c);
      else dir[v] = {{ 0, 0, 0 }};
  };
  // sᵀ L s, for the scale of H₀ = γ L⁻¹: γ = sᵀLs / sᵀy (the curvature along
  // s over the stiffness's), without a second solve.
  auto stiffness_norm = [&](const std::vector<Vec3>& sk) {
    Eigen::MatrixXd S(ndof, 3);
    for(std::size_t v = 0; v < V; ++v)
      if(dof[v] >= 0) for(int c = 0; c < 3; ++c) S(dof[v], c) = sk[v][std::size_t(c)];
    const Eigen::MatrixXd LS = L.selfadjointView<Eigen::Lower>() * S;
    return (S.array() * LS.array()).sum();
  };
  // Energy and gradient (per vertex, ambient) at fixed ε.
  std::vector<double> dets(T);
  auto evaluate = [&](const std::vector<Vec3>& y, double eps, std::vector<Vec3>* grad) {
    double E = 0;
    if(grad) grad->assign(V, Vec3{{ 0, 0, 0 }});
    for(std::size_t t = 0; t < T; ++t) {
      const Tet& k = tets[t];
      const Vec3& a = y[std::size_t(k[0])];
      Eigen::Matrix3d X;
      for(int j = 0; j < 3; ++j)
        for(int c = 0; c < 3; ++c) X(c, j) = y[std::size_t(k[std::size_t(j + 1)])][std::size_t(c)] - a[std::size_t(c)];
      const Eigen::Matrix3d J = X * A[t];
      const double d = X.determinant() * detA[t];
      dets[t] = d;
      const double chi = Volume_energy::chi(d, eps), dchi = Volume_energy::dchi(d, eps);
      if(!(chi > 0)) return std::numeric_limits<double>::infinity();
      const double s = J.squaredNorm();
      const double c23 = std::cbrt(chi * chi);
      const double f = s / c23, g = (d * d + 1) / chi;
      E += weight[t] * ((1 - theta) * f + theta * g);
      if(!grad) continue;
      // ∂/∂X: shape 2 J Aᵀ / χ^{2/3}; determinant terms times ∂d/∂X = detA·cof(X).
      const double df_dd = -(2. / 3.) * s * dchi / (c23 * chi);
      const double dg_dd = 2 * d / chi - (d * d + 1) * dchi / (chi * chi);
      const double dd = weight[t] * ((1 - theta) * df_dd + theta * dg_dd) * detA[t];
      const Eigen::Matrix3d GS = weight[t] * (1 - theta) * 2 * J * A[t].transpose() / c23;
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
  };
  auto project = [&](const std::vector<Vec3>& y, std::vector<Vec3>& g) {
    for(std::size_t v = 0; v < V; ++v)
      if(on_border[v] == 2) {
        g[v] = {{ 0, 0, 0 }};
      } else if(on_border[v]) {
        const Vec3 n = normalized(y[v]);
        const double k = dot(g[v], n);
        for(int c = 0; c < 3; ++c) g[v][std::size_t(c)] -= k * n[std::size_t(c)];
      }
  };
  auto inner = [](const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
    double s = 0;
    for(std::size_t i = 0; i < a.size(); ++i) s += dot(a[i], b[i]);
    return s;
  };
  auto certified = [&](const std::vector<Vec3>& y) {
    for(double d : dets) if(!(d > 0)) return false;
    return count_bad_tets(y, tets).not_positive() == 0;
  };
  (void)border_faces; // in `tets` as cone tets
  std::vector<Vec3> g, g_new, dir, y(V);
  double E = evaluate(x, 1, nullptr); // fills dets
  double dmin = *std::min_element(dets.begin(), dets.end());
  const double mu0 = 0.1;
  // ε at most a tenth of the target determinant (1): with a larger ε the
  // energy hardly sees the small determinants, and the shape term, which
  // rewards shrinking, pushes the tets that are too small through zero.
  double eps = (std::min)(0.1, dmin < mu0 ? 2 * std::sqrt(mu0 * (mu0 - dmin)) : 1e-3);
  bool polishing = false;
  std::size_t polished = 0;
  std::vector<Vec3> certified_x;
  // A round that accepts no step leaves x and, but for ε, everything as it
  // was: three in a row end the attempt (else the loop would not end).
  int idle_rounds = 0;
  while(out.iterations < max_iterations && idle_rounds < 3) {
    if(polishing) break;
    ++out.rounds;
    const std::size_t round_start = out.iterations;
    E = evaluate(x, eps, &g);
    project(x, g);
    const double E_round = E;
    std::deque<std::pair<std::vector<Vec3>, std::vector<Vec3> > > memory; // (s_k, y_k)
    std::deque<double> memory_sls; // s_kᵀ L s_k
    for(int it = 0; it < 200 && out.iterations < max_iterations; ++it) {
      // Two-loop recursion.
      dir = g;
      std::vector<double> alpha(memory.size());
      for(std::size_t m = memory.size(); m-- > 0;) {
        const double rho = 1 / inner(memory[m].second, memory[m].first);
        alpha[m] = rho * inner(memory[m].first, dir);
        for(std::size_t i = 0; i < V; ++i)
          for(int c = 0; c < 3; ++c) dir[i][std::size_t(c)] -= alpha[m] * memory[m].second[i][std::size_t(c)];
      }
      if(preconditioned) {
        project(x, dir);
        apply_stiffness_inverse(dir);
        project(x, dir);
        if(!memory.empty()) {
          const double gamma = memory_sls.back() / inner(memory.back().first, memory.back().second);
          for(Vec3& v : dir) for(double& c : v) c *= gamma;
        }
      } else if(!memory.empty()) {
        const double gamma = inner(memory.back().first, memory.back().second) / inner(memory.back().second, memory.back().second);
        for(Vec3& v : dir) for(double& c : v) c *= gamma;
      }
      for(std::size_t m = 0; m < memory.size(); ++m) {
        const double rho = 1 / inner(memory[m].second, memory[m].first);
        const double beta = rho * inner(memory[m].second, dir);
        for(std::size_t i = 0; i < V; ++i)
          for(int c = 0; c < 3; ++c) dir[i][std::size_t(c)] += (alpha[m] - beta) * memory[m].first[i][std::size_t(c)];
      }
      for(Vec3& v : dir) for(double& c : v) c = -c;
      project(x, dir);
      double slope = inner(g, dir);
      if(!(slope < 0)) { // not a descent direction: the gradient
        memory.clear();
        memory_sls.clear();
        dir = g;
        for(Vec3& v : dir) for(double& c : v) c = -c;
        slope = inner(g, dir);
      }
      double dmax = 0;
      for(const Vec3& v : dir) dmax = (std::max)(dmax, norm3(v));
      if(!(dmax > 0)) break;
      double step = (std::min)(1., 0.05 / dmax);
      if(memory.empty()) step = (std::min)(step, 0.01 / dmax);
      double E_new = E;
      bool ok = false;
      for(int tries = 0; tries < 40; ++tries, step *= 0.5) {
        for(std::size_t v = 0; v < V; ++v) {
          const Vec3 p = {{ x[v][0] + step * dir[v][0], x[v][1] + step * dir[v][1], x[v][2] + step * dir[v][2] }};
          y[v] = on_border[v] == 1 ? normalized(p) : p;
        }
        E_new = evaluate(y, eps, &g_new);
        if(E_new <= E + 1e-4 * step * slope) { ok = true; break; }
      }
      if(!ok) break;
      ++out.iterations;
      project(y, g_new);
      std::vector<Vec3> sk(V), yk(V);
      for(std::size_t v = 0; v < V; ++v) {
        sk[v] = sub(y[v], x[v]);
        yk[v] = sub(g_new[v], g[v]);
      }
      if(inner(sk, yk) > 1e-300) {
        if(preconditioned) {
          memory_sls.push_back(stiffness_norm(sk));
          if(memory_sls.size() > 8) memory_sls.pop_front();
        }
        memory.emplace_back(std::move(sk), std::move(yk));
        if(memory.size() > 8) memory.pop_front();
      }
      x.swap(y);
      g.swap(g_new);
      const double drop = (E - E_new) / std::abs(E);
      E = E_new;
      std::size_t negative = 0;
      for(double d : dets) negative += (d <= 0);
      if(callback) {
        Volume_iteration I;
        I.iteration = out.iterations;
        I.step = step;
        I.d_vol = E;
        I.epsilon = eps;
        I.untangling = true;
        I.negative_tets = negative;
        I.seconds = std::chrono::duration<double>(Clock::now() - start).count();
        if(!callback(I)) { out.stopped = true; return out; }
      }
      if(polishing) {
        if(out.iterations % 10 == 0 && certified(x)) certified_x = x;
        if(drop < 1e-5 || ++polished >= 200) break;
        continue;
      }
      if(negative == 0 && certified(x)) {
        // Untangled. Then the pure barrier (ε = 0) from there for a while:
        // it moves every tet and border triangle away from flat, which
        // leaves the flow room to move.
        out.success = true;
        certified_x = x;
        polishing = true;
        eps = 0;
        E = evaluate(x, eps, &g);
        project(x, g);
        memory.clear();
        memory_sls.clear();
        continue;
      }
      if(drop < 1e-6) break;
    }
    idle_rounds = out.iterations == round_start ? idle_rounds + 1 : 0;
    // The next ε.
    evaluate(x, eps, nullptr);
    dmin = *std::min_element(dets.begin(), dets.end());
    const double sigma = (std::max)(0.1, 1 - E / E_round);
    const double mu = (1 - sigma) * Volume_energy::chi(dmin, eps);
    eps = (std::min)(0.1, dmin < mu ? 2 * std::sqrt(mu * (mu - dmin)) : 1e-10);
    if(polishing) break;
    if(dmin > 0 && certified(x)) { out.success = true; return out; }
  }
  if(polishing) {
    if(certified(x)) certified_x = x;
    x.swap(certified_x);
    return out;
  }
  out.success = certified(x);
  return out;
}

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
  const std::size_t V = x.size(), T = tets.size();
  double Tsum = 0;
  for(double a : target) Tsum += a;
  const double cone_weight = 0.1 * Tsum / double((std::max)(border_faces.size(), std::size_t(1)));
  std::vector<std::vector<int> > vertex_tets(V), vertex_faces(V);
  for(std::size_t t = 0; t < T; ++t)
    for(int v : tets[t]) vertex_tets[std::size_t(v)].push_back(int(t));
  for(std::size_t f = 0; f < border_faces.size(); ++f)
    for(int v : border_faces[f]) vertex_faces[std::size_t(v)].push_back(int(f));
  Untangle_outcome total;
  // A stage cut short hands a half-untangled region to the next one, where
  // ε starts afresh; long stages untangled triceratops and armadillo where
  // four of 3,000 iterations did not.
  const std::size_t stage_cap = 10000;
  const Vec3 o = {{ 0, 0, 0 }};
  std::vector<int> region(V, -1), local(V, -1);
  std::vector<char> tet_taken(T, 0), face_taken(border_faces.size(), 0);
  for(int rings : { 1, 3, 6, 12, -1 }) {
    if(total.iterations >= max_iterations) break;
    // The folded tets' and cones' vertices, grown by `rings` rings.
    std::vector<char> movable(V, 0);
    std::vector<int> front;
    for(const Tet& k : tets)
      if(exact_tet_orientation(x[std::size_t(k[0])], x[std::size_t(k[1])], x[std::size_t(k[2])], x[std::size_t(k[3])]) != POSITIVE)
        for(int v : k) if(!movable[std::size_t(v)]) { movable[std::size_t(v)] = 1; front.push_back(v); }
    for(const auto& f : border_faces)
      if(exact_tet_orientation(o, x[std::size_t(f[0])], x[std::size_t(f[1])], x[std::size_t(f[2])]) != POSITIVE)
        for(int v : f) if(!movable[std::size_t(v)]) { movable[std::size_t(v)] = 1; front.push_back(v); }
    if(front.empty()) { total.success = true; return total; }
    if(rings < 0) std::fill(movable.begin(), movable.end(), 1);
    for(int r = 0; r < rings; ++r) {
      std::vector<int> next;
      for(int v : front)
        for(int t : vertex_tets[std::size_t(v)])
          for(int w : tets[std::size_t(t)])
            if(!movable[std::size_t(w)]) { movable[std::size_t(w)] = 1; next.push_back(w); }
      front.swap(next);
    }
    // The connected regions of movable vertices.
    std::fill(region.begin(), region.end(), -1);
    std::vector<std::vector<int> > regions;
    for(std::size_t s = 0; s < V; ++s) {
      if(!movable[s] || region[s] >= 0) continue;
      std::vector<int> members(1, int(s));
      region[s] = int(regions.size());
      for(std::size_t i = 0; i < members.size(); ++i)
        for(int t : vertex_tets[std::size_t(members[i])])
          for(int w : tets[std::size_t(t)])
            if(movable[std::size_t(w)] && region[std::size_t(w)] < 0) {
              region[std::size_t(w)] = region[s];
              members.push_back(w);
            }
      regions.push_back(std::move(members));
    }
    bool all_certified = true;
    for(const std::vector<int>& members : regions) {
      if(total.iterations >= max_iterations) { all_certified = false; break; }
      // The sub-problem: the tets with a vertex in the region, their
      // vertices (the others fixed), the border triangles with a vertex in
      // the region as cones.
      std::vector<int> global;
      std::vector<Tet> te;
      std::vector<double> ge;
      std::vector<Vec3> xe, refe, cone_ref;
      std::vector<char> kind;
      std::vector<int> tet_ids, face_ids;
      auto index = [&](int v) {
        if(local[std::size_t(v)] < 0) {
          local[std::size_t(v)] = int(global.size());
          global.push_back(v);
          xe.push_back(x[std::size_t(v)]);
          refe.push_back(reference[std::size_t(v)]);
          kind.push_back(movable[std::size_t(v)] ? char(on_border[std::size_t(v)] ? 1 : 0) : char(2));
        }
        return local[std::size_t(v)];
      };
      for(int v : members)
        for(int t : vertex_tets[std::size_t(v)])
          if(!tet_taken[std::size_t(t)]) { tet_taken[std::size_t(t)] = 1; tet_ids.push_back(t); }
      std::sort(tet_ids.begin(), tet_ids.end()); // the input's order, for the sub-problem's fill-in
      for(int t : tet_ids) {
        const Tet& k = tets[std::size_t(t)];
        te.push_back({{ index(k[0]), index(k[1]), index(k[2]), index(k[3]) }});
        ge.push_back(target[std::size_t(t)]);
      }
      const std::size_t real_tets = te.size();
      for(int v : members)
        for(int f : vertex_faces[std::size_t(v)])
          if(!face_taken[std::size_t(f)]) { face_taken[std::size_t(f)] = 1; face_ids.push_back(f); }
      std::sort(face_ids.begin(), face_ids.end());
      std::vector<std::array<int, 3> > faces;
      for(int fi : face_ids) {
        const auto& f = border_faces[std::size_t(fi)];
        faces.push_back({{ index(f[0]), index(f[1]), index(f[2]) }});
      }
      for(int t : tet_ids) tet_taken[std::size_t(t)] = 0;
      for(int f : face_ids) face_taken[std::size_t(f)] = 0;
      const int centre = int(xe.size());
      xe.push_back(o);
      refe.push_back(o);
      kind.push_back(2);
      cone_ref = xe;
      for(const auto& f : faces) {
        te.push_back({{ centre, f[0], f[1], f[2] }});
        ge.push_back(cone_weight);
      }
      // The callback counts the iterations of every region and stage.
      const std::size_t offset = total.iterations;
      std::function<bool(const Volume_iteration&)> counted;
      if(callback)
        counted = [&](const Volume_iteration& I) {
          Volume_iteration J = I;
          J.iteration += offset;
          return callback(J);
        };
      const Untangle_outcome out = untangle_volume_impl(xe, te, real_tets, kind, faces, refe, cone_ref, ge,
                                                        (std::min)(stage_cap, max_iterations - total.iterations),
                                                        counted);
      total.iterations += out.iterations;
      total.rounds += out.rounds;
      ++total.regions;
      // The region's result, certified or not, is where the next stage
      // starts (the others did not move); success is checked on the whole.
      for(std::size_t i = 0; i < global.size(); ++i) {
        x[std::size_t(global[i])] = xe[i];
        local[std::size_t(global[i])] = -1;
      }
      if(out.stopped) { total.stopped = true; return total; }
      all_certified = all_certified && out.success;
    }
    if(all_certified) {
      total.success = true;
      return total;
    }
  }
  return total;
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
