// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Gauss–Newton direction of the planar certified flow, for its tail.
// Near the targets the Sobolev gradient converges linearly, and slowly when
// a density jump makes the targets far from the Tutte start's proportions
// (measured, a region scaled by 16: nefertiti D_area 2.005 after 8
// iterations, then ~0.97 per iteration down to 2.0008). The Gauss–Newton
// model of E = Σ e_t(u_t) in the dof coordinates, H = Jᵀ diag(e_t'') J with
// J = ∂u/∂dofs, is regularised by ε times the Sobolev metric S of the
// current domain (Levenberg–Marquardt: S fixes the modes that change no
// area, and ε follows how well the model predicted the last step), as on the
// sphere (sphere_gauss_newton.h).

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_PLANAR_GAUSS_NEWTON_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_PLANAR_GAUSS_NEWTON_H

#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/cotangent_laplacian.h>

#include <Eigen/Sparse>

#include <algorithm>
#include <array>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// H + ε S over the dofs: `first[v]`/`count[v]` give vertex v's dofs (0, 1
/// or 2, fixed for the run), `basis[a]` the direction of dof a. The pattern
/// (every pair of dofs of one face) and each face's 6 × 6 slots are built on
/// the first call; later calls only add numbers, as in the Sobolev assembly.
class Planar_gauss_newton_system
{
public:
  Planar_gauss_newton_system(const std::vector<int>& first, const std::vector<int>& count, int size)
    : m_first(first), m_count(count), m_size(size)
  {}

  /// Assembles H + ε S for the areas' curvatures `w` (e_t''(u_t)); ε is
  /// `eps_relative` · tr(H)/tr(S), so that it does not depend on the scale.
  const Sparse_matrix& assemble(const std::vector<Vec2>& uv, const std::vector<Face>& faces,
                                const std::vector<Vec2>& basis, const std::vector<double>& w, double eps_relative)
  {
    if(m_slots.empty()) build_pattern(faces);
    m_h.assign(std::size_t(m_A.nonZeros()), 0.);
    m_s.assign(std::size_t(m_A.nonZeros()), 0.);
    double trace_H = 0, trace_S = 0;
    std::array<int, 6> dof, vertex_of;
    std::array<double, 6> J;  // ∂u_t/∂dof
    std::array<Vec2, 6> e;
    const int* slot = m_slots.data();
    for(std::size_t t = 0; t < faces.size(); ++t, slot += 36) {
      const Face& f = faces[t];
      int m = 0;
      for(int k = 0; k < 3; ++k) {
        const std::size_t v = std::size_t(f[k]);
        const Vec2& a = uv[std::size_t(f[(k + 1) % 3])];
        const Vec2& b = uv[std::size_t(f[(k + 2) % 3])];
        for(int j = 0; j < m_count[v]; ++j, ++m) {
          dof[std::size_t(m)] = m_first[v] + j;
          vertex_of[std::size_t(m)] = k;
          e[std::size_t(m)] = basis[std::size_t(m_first[v] + j)];
          J[std::size_t(m)] = 0.5 * ((a[1] - b[1]) * e[std::size_t(m)][0] + (b[0] - a[0]) * e[std::size_t(m)][1]);
        }
      }
      // The face's Dirichlet stiffness between corners k and l: Σ over its
      // edges of the half cotangent times (δ_k − δ_l) differences.
      const std::array<double, 3> c = half_cotangents(uv[std::size_t(f[0])], uv[std::size_t(f[1])], uv[std::size_t(f[2])]);
      double stiffness[3][3];
      for(int k = 0; k < 3; ++k) stiffness[k][k] = c[std::size_t((k + 1) % 3)] + c[std::size_t((k + 2) % 3)];
      for(int k = 0; k < 3; ++k) {
        const int i = (k + 1) % 3, j = (k + 2) % 3; // edge opposite corner k
        stiffness[i][j] = stiffness[j][i] = -c[std::size_t(k)];
      }
      for(int i = 0; i < m; ++i)
        for(int j = 0; j < m; ++j) {
          const int sl = slot[6 * i + j];
          const double hv = w[t] * J[std::size_t(i)] * J[std::size_t(j)];
          const Vec2& ei = e[std::size_t(i)];
          const Vec2& ej = e[std::size_t(j)];
          const double sv = stiffness[vertex_of[std::size_t(i)]][vertex_of[std::size_t(j)]] * (ei[0] * ej[0] + ei[1] * ej[1]);
          m_h[std::size_t(sl)] += hv;
          m_s[std::size_t(sl)] += sv;
          if(i == j) { trace_H += hv; trace_S += sv; }
        }
    }
    const double eps = eps_relative * (trace_S > 0 ? trace_H / trace_S : 1);
    double* values = m_A.valuePtr();
    for(std::size_t k = 0; k < m_h.size(); ++k) values[k] = m_h[k] + eps * m_s[k];
    return m_A;
  }

private:
  void build_pattern(const std::vector<Face>& faces)
  {
    std::vector<Eigen::Triplet<double> > trip;
    std::vector<int> dofs;
    for(const Face& f : faces) {
      dofs.clear();
      for(int k = 0; k < 3; ++k)
        for(int j = 0; j < m_count[std::size_t(f[k])]; ++j) dofs.push_back(m_first[std::size_t(f[k])] + j);
      for(int a : dofs)
        for(int b : dofs) trip.emplace_back(a, b, 1.);
    }
    m_A.resize(m_size, m_size);
    m_A.setFromTriplets(trip.begin(), trip.end());
    m_A.makeCompressed();
    m_slots.assign(faces.size() * 36, -1);
    int* slot = m_slots.data();
    for(const Face& f : faces) {
      dofs.clear();
      for(int k = 0; k < 3; ++k)
        for(int j = 0; j < m_count[std::size_t(f[k])]; ++j) dofs.push_back(m_first[std::size_t(f[k])] + j);
      for(std::size_t i = 0; i < dofs.size(); ++i)
        for(std::size_t j = 0; j < dofs.size(); ++j) {
          const int* inner = m_A.innerIndexPtr();
          const int* lo = inner + m_A.outerIndexPtr()[dofs[j]];
          const int* hi = inner + m_A.outerIndexPtr()[dofs[j] + 1];
          slot[6 * i + j] = int(std::lower_bound(lo, hi, dofs[i]) - inner);
        }
      slot += 36;
    }
  }

  std::vector<int> m_first, m_count;
  int m_size;
  Sparse_matrix m_A;
  std::vector<double> m_h, m_s;
  std::vector<int> m_slots; // per face, 6 × 6 positions in m_A's values
};

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
