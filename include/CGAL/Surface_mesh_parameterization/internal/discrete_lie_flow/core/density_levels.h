// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The measure a density prescribes, checked region by region. D_area weighs
// each face's own error, so an error spread smoothly over a whole region
// costs it little: at D_area 2.0005, a ball scaled by 0.5 on nefertiti after
// one Loop subdivision received 1.8% more than its share. The flows
// therefore stop as converged only once the regions of ρ also have their
// shares (`Discrete_lie_flow_options::share_tolerance`).

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_DENSITY_LEVELS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_DENSITY_LEVELS_H

#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/distortion.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// The sublevel sets {ρ < c} of a per-face density on which the achieved
/// share of the domain's area is held against the prescribed one, relative
/// to the smaller of the set and its complement. A cut c lies between two
/// consecutive distinct values of ρ and is kept when one of the two values
/// has at least `min_faces` faces (a region of a region density, or the
/// rest of the surface), or when the cumulative measure crosses a tenth there
/// (smooth densities); and only when each side has `min_faces` faces. Faces
/// of one region share one value, so a region is a sublevel set or the
/// complement of one.
class Density_levels
{
public:
  /// Sets of fewer faces are not held: their share is the sum of a few
  /// faces' own errors (at D_area 2.0005 about 2% each), which the flow
  /// brings down only with D_area itself.
  static constexpr std::size_t min_faces = 32;

  /// `target[t]` = ρ_t · area_M(t) (any common scale) of the triangles `faces` of `xyz`.
  Density_levels(const std::vector<Vec3>& xyz, const std::vector<Face>& faces, const std::vector<double>& target)
  {
    const std::size_t F = faces.size();
    std::vector<double> rho(F);
    double total = 0;
    for(std::size_t t = 0; t < F; ++t) {
      const Face& f = faces[t];
      rho[t] = target[t] / triangle_area_3(xyz[f[0]], xyz[f[1]], xyz[f[2]]);
      total += target[t];
    }
    if(F < 2 * min_faces || !(total > 0)) return;
    m_order.resize(F);
    std::iota(m_order.begin(), m_order.end(), std::size_t(0));
    std::stable_sort(m_order.begin(), m_order.end(), [&](std::size_t a, std::size_t b) { return rho[a] < rho[b]; });
    // Groups of equal ρ (to rounding: a density set per region is one
    // value, per-face areas divide it back with a relative error ~1e-16).
    std::vector<std::size_t> end;
    std::vector<double> mass;
    for(std::size_t k = 0; k < F; ++k) {
      const std::size_t t = m_order[k];
      if(k == 0 || rho[t] > rho[m_order[k - 1]] * (1 + 1e-9)) { end.push_back(k); mass.push_back(0); }
      end.back() = k + 1;
      mass.back() += target[t] / total;
    }
    double cumulative = 0;
    for(std::size_t g = 0; g + 1 < end.size(); ++g) {
      const double before = cumulative;
      cumulative += mass[g];
      const std::size_t size = end[g] - (g > 0 ? end[g - 1] : 0), next = end[g + 1] - end[g];
      const bool region = size >= min_faces || next >= min_faces;
      const bool tenth = std::floor(10 * cumulative) != std::floor(10 * before);
      if((region || tenth) && end[g] >= min_faces && F - end[g] >= min_faces) {
        m_cut.push_back(end[g]);
        m_prescribed.push_back(cumulative);
      }
    }
  }

  /// True when ρ is constant: no region to check.
  bool uniform() const { return m_cut.empty(); }

  /// The largest error over the cuts of the domain's share of {ρ < c},
  /// |achieved − prescribed| / min(prescribed, 1 − prescribed),
  /// for the signed domain areas `area` (per face, the order of `faces`;
  /// folds, in paper mode, count negatively); +∞ when their sum is not positive.
  double error(const std::vector<double>& area) const
  {
    if(uniform()) return 0;
    double total = 0;
    for(double a : area) total += a;
    if(!(total > 0)) return std::numeric_limits<double>::infinity();
    double worst = 0, achieved = 0;
    std::size_t k = 0;
    for(std::size_t c = 0; c < m_cut.size(); ++c) {
      for(; k < m_cut[c]; ++k) achieved += area[m_order[k]];
      const double p = m_prescribed[c];
      const double e = std::abs(achieved / total - p) / (std::min)(p, 1 - p);
      worst = (std::max)(worst, e);
    }
    return worst;
  }

  /// How many sets are held.
  std::size_t cuts() const { return m_cut.size(); }

private:
  std::vector<std::size_t> m_order;    // faces by increasing ρ
  std::vector<std::size_t> m_cut;      // {ρ < c} = m_order[0, m_cut[i])
  std::vector<double> m_prescribed;    // its prescribed share
};

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
