// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The coarse-to-fine start of the certified disk flow: the coarsest level
// of disk_hierarchy.h flowed to its targets, its map carried down level by
// level (each level certified by the exact predicate, its vertices swept
// one by one), so that the finest level's flow starts near its targets.
// On a large mesh almost every iteration of the plain flow is spent at the
// finest resolution moving the smooth modes a coarse level moves for a
// fraction of the cost (doc/coarse_to_fine.md).

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_COARSE_TO_FINE_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_COARSE_TO_FINE_H

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_options.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_report.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/area_barrier_energy.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/certification.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/morton_order.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/vertex_relaxation.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/disk/border_spacing.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/disk/boundary_curve.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/disk/disk_hierarchy.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/disk/disk_problem.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/disk/planar_certified_flow.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/disk/planar_relaxation.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/flow/coarse_to_fine_levels.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/flow/flow_driver.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// Whether the certified flow on a disk of `faces` faces starts coarse to fine.
inline bool flows_coarse_to_fine(const Discrete_lie_flow_options& opt, std::size_t faces)
{
  return opt.mode == Discrete_lie_flow_mode::CERTIFIED && opt.fixed_step == 0 && opt.disk.coarse_to_fine_faces > 0 &&
         faces >= opt.disk.coarse_to_fine_faces;
}

/// The levels of `P` from the start `uv`, finest first, until one has at
/// most `coarsest` faces or a level removes too few vertices.
inline std::vector<Disk_level> build_disk_levels(const Disk_problem& P, const std::vector<Vec2>& uv,
                                                 const std::vector<char>& fixed, std::size_t coarsest,
                                                 const Coarse_to_fine_settings& s)
{
  std::vector<Disk_level> levels;
  std::size_t alive = uv.size();
  for(;;) {
    const std::vector<Face>& F = levels.empty() ? P.faces : levels.back().faces;
    const std::vector<double>& T = levels.empty() ? P.target : levels.back().target;
    if(F.size() <= coarsest) break;
    Disk_level L;
    const std::size_t removed = coarsen_disk_level(uv.size(), F, T, uv, P.xyz, fixed, L);
    if(removed == 0) break;
    levels.push_back(std::move(L));
    if(double(removed) < s.least_removed * double(alive)) break;
    alive -= removed;
  }
  return levels;
}

/// Flows the coarsest level `L` of `P` (on its own vertices) from `uv` and
/// writes its map into `fine` at its vertices; `curve` follows its border.
template <class EigenSolver>
Discrete_lie_flow_level flow_coarsest_level(const Disk_problem& P, const Disk_level& L, const std::vector<Vec2>& uv,
                                            Boundary_curve& curve, const Discrete_lie_flow_options& opt,
                                            const Planar_flow_settings& flow_settings, const Coarse_to_fine_settings& s,
                                            std::vector<Vec2>& fine)
{
  Disk_problem C;
  std::vector<int> index, vertex_of;
  C.faces = L.faces;
  C.target = L.target;
  renumber_coarsest_level(C.faces, P.xyz, C.xyz, index, vertex_of);
  for(int b : P.boundary) C.boundary.push_back(index[std::size_t(b)]);
  std::vector<Vec2> coarse_uv(vertex_of.size());
  for(std::size_t i = 0; i < vertex_of.size(); ++i) coarse_uv[i] = uv[std::size_t(vertex_of[i])];
  const Discrete_lie_flow_options coarse = coarsest_level_options(opt, s);
  Planar_flow_settings settings = flow_settings;
  EigenSolver solver; // the caller's solver keeps the finest level's analysis
  // On the circle the coarsest level's border is spaced by area, as the
  // plain flow's start is (border_spacing.h), with its own small system.
  Tutte_interior_system<EigenSolver> tutte(C, coarse_uv.size(), solver);
  if(curve.kind() == Discrete_lie_flow_border::CIRCLE)
    settings.coupled_metric = respace_border_by_area<EigenSolver>(C, coarse_uv, curve, 0.5, tutte);
  Planar_certified_flow<EigenSolver> flow(C, coarse_uv, curve, coarse, solver, settings,
                                          tutte.solver().analyses() > 0 ? &tutte.solver() : nullptr);
  const Flow_outcome flowed = run_flow(flow, coarse);
  for(std::size_t i = 0; i < vertex_of.size(); ++i) fine[std::size_t(vertex_of[i])] = coarse_uv[i];
  return coarsest_level_record(vertex_of.size(), C.faces.size(), flowed);
}

/// Puts the vertices `D` removed back into `fine` (prolong_disk_level())
/// and sweeps the finer level (`F`, `target`): its D_area after, or NaN
/// when a vertex found no position.
inline double carry_down_level(const Disk_decimation& D, const std::vector<Face>& F, const std::vector<double>& target,
                               const std::vector<Vec2>& start, const std::vector<char>& fixed,
                               const std::vector<std::size_t>& order, int threads, double goal, bool finest,
                               const Discrete_lie_flow_options& opt, const Coarse_to_fine_settings& s,
                               std::vector<Vec2>& fine)
{
  if(!prolong_disk_level(D, start, fine)) return std::numeric_limits<double>::quiet_NaN();
  const Area_barrier_energy energy(target);
  std::vector<double> u;
  signed_areas_2(fine, F, u);
  const Vertex_faces around(fine.size(), F);
  std::vector<char> movable(fixed.size());
  for(std::size_t v = 0; v < fixed.size(); ++v) movable[v] = !fixed[v];
  const double mu = step_fraction(opt);
  sweep_finer_level(order, F, around, D.removed, movable, finest, s,
                    [&](const Sweep_partition& part) { return relax_planar_vertices(F, around, energy, mu, part, threads, fine, u); },
                    [&] { return energy.value(u); }, [](const Relaxation_outcome& r) { return r.energy; },
                    [&](double E) { return E <= goal; });
  signed_areas_2(fine, F, u); // the sweeps' incremental sums drop
  return energy.value(u);
}

/// Replaces the positively oriented start `uv` of `P` (and the border's
/// state in `curve`) by the coarse-to-fine start when the hierarchy has a
/// level, every level's map is certified and the start's D_area is not
/// raised; else leaves both as they are and says why in
/// `R.levels_refused`. Fills `R.levels` (the last one the caller's mesh)
/// and `R.seconds_levels`; `flow_settings` become the finest level's.
template <class EigenSolver>
bool coarse_to_fine_start(const Disk_problem& P, std::vector<Vec2>& uv, Boundary_curve& curve,
                          const Discrete_lie_flow_options& opt, Planar_flow_settings& flow_settings,
                          Discrete_lie_flow_report& R, const Coarse_to_fine_settings& s = Coarse_to_fine_settings())
{
  typedef std::chrono::steady_clock Clock;
  const auto since = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };
  const auto refuse = [&R](const std::string& why) { R.levels.clear(); R.levels_refused = why; return false; };
  const std::size_t n = uv.size();
  Clock::time_point t = Clock::now();
  const std::size_t coarsest = std::size_t(s.coarsest_share * double(opt.disk.coarse_to_fine_faces));
  std::vector<char> fixed(n, 0);
  for(int b : P.boundary) fixed[std::size_t(b)] = 1;
  std::vector<Disk_level> levels = build_disk_levels(P, uv, fixed, coarsest, s);
  R.seconds_levels = since(t);
  if(levels.empty()) return refuse("no interior vertex could be removed");

  t = Clock::now();
  std::vector<Vec2> fine(uv);
  Boundary_curve coarse_curve = curve;
  R.levels.push_back(flow_coarsest_level<EigenSolver>(P, levels.back(), uv, coarse_curve, opt, flow_settings, s, fine));
  R.levels.back().seconds = since(t);
  const std::vector<std::size_t> order = morton_order(P.xyz);
  const int threads = disk_sweep_threads(opt, P.faces.size());
  for(std::size_t l = levels.size(); l-- > 0;) {
    t = Clock::now();
    const std::vector<Face>& F = l == 0 ? P.faces : levels[l - 1].faces;
    const double goal = 2 + (l == 0 ? s.finest_goal_share : s.level_goal_share) * opt.tolerance;
    Discrete_lie_flow_level level;
    level.faces = F.size();
    level.vertices = R.levels.back().vertices + levels[l].from_above.removed.size();
    level.d_area = carry_down_level(levels[l].from_above, F, l == 0 ? P.target : levels[l - 1].target, uv, fixed, order,
                                    threads, goal, l == 0, opt, s, fine);
    if(std::isnan(level.d_area))
      return refuse("a vertex put back on the level of " + std::to_string(F.size()) + " faces found no position with a positive star");
    levels.pop_back(); // its faces are not needed any more
    level.seconds = since(t);
    R.levels.push_back(level);
  }
  // The caller's faces, certified once more as a whole, and no worse than the start.
  std::vector<double> u0;
  signed_areas_2(uv, P.faces, u0);
  const double E0 = Area_barrier_energy(P.target).value(u0);
  if(!count_orientations_2(fine, P.faces).all_positive()) return refuse("the map carried down has a triangle that is not positive");
  if(!(R.levels.back().d_area <= E0))
    return refuse("the map carried down has D_area " + std::to_string(R.levels.back().d_area) + ", above the start's " + std::to_string(E0));
  uv.swap(fine);
  curve = coarse_curve;
  flow_settings.coupled_metric = false; // the coarsest level's flow has slid the border where it belongs
  return true;
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
