// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Area elements of a domain triangulation: signed areas, the lumped vertex
// areas A_Ω and A_M, their residual, D_area, and the targets of faces that
// flips create (one density per vertex, as in the paper's Eq. 6).

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_AREA_ELEMENTS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_AREA_ELEMENTS_H

#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/geometry.h>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// Lumped vertex areas: out[i] = (1/3) Σ_{f ∋ i} value[f].
inline void lump_on_vertices(std::size_t n, const std::vector<Face>& faces, const std::vector<double>& value,
                             std::vector<double>& out)
{
  out.assign(n, 0.);
  for(std::size_t f = 0; f < faces.size(); ++f)
    for(int k = 0; k < 3; ++k) out[faces[f][k]] += value[f] / 3;
}

inline void signed_areas_2(const std::vector<Vec2>& uv, const std::vector<Face>& faces, std::vector<double>& out)
{
  out.resize(faces.size());
  for(std::size_t f = 0; f < faces.size(); ++f)
    out[f] = signed_area_2(uv[faces[f][0]], uv[faces[f][1]], uv[faces[f][2]]);
}

/// Normalised squared mismatch Σ_i (A_Ω(i) − A_M(i))² / (Σ A_Ω)², with A_M
/// scaled to the domain's total area.
inline double area_residual(std::size_t n, const std::vector<Face>& faces, const std::vector<double>& dom_area,
                            const std::vector<double>& target)
{
  std::vector<double> ao, am;
  lump_on_vertices(n, faces, dom_area, ao);
  lump_on_vertices(n, faces, target, am);
  double so = 0, sm = 0;
  for(std::size_t i = 0; i < n; ++i) { so += ao[i]; sm += am[i]; }
  double r = 0;
  for(std::size_t i = 0; i < n; ++i) { const double d = ao[i] - am[i] * so / sm; r += d * d; }
  return r / (so * so);
}

/// Algorithm 1's mismatch ‖h_M − h_Ω‖² between two per-vertex area
/// elements, each in units of its own mean: the mean squared relative
/// mismatch n · Σ_i (a_i/Σa − b_i/Σb)² (doc/paper_errata.md, "Stop rule").
inline double normalized_mismatch(const std::vector<double>& a, const std::vector<double>& b)
{
  double sa = 0, sb = 0;
  for(std::size_t i = 0; i < a.size(); ++i) { sa += a[i]; sb += b[i]; }
  double s = 0;
  for(std::size_t i = 0; i < a.size(); ++i) {
    const double e = a[i] / sa - b[i] / sb;
    s += e * e;
  }
  return double(a.size()) * s;
}

/// D_area of domain areas `u` against targets (both per face; u > 0):
/// exactly the metric `d_area` of doc/design.md. +∞ if some u ≤ 0.
inline double d_area_of(const std::vector<double>& u, const std::vector<double>& target)
{
  double U = 0, T = 0;
  for(std::size_t f = 0; f < u.size(); ++f) {
    if(!(u[f] > 0)) return std::numeric_limits<double>::infinity();
    U += u[f]; T += target[f];
  }
  double e = 0;
  for(std::size_t f = 0; f < u.size(); ++f) {
    const double r = (u[f] / U) / (target[f] / T);
    e += (target[f] / T) * (r + 1 / r);
  }
  return e;
}

/// Targets of a flowing triangulation: the input's targets as long as a face
/// is unchanged, ρ × the 3D triangle between its vertices once a flip
/// created it, ρ per vertex the area-weighted mean of the incident faces'
/// ρ = target / area_M. Shared by the paper flows of the plane and the sphere.
class Flowing_targets
{
public:
  Flowing_targets(const std::vector<Vec3>& xyz, const std::vector<Face>& faces, const std::vector<double>& target)
    : m_xyz(xyz), m_rho(xyz.size(), 0.), m_min_target(*std::min_element(target.begin(), target.end()))
  {
    std::vector<double> den(xyz.size(), 0.);
    for(std::size_t f = 0; f < faces.size(); ++f) {
      const Face& t = faces[f];
      const double a = triangle_area_3(xyz[std::size_t(t[0])], xyz[std::size_t(t[1])], xyz[std::size_t(t[2])]);
      for(int k = 0; k < 3; ++k) { m_rho[std::size_t(t[k])] += target[f]; den[std::size_t(t[k])] += a; }
    }
    for(std::size_t v = 0; v < m_rho.size(); ++v) m_rho[v] = den[v] > 0 ? m_rho[v] / den[v] : 1.;
  }

  /// The target of the triangle `t` created by a flip.
  double operator()(const Face& t) const
  {
    const std::size_t a = std::size_t(t[0]), b = std::size_t(t[1]), c = std::size_t(t[2]);
    const double area = triangle_area_3(m_xyz[a], m_xyz[b], m_xyz[c]) * (m_rho[a] + m_rho[b] + m_rho[c]) / 3;
    return (std::max)(area, 1e-3 * m_min_target); // guard flat 3D triangles
  }

private:
  const std::vector<Vec3>& m_xyz;
  std::vector<double> m_rho;
  double m_min_target;
};

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
