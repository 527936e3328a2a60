// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The paper's flow on the unit sphere (Algorithm 1 with its §5.3 gradient
// decomposition): Delaunay flips of the flowing spherical triangulation, the
// Poisson solve L h = A_Ω − A_M with the cotangent stiffness of the flat
// triangles between the sphere points, area-weighted vertex gradients with
// their normal component removed, re-normalised points, and the adaptive
// step μ·(smallest positive root of the per-face orientation cubics),
// certified on the flowing triangulation by the exact orientation(O, p, q, r)
// plus a degeneracy guard. The choices of the planar paper mode
// (paper_flow.h) carry over: targets lumped on the flowing faces, best
// iterate, D_area plateau, stall detector.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_SPHERE_PAPER_FLOW_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_SPHERE_PAPER_FLOW_H

#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/certification.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/cotangent_laplacian.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/critical_step.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/disk_problem.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/sphere_edge_flips.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/sphere_flow.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/sphere_problem.h>

#include <Eigen/Sparse>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// What the paper's flow on the sphere returns besides the points.
struct Sphere_paper_outcome : Flow_outcome
{
  std::vector<Face> flowing;          ///< the final flowing triangulation
  std::vector<double> flowing_target; ///< its targets (the input's on unchanged faces)
  std::size_t non_delaunay_edges = 0; ///< edges of `flowing` left non-Delaunay (0 with flips on)
};

/// Per-vertex density, the area-weighted mean of the incident faces'
/// ρ = target / area_M, used to weigh triangles created by flips.
inline std::vector<double> sphere_vertex_density(const Sphere_problem& P)
{
  std::vector<double> num(P.xyz.size(), 0.), den(P.xyz.size(), 0.);
  for(std::size_t f = 0; f < P.faces.size(); ++f) {
    const Face& t = P.faces[f];
    const double a = triangle_area_3(P.xyz[std::size_t(t[0])], P.xyz[std::size_t(t[1])], P.xyz[std::size_t(t[2])]);
    for(int k = 0; k < 3; ++k) { num[std::size_t(t[k])] += P.target[f]; den[std::size_t(t[k])] += a; }
  }
  for(std::size_t v = 0; v < num.size(); ++v) num[v] = den[v] > 0 ? num[v] / den[v] : 1.;
  return num;
}

/// Gradient of the P1 function with values h at the corners of the flat
/// triangle (p0, p1, p2) in 3D: Σ_k h_k N × (p_{k+2} − p_{k+1}) / |N|², with
/// N = (p1 − p0) × (p2 − p0) (the planar rot90 formula in the triangle's plane).
inline Vec3 p1_gradient_3(const Vec3& p0, const Vec3& p1, const Vec3& p2, double h0, double h1, double h2)
{
  const Vec3 N = cross(sub(p1, p0), sub(p2, p0));
  const double nn = dot(N, N);
  const Vec3 g = cross(N, Vec3{{ h0 * (p2[0] - p1[0]) + h1 * (p0[0] - p2[0]) + h2 * (p1[0] - p0[0]),
                                 h0 * (p2[1] - p1[1]) + h1 * (p0[1] - p2[1]) + h2 * (p1[1] - p0[1]),
                                 h0 * (p2[2] - p1[2]) + h1 * (p0[2] - p2[2]) + h2 * (p1[2] - p0[2]) }});
  return {{ g[0] / nn, g[1] / nn, g[2] / nn }};
}

/// Runs the paper's flow from the positively oriented unit vectors `p`. On
/// return, `p` is the best iterate (lowest D_area on the flowing
/// triangulation, flat triangles between the sphere points) and
/// `out.flowing` its triangulation, flipped once more to be Delaunay where
/// it stands. Every face of every accepted flowing triangulation is
/// positively oriented by the exact predicate.
template <class EigenSolver>
Sphere_paper_outcome paper_sphere_flow(const Sphere_problem& P, std::vector<Vec3>& p,
                                       const Discrete_lie_flow_options& opt, EigenSolver& eigen_solver)
{
  typedef std::chrono::steady_clock Clock;
  const Clock::time_point start = Clock::now();
  Sphere_paper_outcome out;
  const std::size_t n = p.size();
  const double mu = opt.mu > 0 ? opt.mu : 0.8;
  Pattern_reusing_solver<EigenSolver> solver(eigen_solver);
  Flip_triangulation tri(P.faces);
  const std::size_t max_flips = 100 * P.faces.size() + 100;

  // Targets of the flowing faces: the input's as long as a face is unchanged,
  // ρ × the 3D triangle between its vertices once a flip created it.
  const std::vector<double> rho = sphere_vertex_density(P);
  std::vector<double> target = P.target;
  const double min_target = *std::min_element(P.target.begin(), P.target.end());
  auto target_of = [&](const Face& t) {
    const double a = triangle_area_3(P.xyz[std::size_t(t[0])], P.xyz[std::size_t(t[1])], P.xyz[std::size_t(t[2])]) *
                     (rho[std::size_t(t[0])] + rho[std::size_t(t[1])] + rho[std::size_t(t[2])]) / 3;
    return (std::max)(a, 1e-3 * min_target); // guard flat 3D triangles
  };
  auto retarget = [&](int f) { target[std::size_t(f)] = target_of(tri.faces[std::size_t(f)]); };
  std::vector<double> literal_AM;
  lump_on_vertices(n, P.faces, P.target, literal_AM);
  auto converged = [&](double D, const std::vector<Vec3>& x, const std::vector<Face>& faces, const std::vector<double>& t) {
    return D - 2 <= opt.tolerance &&
           (!(opt.log_area_tolerance > 0) || flat_mean_abs_log_ratio(x, faces, t) <= opt.log_area_tolerance);
  };

  std::vector<double> u, AO, AM, u_trial;
  signed_areas_sphere(p, tri.faces, u);
  double d_area = d_area_of(u, target);
  out.initial_d_area = out.final_d_area = d_area;
  std::vector<Vec3> best_p = p, trial(n), grad(n), d(n);
  Flip_triangulation best_tri = tri;
  std::vector<double> best_target = target;
  double best = d_area;
  bool best_converged = converged(best, p, tri.faces, target);
  // The plateau test watches the iterates' own best: the first flips change
  // the targets, so the start's D_area (on the input triangulation) may stay
  // the lowest for a while as the flow descends (oblong.off: 35.5 at the
  // start, 59.6 after the first flips and step, then down again).
  double best_iterate = infinite_step();
  std::vector<double> best_history;
  std::vector<double> wsum(n);
  int last_limiting = -1;
  std::size_t same_limiting = 0;

  out.stop_reason = Discrete_lie_flow_stop_reason::ITERATION_CAP;
  for(std::size_t it = 1; it <= opt.max_iterations; ++it) {
    if(best_converged) { out.stop_reason = Discrete_lie_flow_stop_reason::CONVERGED; break; }
    Clock::time_point tic = Clock::now();
    std::size_t flips = 0;
    if(opt.delaunay_flips) flips = make_delaunay_sphere(tri, p, [&](int f) { retarget(f); }, max_flips);
    out.flips += flips;
    if(flips > 0) signed_areas_sphere(p, tri.faces, u);

    // Area elements and the Poisson problem L h = A_Ω − A_M (closed surface:
    // pin h_0 = 0; the right-hand side sums to zero).
    lump_on_vertices(n, tri.faces, u, AO);
    if(opt.lump_targets_on_flowing_faces) lump_on_vertices(n, tri.faces, target, AM);
    else AM = literal_AM;
    double so = 0, sm = 0;
    for(std::size_t i = 0; i < n; ++i) { so += AO[i]; sm += AM[i]; }
    Eigen::VectorXd rhs(Eigen::Index(n - 1));
    for(std::size_t i = 1; i < n; ++i) rhs[Eigen::Index(i - 1)] = AO[i] - AM[i] * so / sm;
    const Sparse_matrix L = sphere_sobolev_matrix(p, tri.faces, 0.); // cotangent stiffness alone
    const Sparse_matrix Lr = L.bottomRightCorner(Eigen::Index(n - 1), Eigen::Index(n - 1));
    Clock::time_point toc = Clock::now();
    out.seconds_assembly += std::chrono::duration<double>(toc - tic).count();
    Eigen::VectorXd h_red;
    ++out.factorizations;
    const bool solved = solver.factorize(Lr) && solver.solve(rhs, h_red);
    tic = Clock::now();
    out.seconds_solve += std::chrono::duration<double>(tic - toc).count();
    if(!solved) {
      out.solver_failed = true;
      out.stop_reason = Discrete_lie_flow_stop_reason::STALLED;
      break;
    }
    std::vector<double> h(n, 0.);
    for(std::size_t i = 1; i < n; ++i) h[i] = h_red[Eigen::Index(i - 1)];

    // Vertex gradients: area-weighted mean of the faces' constant gradients,
    // then the normal component removed (§5.3: ∇h∥ = ∇h − ⟨∇h, n⟩ n).
    std::fill(grad.begin(), grad.end(), Vec3{{ 0, 0, 0 }});
    std::fill(wsum.begin(), wsum.end(), 0.);
    for(std::size_t t = 0; t < tri.faces.size(); ++t) {
      const Face& f = tri.faces[t];
      const std::size_t a = std::size_t(f[0]), b = std::size_t(f[1]), c = std::size_t(f[2]);
      const Vec3 gt = p1_gradient_3(p[a], p[b], p[c], h[a], h[b], h[c]);
      for(int k = 0; k < 3; ++k) {
        Vec3& gv = grad[std::size_t(f[k])];
        for(int j = 0; j < 3; ++j) gv[j] += u[t] * gt[j];
        wsum[std::size_t(f[k])] += u[t];
      }
    }
    for(std::size_t v = 0; v < n; ++v)
      for(int j = 0; j < 3; ++j) d[v][j] = grad[v][j] / wsum[v];
    project_to_tangent(p, d);

    int limiting = -1;
    double lambda_crit = infinite_step();
    for(std::size_t t = 0; t < tri.faces.size(); ++t) {
      const Face& f = tri.faces[t];
      const std::size_t a = std::size_t(f[0]), b = std::size_t(f[1]), c = std::size_t(f[2]);
      const double r = critical_step_sphere(p[a], p[b], p[c], d[a], d[b], d[c]);
      if(r < lambda_crit) { lambda_crit = r; limiting = int(t); }
    }
    double lambda = opt.fixed_step > 0 ? opt.fixed_step : (std::min)(opt.step_cap, mu * lambda_crit);

    // Shrink until every flowing face is positive (exact) and none collapses:
    // a face's share of the sphere may not fall below `degeneracy_ratio` times
    // its target share, nor, if the start already has it below, halve per step.
    double U = 0, T = 0;
    for(std::size_t t = 0; t < u.size(); ++t) { U += u[t]; T += target[t]; }
    bool accepted = false;
    std::size_t halvings = 0;
    for(; halvings <= opt.max_backtracks; ++halvings, lambda *= 0.5) {
      for(std::size_t v = 0; v < n; ++v)
        trial[v] = normalized(Vec3{{ p[v][0] + lambda * d[v][0], p[v][1] + lambda * d[v][1], p[v][2] + lambda * d[v][2] }});
      signed_areas_sphere(trial, tri.faces, u_trial);
      double U_trial = 0;
      bool ok = true;
      for(std::size_t t = 0; t < u_trial.size() && ok; ++t) { ok = u_trial[t] > 0; U_trial += u_trial[t]; }
      for(std::size_t t = 0; t < u_trial.size() && ok; ++t)
        ok = (u_trial[t] / U_trial) >= (std::min)(opt.degeneracy_ratio * (target[t] / T), 0.5 * (u[t] / U));
      if(!ok) continue;
      if(!count_orientations_sphere(trial, tri.faces, true).all_positive()) { ++out.rejected_by_exact_check; continue; }
      accepted = true;
      break;
    }
    out.seconds_step += std::chrono::duration<double>(Clock::now() - tic).count();
    // A fixed step that would fold is the paper's "collapse".
    if(!accepted || (opt.fixed_step > 0 && halvings > 0)) {
      out.stop_reason = Discrete_lie_flow_stop_reason::STALLED;
      break;
    }
    p.swap(trial);
    u.swap(u_trial);
    d_area = d_area_of(u, target);
    out.iterations = it;
    if(d_area < best) {
      best = d_area;
      best_p = p;
      best_tri = tri;
      best_target = target;
      best_converged = converged(best, p, tri.faces, target);
    }
    best_iterate = (std::min)(best_iterate, d_area);
    best_history.push_back(best_iterate);

    if(!record_iteration(opt, it, lambda, lambda_crit, limiting, d_area, halvings, flips,
                         std::chrono::duration<double>(Clock::now() - start).count(),
                         [&] { return area_residual(n, tri.faces, u, target); }, out))
      break;

    if(best_converged) { out.stop_reason = Discrete_lie_flow_stop_reason::CONVERGED; break; }
    // Stall: the same triangle limits the step again and again while the
    // step is far below the cap (a vertex driven onto an edge).
    if(limiting == last_limiting && lambda < 1e-3 * opt.step_cap) ++same_limiting; else same_limiting = 0;
    last_limiting = limiting;
    if(same_limiting >= opt.stall_window) { out.stop_reason = Discrete_lie_flow_stop_reason::STALLED; break; }
    if(best_history.size() > opt.plateau_window) {
      const double old = best_history[best_history.size() - 1 - opt.plateau_window];
      if(old - best_iterate < opt.plateau_tolerance * (best_iterate - 1)) { out.stop_reason = Discrete_lie_flow_stop_reason::PLATEAU; break; }
    }
  }
  p = best_p;
  // The best triangulation was made Delaunay for the positions before its
  // step; flip once more so that the returned one is Delaunay where it is
  // (the new faces' targets raise D_area − 2 by 1–15% on CGAL's meshes),
  // unless that raises D_area − 2 by more than half: on a start compressed to
  // the rounding level (camel.off, e^30) in-circle decisions are rounding
  // noise and the flips multiplied D_area by 6; the best iterate is then
  // returned unflipped, its non-Delaunay edges counted.
  if(opt.delaunay_flips) {
    Flip_triangulation flipped = best_tri;
    std::vector<double> flipped_target = best_target;
    const std::size_t last = make_delaunay_sphere(flipped, p, [&](int f) {
      flipped_target[std::size_t(f)] = target_of(flipped.faces[std::size_t(f)]); }, max_flips);
    signed_areas_sphere(p, flipped.faces, u);
    const double D_flipped = d_area_of(u, flipped_target);
    if(last > 0 && D_flipped - 2 <= 1.5 * (best - 2)) {
      out.flips += last;
      best_tri = std::move(flipped);
      best_target.swap(flipped_target);
    }
  }
  out.non_delaunay_edges = count_non_delaunay_edges_sphere(best_tri, p);
  out.flowing = best_tri.faces;
  out.flowing_target = best_target;
  signed_areas_sphere(p, out.flowing, u);
  out.final_d_area = d_area_of(u, best_target);
  out.final_residual = area_residual(n, out.flowing, u, best_target);
  out.symbolic_analyses = solver.analyses();
  return out;
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
