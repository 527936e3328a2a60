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

#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/cotangent_laplacian.h>

#include <CGAL/assertions.h>

#include <Eigen/Sparse>

#include <array>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// H + ε S over the dofs: `first[v]`/`count[v]` give vertex v's dofs (0, 1
/// or 2, fixed for the run), `basis[a]` the direction of dof a. H and S are
/// refilled in the same fixed pattern (every pair of dofs of one face), so
/// A = H + ε S is a sum of value arrays.
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
    double trace_H = 0, trace_S = 0;
    const Sparse_matrix& H = m_H.assemble(std::size_t(m_size), [&](auto&& add) {
      trace_H = 0;
      for_each_face(uv, faces, basis, [&](std::size_t t, int m, const Local& l) {
        for(int i = 0; i < m; ++i)
          for(int j = 0; j < m; ++j) {
            const double v = w[t] * l.J[std::size_t(i)] * l.J[std::size_t(j)];
            add(l.dof[std::size_t(i)], l.dof[std::size_t(j)], v);
            if(i == j) trace_H += v;
          }
      });
    });
    const Sparse_matrix& S = metric(uv, faces, basis, &trace_S);
    CGAL_assertion(S.nonZeros() == H.nonZeros()); // the same contributions' pattern
    if(m_A.nonZeros() != H.nonZeros()) m_A = H;
    const double eps = eps_relative * (trace_S > 0 ? trace_H / trace_S : 1);
    const double *h = H.valuePtr(), *s = S.valuePtr();
    double* a = m_A.valuePtr();
    for(Eigen::Index k = 0; k < m_A.nonZeros(); ++k) a[k] = h[k] + eps * s[k];
    return m_A;
  }

  /// The Sobolev metric S alone: the Dirichlet energy of the current domain
  /// over the dofs, border tangents included (x and y coupled through them).
  /// Same pattern as H + ε S, so one symbolic analysis serves both.
  const Sparse_matrix& metric(const std::vector<Vec2>& uv, const std::vector<Face>& faces,
                              const std::vector<Vec2>& basis, double* trace_S = nullptr)
  {
    double trace = 0;
    const Sparse_matrix& S = m_S.assemble(std::size_t(m_size), [&](auto&& add) {
      trace = 0;
      for_each_face(uv, faces, basis, [&](std::size_t t, int m, const Local& l) {
        // The face's Dirichlet stiffness between its corners: the half
        // cotangent of the opposite corner off the diagonal, the two
        // incident edges' on it.
        const Face& f = faces[t];
        const std::array<double, 3> c = half_cotangents(uv[std::size_t(f[0])], uv[std::size_t(f[1])], uv[std::size_t(f[2])]);
        double stiffness[3][3];
        for(int k = 0; k < 3; ++k) {
          stiffness[k][k] = c[std::size_t((k + 1) % 3)] + c[std::size_t((k + 2) % 3)];
          const int i = (k + 1) % 3, j = (k + 2) % 3;
          stiffness[i][j] = stiffness[j][i] = -c[std::size_t(k)];
        }
        for(int i = 0; i < m; ++i)
          for(int j = 0; j < m; ++j) {
            const Vec2& ei = l.e[std::size_t(i)];
            const Vec2& ej = l.e[std::size_t(j)];
            const double v = stiffness[l.corner[std::size_t(i)]][l.corner[std::size_t(j)]] * (ei[0] * ej[0] + ei[1] * ej[1]);
            add(l.dof[std::size_t(i)], l.dof[std::size_t(j)], v);
            if(i == j) trace += v;
          }
      });
    });
    if(trace_S) *trace_S = trace;
    return S;
  }

private:
  /// A face's dofs (up to six), their corners, directions and ∂u_t/∂dof.
  struct Local
  {
    std::array<int, 6> dof, corner;
    std::array<Vec2, 6> e;
    std::array<double, 6> J;
  };

  /// Calls f(t, m, local) for every face t, m its number of dofs.
  template <class F>
  void for_each_face(const std::vector<Vec2>& uv, const std::vector<Face>& faces, const std::vector<Vec2>& basis, F&& f) const
  {
    Local l;
    for(std::size_t t = 0; t < faces.size(); ++t) {
      const Face& fc = faces[t];
      int m = 0;
      for(int k = 0; k < 3; ++k) {
        const std::size_t v = std::size_t(fc[k]);
        const Vec2& a = uv[std::size_t(fc[(k + 1) % 3])];
        const Vec2& b = uv[std::size_t(fc[(k + 2) % 3])];
        for(int j = 0; j < m_count[v]; ++j, ++m) {
          const std::size_t i = std::size_t(m);
          l.dof[i] = m_first[v] + j;
          l.corner[i] = k;
          l.e[i] = basis[std::size_t(l.dof[i])];
          l.J[i] = 0.5 * ((a[1] - b[1]) * l.e[i][0] + (b[0] - a[0]) * l.e[i][1]);
        }
      }
      f(t, m, l);
    }
  }

  std::vector<int> m_first, m_count;
  int m_size;
  Fixed_pattern_matrix m_H, m_S;
  Sparse_matrix m_A;
};

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
