// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The coarse-to-fine start of the certified spherical flow: coarser closed
// meshes made by independent half-edge collapses (core/vertex_relaxation.h:
// the link condition keeps genus 0, the removed faces' targets go to their
// ring), the coarsest one given its own certified start and flowed, its map
// carried down level by level (each removed vertex put back where its 3D
// ring puts it, its star checked by the exact predicate, the level's
// vertices swept), so that the caller's flow starts near its targets. A
// large mesh spends its plain flow's iterations at full resolution moving
// the smooth modes a coarse level moves for a fraction of the cost, and its
// Tutte start compresses the mesh by many decades (doc/sphere.md, "Coarse
// to fine").

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_SPHERE_COARSE_TO_FINE_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_SPHERE_COARSE_TO_FINE_H

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_options.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_report.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/area_barrier_energy.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/certification.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/morton_order.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/vertex_relaxation.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/flow/coarse_to_fine_levels.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/flow/flow_driver.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/sphere/sphere_certified_flow.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/sphere/sphere_initial_map.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/sphere/sphere_problem.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/sphere/sphere_relaxation.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>
#include <thread>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// Internal knobs of the sphere's coarse-to-fine start (doc/sphere.md,
/// "Coarse to fine"): the disk's, and how far a collapse may turn a face.
struct Sphere_coarse_to_fine_settings : Coarse_to_fine_settings
{
  /// A collapse keeps the 3D shape: each new face's normal within this
  /// cosine of the face it replaces (the targets are summed whatever the
  /// shape, but a folded coarse level is a poor model of the fine one).
  double least_normal_cosine = 0.5;
};

/// Whether the certified spherical flow on `faces` faces starts coarse to fine.
inline bool sphere_flows_coarse_to_fine(const Discrete_lie_flow_options& opt, std::size_t faces)
{
  return opt.mode == Discrete_lie_flow_mode::CERTIFIED && opt.fixed_step == 0 &&
         opt.sphere.start != Discrete_lie_flow_sphere_start::CONFORMAL && opt.sphere.coarse_to_fine_faces > 0 &&
         faces >= opt.sphere.coarse_to_fine_faces;
}

/// The levels of the closed mesh `P`, finest first, until one has at most
/// `coarsest` faces or a level removes too few vertices. No vertex is
/// fixed; a collapse keeps its new faces' 3D normals near the old ones'.
inline std::vector<Collapse_level> build_sphere_levels(const Sphere_problem& P, std::size_t coarsest,
                                                      const Sphere_coarse_to_fine_settings& s)
{
  const std::vector<Vec3>& x = P.xyz;
  const std::vector<char> fixed(x.size(), 0);
  const auto accept = [&x, &s](int v, int w, int a, int b) {
    const Vec3 &pv = x[std::size_t(v)], &pw = x[std::size_t(w)], &pa = x[std::size_t(a)], &pb = x[std::size_t(b)];
    const Vec3 n0 = cross(sub(pa, pv), sub(pb, pv)), n1 = cross(sub(pa, pw), sub(pb, pw));
    const double l = norm3(n0) * norm3(n1);
    return l > 0 && dot(n0, n1) > s.least_normal_cosine * l;
  };
  std::vector<Collapse_level> levels;
  std::size_t alive = x.size();
  for(;;) {
    const std::vector<Face>& F = levels.empty() ? P.faces : levels.back().faces;
    const std::vector<double>& T = levels.empty() ? P.target : levels.back().target;
    // A tetrahedron's collapse would leave two faces on the same corners.
    if(F.size() <= (std::max)(coarsest, std::size_t(4))) break;
    Collapse_level L;
    const std::size_t removed = coarsen_level(x.size(), F, T, x, fixed, accept, L);
    if(removed == 0) break;
    levels.push_back(std::move(L));
    if(double(removed) < s.least_removed * double(alive)) break;
    alive -= removed;
  }
  return levels;
}

/// Whether every face (x, ring[i], ring[i+1]) is positive on the sphere (exact predicate).
inline bool sphere_star_positive(const Vec3& x, const std::vector<Vec3>& ring)
{
  for(std::size_t i = 0; i < ring.size(); ++i)
    if(exact_orientation_sphere(x, ring[i], ring[(i + 1) % ring.size()]) != CGAL::POSITIVE) return false;
  return true;
}

/// Puts every vertex `D` removed back into its ring in `p` (the ring's
/// points are the coarser level's map): first where its 3D ring puts it
/// (the ring laid flat around it by angles scaled to 2π and lengths, the
/// vertex's barycentric coordinates in the fan triangle from the collapse's
/// target that holds it, applied to the ring's points on the sphere); else
/// at the centroid of the ring's kernel in the gnomonic plane of the ring's
/// mean direction (great circles are its straight lines). False when a
/// vertex finds no position with a positive star (exact predicate); `p`
/// then holds a map that must not be used.
inline bool prolong_sphere_level(const Collapse_decimation& D, const std::vector<Vec3>& xyz, std::vector<Vec3>& p)
{
  const double pi = 3.14159265358979323846;
  std::vector<Vec3> ring;
  std::vector<Vec2> flat, poly;
  std::vector<double> angle;
  for(std::size_t r = 0; r < D.removed.size(); ++r) {
    const std::size_t v = std::size_t(D.removed[r]);
    const std::size_t b = D.ring_first[r], k = D.ring_first[r + 1] - b;
    ring.resize(k);
    for(std::size_t i = 0; i < k; ++i) ring[i] = p[std::size_t(D.ring[b + i])];
    // The ring laid flat around v: angles scaled to a full turn.
    angle.assign(k + 1, 0);
    for(std::size_t i = 0; i < k; ++i) {
      const Vec3 e0 = sub(xyz[std::size_t(D.ring[b + i])], xyz[v]), e1 = sub(xyz[std::size_t(D.ring[b + (i + 1) % k])], xyz[v]);
      angle[i + 1] = angle[i] + std::atan2(norm3(cross(e0, e1)), dot(e0, e1));
    }
    flat.resize(k);
    for(std::size_t i = 0; i < k; ++i) {
      const double t = 2 * pi * angle[i] / angle[k], l = norm3(sub(xyz[std::size_t(D.ring[b + i])], xyz[v]));
      flat[i] = {{ l * std::cos(t), l * std::sin(t) }};
    }
    double best = -infinite_step();
    Vec3 q = ring[0];
    const Vec2 origin{{ 0, 0 }};
    for(std::size_t i = 1; i + 1 < k; ++i) {
      const double A = signed_area_2(flat[0], flat[i], flat[i + 1]);
      if(!(A > 0)) continue;
      const double l0 = signed_area_2(origin, flat[i], flat[i + 1]) / A, l1 = signed_area_2(flat[0], origin, flat[i + 1]) / A,
                   l2 = 1 - l0 - l1;
      const double least = (std::min)(l0, (std::min)(l1, l2));
      if(least > best) {
        best = least;
        for(int c = 0; c < 3; ++c)
          q[std::size_t(c)] = l0 * ring[0][std::size_t(c)] + l1 * ring[i][std::size_t(c)] + l2 * ring[i + 1][std::size_t(c)];
      }
    }
    if(norm3(q) > 0) {
      q = normalized(q);
      if(sphere_star_positive(q, ring)) { p[v] = q; continue; }
    }
    // The kernel in the gnomonic plane tangent at the ring's mean direction.
    Vec3 c{{ 0, 0, 0 }};
    for(const Vec3& y : ring) for(int j = 0; j < 3; ++j) c[std::size_t(j)] += y[std::size_t(j)];
    if(!(norm3(c) > 0)) return false;
    c = normalized(c);
    const Vec3 any = std::abs(c[0]) < 0.6 ? Vec3{{ 1, 0, 0 }} : Vec3{{ 0, 1, 0 }};
    const Vec3 e1 = normalized(cross(any, c)), e2 = cross(c, e1); // e1 × e2 = c: the sphere's orientation
    poly.resize(k);
    for(std::size_t i = 0; i < k; ++i) {
      const double h = dot(ring[i], c);
      if(!(h > 0)) return false;
      poly[i] = {{ dot(ring[i], e1) / h, dot(ring[i], e2) / h }};
    }
    Vec2 m;
    if(!kernel_centroid(poly, m)) return false;
    for(int j = 0; j < 3; ++j) q[std::size_t(j)] = c[std::size_t(j)] + m[0] * e1[std::size_t(j)] + m[1] * e2[std::size_t(j)];
    q = normalized(q);
    if(!sphere_star_positive(q, ring)) return false;
    p[v] = q;
  }
  return true;
}

/// Flows the coarsest level `L` of `P` from its own certified start (the
/// caller's start kind) and writes its map into `fine` at its vertices.
/// False when its start is not certified or its flow stalls.
template <class EigenSolver>
bool flow_coarsest_sphere_level(const Sphere_problem& P, const Collapse_level& L, const Discrete_lie_flow_options& opt,
                                const Sphere_coarse_to_fine_settings& s, std::vector<Vec3>& fine,
                                Discrete_lie_flow_level& level)
{
  Sphere_problem C;
  std::vector<int> index, vertex_of;
  C.faces = L.faces;
  C.target = L.target;
  renumber_coarsest_level(C.faces, P.xyz, C.xyz, index, vertex_of);
  std::vector<Vec3> q;
  const Sphere_initial_outcome init = certified_sphere_initial_map<EigenSolver>(
    C, q, false, 3, true, false, true, opt.sphere.start == Discrete_lie_flow_sphere_start::MEAN_VALUE);
  if(!init.certified) return false;
  const Discrete_lie_flow_options coarse = coarsest_level_options(opt, s);
  EigenSolver solver;
  Sphere_certified_flow<EigenSolver> flow(C, q, coarse, solver, Sphere_flow_settings());
  const Flow_outcome flowed = run_flow(flow, coarse);
  if(flowed.stop_reason == Discrete_lie_flow_stop_reason::STALLED || flowed.solver_failed) return false;
  for(std::size_t i = 0; i < vertex_of.size(); ++i) fine[std::size_t(vertex_of[i])] = q[i];
  level = coarsest_level_record(vertex_of.size(), C.faces.size(), flowed);
  return true;
}

/// Puts the vertices `D` removed back into `p` (prolong_sphere_level()) and
/// sweeps the finer level (`F`, `target`) with the polish's energy: its flat
/// D_area after, or NaN when a vertex found no position.
inline double carry_down_sphere_level(const Collapse_decimation& D, const std::vector<Face>& F,
                                      const std::vector<double>& target, const std::vector<Vec3>& xyz,
                                      const std::vector<std::size_t>& order, int threads, bool finest,
                                      const Discrete_lie_flow_options& opt, const Sphere_coarse_to_fine_settings& s,
                                      std::vector<Vec3>& p)
{
  if(!prolong_sphere_level(D, xyz, p)) return std::numeric_limits<double>::quiet_NaN();
  const std::size_t n = p.size();
  const Sphere_flow_settings flow;
  const Weighted_area_energy energy(target, flow.uniform_weight);
  std::vector<double> u, w;
  signed_areas_sphere(p, F, u);
  cone_areas_sphere(p, F, w);
  const Vertex_faces around(n, F);
  const double mu = step_fraction(opt);
  const double goal = 2 + (finest ? s.finest_goal_share : s.level_goal_share) * opt.tolerance;
  const auto measure = [&] { return flat_d_area(p, F, target); };
  return sweep_finer_level(
    order, F, around, D.removed, std::vector<char>(n, 1), finest, s,
    [&](const Sweep_partition& part) { return relax_sphere_vertices(F, around, energy, flow.cone_weight, mu, part, threads, p, u, w); },
    measure, [&](const Relaxation_outcome&) { return measure(); },
    [&](double d) {
      return d <= goal && (!finest || !(opt.sphere.log_area_tolerance > 0) ||
                           flat_mean_abs_log_ratio(p, F, target) <= opt.sphere.log_area_tolerance);
    });
}

/// Replaces the start `p` of `P` by the coarse-to-fine map when the
/// hierarchy has a level, the coarsest level's start and flow succeed and
/// every level's map is certified; else leaves `p` as it is and says why in
/// `R.levels_refused`. Fills `R.levels` (coarsest first, the last one the
/// caller's mesh) and `R.seconds_levels`.
template <class EigenSolver>
bool sphere_coarse_to_fine_start(const Sphere_problem& P, std::vector<Vec3>& p, const Discrete_lie_flow_options& opt,
                                 Discrete_lie_flow_report& R,
                                 const Sphere_coarse_to_fine_settings& s = Sphere_coarse_to_fine_settings())
{
  typedef std::chrono::steady_clock Clock;
  const auto since = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };
  const auto refuse = [&R](const std::string& why) { R.levels.clear(); R.levels_refused = why; return false; };
  const std::size_t n = P.xyz.size();
  Clock::time_point t = Clock::now();
  const std::size_t coarsest = std::size_t(s.coarsest_share * double(opt.sphere.coarse_to_fine_faces));
  std::vector<Collapse_level> levels = build_sphere_levels(P, coarsest, s);
  R.seconds_levels = since(t);
  if(levels.empty()) return refuse("no vertex could be removed");

  t = Clock::now();
  std::vector<Vec3> fine(n, Vec3{{ 0, 0, 0 }});
  Discrete_lie_flow_level top;
  if(!flow_coarsest_sphere_level<EigenSolver>(P, levels.back(), opt, s, fine, top))
    return refuse("the coarsest level of " + std::to_string(levels.back().faces.size()) + " faces was not mapped");
  top.seconds = since(t);
  R.levels.push_back(top);
  const std::vector<std::size_t> order = morton_order(P.xyz);
  int threads = opt.sphere.threads;
  if(threads <= 0) {
    const unsigned h = std::thread::hardware_concurrency();
    threads = h == 0 ? 1 : (h > 8 ? 8 : int(h));
  }
  for(std::size_t l = levels.size(); l-- > 0;) {
    t = Clock::now();
    const std::vector<Face>& F = l == 0 ? P.faces : levels[l - 1].faces;
    Discrete_lie_flow_level level;
    level.faces = F.size();
    level.vertices = R.levels.back().vertices + levels[l].from_above.removed.size();
    level.d_area = carry_down_sphere_level(levels[l].from_above, F, l == 0 ? P.target : levels[l - 1].target, P.xyz, order,
                                           threads, l == 0, opt, s, fine);
    if(std::isnan(level.d_area))
      return refuse("a vertex put back on the level of " + std::to_string(F.size()) + " faces found no position with a positive star");
    levels.pop_back(); // its faces are not needed any more
    level.seconds = since(t);
    R.levels.push_back(level);
  }
  // The caller's faces, certified once more as a whole.
  if(!count_orientations_sphere(fine, P.faces).all_positive()) return refuse("the map carried down has a triangle that is not positive");
  p.swap(fine);
  return true;
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
