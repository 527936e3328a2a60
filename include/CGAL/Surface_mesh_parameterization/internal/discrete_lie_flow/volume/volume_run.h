// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A run of the volumetric parameterizer on index data, from the caller's
// options to a filled report: the checks, the targets, the certified start
// (volume_start.h), the flow in rounds (the density levels' targets
// rescaled between them), then the result measured from scratch.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_VOLUME_RUN_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_VOLUME_RUN_H

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_volume_options.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/parallel_ranges.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/volume/volume_flow.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/volume/volume_geometry.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/volume/volume_mesh.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/volume/volume_paper_flow.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/volume/volume_start.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// Sets the report's status and message (the code's own message when
/// `message` is empty); returns the code.
inline Error_code volume_failure(Discrete_lie_flow_volume_report& R, int code, const std::string& message)
{
  R.status = Error_code(code);
  R.message = message.empty() ? std::string(discrete_lie_flow_error_message(code)) : message;
  return Error_code(code);
}

/// The options a run refuses: `OK`, or the code and `message`.
inline int check_volume_options(const Discrete_lie_flow_volume_options& O, std::string& message)
{
  if(!(O.mu > 0 && O.mu < 1)) { message = "mu must lie in (0, 1)"; return ERROR_WRONG_PARAMETER; }
  if(!(O.tolerance > 0)) { message = "the tolerance must be positive"; return ERROR_WRONG_PARAMETER; }
  if(O.mode == Discrete_lie_flow_mode::LITERAL) {
    message = "the volumetric flow has a certified and a paper mode, no literal one";
    return ERROR_WRONG_PARAMETER;
  }
  return OK;
}

/// The tets' targets ρ_t vol_t (`density` empty: ρ ≡ 1): `OK`, or the code
/// and `message` naming the offending tet.
inline int volume_targets(const std::vector<Vec3>& xyz, const std::vector<Tet>& tets,
                          const std::vector<double>& density, std::vector<double>& target, std::string& message)
{
  if(!density.empty() && density.size() != tets.size()) {
    message = "the density has " + std::to_string(density.size()) + " values for " + std::to_string(tets.size()) +
              " tetrahedra";
    return ERROR_INVALID_DENSITY;
  }
  target.resize(tets.size());
  for(std::size_t t = 0; t < tets.size(); ++t) {
    const double rho = density.empty() ? 1. : density[t];
    if(!(rho > 0) || !std::isfinite(rho)) {
      message = "the density of tetrahedron " + std::to_string(t) + " is " + std::to_string(rho) +
                "; it must be finite and positive";
      return ERROR_INVALID_DENSITY;
    }
    const Tet& k = tets[t];
    target[t] = rho * tet_det(xyz[std::size_t(k[0])], xyz[std::size_t(k[1])], xyz[std::size_t(k[2])], xyz[std::size_t(k[3])]);
    if(!(target[t] > 0)) {
      message = "tetrahedron " + std::to_string(t) + " has a volume that rounds to zero or below in doubles";
      return ERROR_DEGENERATE_INPUT;
    }
  }
  return OK;
}

/// The density levels of a run (a level per density value, its prescribed
/// share of the targets): set with a share tolerance and 2 to 32 values,
/// else none.
inline Volume_share_levels volume_share_levels(const Discrete_lie_flow_volume_options& O,
                                               const std::vector<double>& target)
{
  Volume_share_levels levels;
  if(O.tet_density.empty() || !(O.share_tolerance > 0)) return levels;
  std::map<double, int> ids;
  for(double rho : O.tet_density) {
    if(ids.size() > 32) break;
    ids.emplace(rho, int(ids.size()));
  }
  if(ids.size() > 32 || ids.size() <= 1) return levels;
  levels.level.resize(target.size());
  levels.share.assign(ids.size(), 0.);
  double Tsum = 0;
  for(std::size_t t = 0; t < target.size(); ++t) {
    levels.level[t] = ids[O.tet_density[t]];
    levels.share[std::size_t(levels.level[t])] += target[t];
    Tsum += target[t];
  }
  for(double& a : levels.share) a /= Tsum;
  return levels;
}

/// The flow from the certified start `x`, in rounds: where D_vol's minimum
/// leaves a density level short of its share (its tets at the border cannot
/// all reach their volumes), the level's targets are scaled by
/// prescribed/achieved and the flow runs again from there (at most 6
/// rounds). The outcome sums the rounds; the stop reason is the last one's.
inline Volume_flow_outcome run_volume_rounds(const Discrete_lie_flow_volume_options& O, std::vector<Vec3>& x,
                                             const std::vector<Tet>& tets, const Ball_topology& topo,
                                             const std::vector<double>& target, const Volume_share_levels& levels,
                                             std::vector<Volume_iteration>* history)
{
  std::vector<double> flow_target = target, u;
  Volume_flow_outcome out;
  for(int round = 0;; ++round) {
    const Volume_flow_outcome o =
      O.mode == Discrete_lie_flow_mode::PAPER
        ? run_volume_paper_flow(x, tets, topo.on_border, topo.border_faces, flow_target, O, levels, history)
        : run_volume_flow(x, tets, topo.on_border, topo.border_faces, flow_target, O, levels, history);
    out.iterations += o.iterations;
    out.rejected_by_exact_check += o.rejected_by_exact_check;
    out.cg_iterations += o.cg_iterations;
    out.stop_reason = o.stop_reason;
    if(levels.level.empty() || round >= 5 || o.stop_reason == Discrete_lie_flow_stop_reason::CONVERGED ||
       o.stop_reason == Discrete_lie_flow_stop_reason::INTERRUPTED)
      break;
    std::vector<double> achieved;
    tet_dets(x, tets, u);
    if(level_share_error(levels, u, &achieved) <= O.share_tolerance) break;
    for(std::size_t t = 0; t < tets.size(); ++t) {
      const std::size_t k = std::size_t(levels.level[t]);
      flow_target[t] *= levels.share[k] / achieved[k];
    }
  }
  return out;
}

/// The volume ratios r_t of the result `u` (tet determinants) against the
/// prescribed `target`, their statistics, the image's volume and the
/// density levels' shares, into the report.
inline void measure_volume_ratios(const Discrete_lie_flow_volume_options& O, const std::vector<double>& u,
                                  const std::vector<double>& target, Discrete_lie_flow_volume_report& R)
{
  const std::size_t T = target.size();
  double U = 0, Tsum = 0;
  for(std::size_t t = 0; t < T; ++t) { U += u[t]; Tsum += target[t]; }
  R.volume = U / 6;
  R.volume_ratio.resize(T);
  R.min_ratio = std::numeric_limits<double>::infinity();
  R.max_ratio = 0;
  double sum_abs = 0;
  std::map<double, Discrete_lie_flow_volume_share> levels;
  for(std::size_t t = 0; t < T; ++t) {
    const double r = (u[t] / U) / (target[t] / Tsum);
    R.volume_ratio[t] = r;
    R.min_ratio = (std::min)(R.min_ratio, r);
    R.max_ratio = (std::max)(R.max_ratio, r);
    const double l = std::abs(std::log(r));
    sum_abs += l;
    R.log_volume_max_abs = (std::max)(R.log_volume_max_abs, l);
    const double rho = O.tet_density.empty() ? 1. : O.tet_density[t];
    if(levels.size() < 33 || levels.count(rho)) {
      Discrete_lie_flow_volume_share& s = levels[rho];
      s.density = rho;
      ++s.tets;
      s.target_share += target[t] / Tsum;
      s.achieved_share += u[t] / U;
    }
  }
  R.log_volume_mean_abs = sum_abs / double(T);
  if(levels.size() <= 32)
    for(const auto& kv : levels) {
      R.shares.push_back(kv.second);
      R.share_error_max = (std::max)(R.share_error_max, std::abs(kv.second.relative_error()));
    }
}

/// The message of a valid map short of its goals, as the surface flows
/// word it: where it stopped, each goal missed with its value.
inline std::string volume_not_converged_message(const Discrete_lie_flow_volume_options& O, const Volume_share_levels& levels,
                                                const Discrete_lie_flow_volume_report& R, double d_vol_reached,
                                                double share_error_reached)
{
  std::ostringstream missed;
  missed << std::setprecision(6);
  if(!(d_vol_reached - 2 <= O.tolerance)) missed << "D_vol " << d_vol_reached << " > " << 2 + O.tolerance;
  if(!levels.level.empty() && !(share_error_reached <= O.share_tolerance))
    missed << (missed.tellp() > 0 ? "; " : "") << "share error " << share_error_reached << " > " << O.share_tolerance;
  std::ostringstream s;
  s << std::setprecision(6) << "not converged: stopped (" << discrete_lie_flow_stop_reason_name(R.stop_reason)
    << ") after " << R.iterations << " iterations short of "
    << (missed.tellp() > 0 ? missed.str() : std::string("the flow's own stop rule"))
    << "; the map is valid and fold-free, D_vol " << R.final_d_vol;
  return s.str();
}

/// The flow from the certified start `x` to the report's flow fields and
/// measures of the result; `OK`, or `ERROR_NO_1_TO_1_MAPPING` should the
/// result not be positive (every accepted step is certified: it cannot).
inline Error_code flow_volume(const Discrete_lie_flow_volume_options& O, std::vector<Vec3>& x,
                              const std::vector<Tet>& tets, const Ball_topology& topo,
                              const std::vector<double>& target, Discrete_lie_flow_volume_report& R)
{
  typedef std::chrono::steady_clock Clock;
  Volume_energy energy(target);
  std::vector<double> u;
  tet_dets(x, tets, u);
  R.initial_d_vol = energy.value(u, 0);
  const Volume_share_levels levels = volume_share_levels(O, target);
  const Clock::time_point t_flow = Clock::now();
  Volume_flow_outcome out = run_volume_rounds(O, x, tets, topo, target, levels, O.record_history ? &R.history : nullptr);
  // Converged: D_vol against the prescribed targets, and the shares. (The
  // last round may have stopped on its rescaled targets' plateau with both
  // tolerances met on the prescribed ones: that is converged.)
  tet_dets(x, tets, u);
  const double d_vol_reached = energy.value(u, 0);
  const double share_error_reached = level_share_error(levels, u);
  const bool reached = d_vol_reached - 2 <= O.tolerance && share_error_reached <= O.share_tolerance;
  if(reached && out.stop_reason != Discrete_lie_flow_stop_reason::INTERRUPTED)
    out.stop_reason = Discrete_lie_flow_stop_reason::CONVERGED;
  else if(!reached && out.stop_reason == Discrete_lie_flow_stop_reason::CONVERGED)
    out.stop_reason = Discrete_lie_flow_stop_reason::PLATEAU;
  R.seconds_flow = std::chrono::duration<double>(Clock::now() - t_flow).count();
  R.stop_reason = out.stop_reason;
  R.iterations = out.iterations;
  R.rejected_by_exact_check = out.rejected_by_exact_check;
  R.cg_iterations = out.cg_iterations;
  // Measures of the result, recomputed from scratch.
  const Tet_orientation_counts bad = count_bad_tets(x, tets);
  R.inverted_border_faces = count_bad_border_faces(x, topo.border_faces);
  R.inverted_tets = bad.negative;
  R.flat_tets = bad.flat;
  tet_dets(x, tets, u);
  R.final_d_vol = energy.value(u, 0);
  measure_volume_ratios(O, u, target, R);
  if(bad.not_positive() != 0 || (O.star_shaped_border && R.inverted_border_faces != 0))
    return volume_failure(R, ERROR_NO_1_TO_1_MAPPING,
                          "the flow left " + std::to_string(bad.not_positive()) + " tetrahedra and " +
                            std::to_string(R.inverted_border_faces) + " border triangles not positive");
  R.status = OK;
  R.message = R.converged() ? std::string("Success")
                            : volume_not_converged_message(O, levels, R, d_vol_reached, share_error_reached);
  return OK;
}

/// A whole run on index data: `xyz` and `tets` (positively oriented) to the
/// ball's points `x` and the report `R`. `map_border` maps the border onto
/// the sphere (volume_start()); `EigenSolver` solves the start's Tutte system.
template <class EigenSolver, class BorderToSphere>
Error_code run_volume_parameterization(const Discrete_lie_flow_volume_options& O, const std::vector<Vec3>& xyz,
                                       const std::vector<Tet>& tets, const BorderToSphere& map_border,
                                       std::vector<Vec3>& x, Discrete_lie_flow_volume_report& R)
{
  typedef std::chrono::steady_clock Clock;
  const Clock::time_point t_start = Clock::now();
  R = Discrete_lie_flow_volume_report();
  std::string message;
  int code = check_volume_options(O, message);
  if(code != OK) return volume_failure(R, code, message);
  R.vertices = xyz.size();
  R.tets = tets.size();
  R.threads = volume_flow_threads(O.threads, tets.size());
  Ball_topology topo;
  code = check_ball(xyz, tets, topo, message);
  if(code != OK) return volume_failure(R, code, message);
  R.border_vertices = topo.border_vertices;
  R.border_faces = topo.border_faces.size();
  std::vector<double> target;
  code = volume_targets(xyz, tets, O.tet_density, target, message);
  if(code != OK) return volume_failure(R, code, message);
  Volume_start_info start;
  code = volume_start<EigenSolver>(xyz, tets, topo, target, map_border, O.untangle_max_iterations, O.callback, x,
                                   start, message);
  R.border = start.border;
  R.start_negative_tets = start.tutte_negative_tets;
  R.start_flat_tets = start.tutte_flat_tets;
  R.untangle_iterations = start.untangle_iterations;
  R.seconds_border = start.seconds_border;
  R.seconds_interior = start.seconds_interior;
  R.seconds_untangle = start.seconds_untangle;
  if(code != OK) return volume_failure(R, code, message);
  R.start_certified = true;
  const Error_code flowed = flow_volume(O, x, tets, topo, target, R);
  R.seconds_total = std::chrono::duration<double>(Clock::now() - t_start).count();
  return flowed;
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
