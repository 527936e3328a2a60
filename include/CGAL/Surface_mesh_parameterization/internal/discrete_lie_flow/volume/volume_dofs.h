// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The unknowns of the volumetric flow's Gauss–Newton system: three per
// interior vertex, two per border vertex (the tangent plane of the sphere at
// its point), and the 3 × 3 blocks of the system per vertex that serve as
// its preconditioner and its damping.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_VOLUME_DOFS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_VOLUME_DOFS_H

#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/geometry.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// The degrees of freedom: an interior vertex moves in space (3), a border
/// vertex in the tangent plane of the sphere at its point (2).
class Volume_dofs
{
public:
  /// `fixed_border`: the border vertices do not move (no dofs).
  Volume_dofs(const std::vector<char>& on_border, bool fixed_border)
    : m_offset(on_border.size()), m_border(on_border), m_fixed(fixed_border)
  {
    for(std::size_t v = 0; v < on_border.size(); ++v) {
      m_offset[v] = m_n;
      m_n += on_border[v] ? (fixed_border ? 0 : 2) : 3;
    }
    m_frame.resize(on_border.size());
  }
  int size() const { return m_n; }
  /// Tangent frames at the current border points.
  void update_frames(const std::vector<Vec3>& x)
  {
    for(std::size_t v = 0; v < x.size(); ++v) {
      if(!m_border[v]) continue;
      const Vec3 n = normalized(x[v]);
      const Vec3 a = std::abs(n[0]) < 0.6 ? Vec3{{ 1, 0, 0 }} : Vec3{{ 0, 1, 0 }};
      const Vec3 t1 = normalized(cross(n, a));
      m_frame[v] = {{ t1, cross(n, t1) }};
    }
  }
  /// Vertex displacements of the dof vector s.
  void expand(const Eigen::VectorXd& s, std::vector<Vec3>& d) const
  {
    d.resize(m_offset.size());
    for(std::size_t v = 0; v < m_offset.size(); ++v) {
      const int o = m_offset[v];
      if(m_border[v] && m_fixed) {
        d[v] = {{ 0, 0, 0 }};
      } else if(m_border[v]) {
        const Vec3& a = m_frame[v][0];
        const Vec3& b = m_frame[v][1];
        d[v] = {{ s[o] * a[0] + s[o + 1] * b[0], s[o] * a[1] + s[o + 1] * b[1], s[o] * a[2] + s[o + 1] * b[2] }};
      } else {
        d[v] = {{ s[o], s[o + 1], s[o + 2] }};
      }
    }
  }
  /// The dof components of per-vertex vectors (the transpose of expand).
  void restrict(const std::vector<Vec3>& g, Eigen::VectorXd& s) const
  {
    s.resize(m_n);
    for(std::size_t v = 0; v < m_offset.size(); ++v) {
      const int o = m_offset[v];
      if(m_border[v] && m_fixed) continue;
      if(m_border[v]) {
        s[o] = dot(g[v], m_frame[v][0]);
        s[o + 1] = dot(g[v], m_frame[v][1]);
      } else {
        s[o] = g[v][0]; s[o + 1] = g[v][1]; s[o + 2] = g[v][2];
      }
    }
  }
  /// The inverse of the block diagonal (3×3 per vertex, projected on the
  /// frame), with λ·(its trace / size) added: the preconditioner.
  void block_inverse(const std::vector<std::array<double, 6> >& M, double lambda,
                     std::vector<std::array<double, 9> >& inv) const
  {
    inv.resize(m_offset.size());
    for(std::size_t v = 0; v < m_offset.size(); ++v) {
      const std::array<double, 6>& m = M[v]; // xx yy zz xy xz yz
      if(m_border[v] && m_fixed) continue;
      Eigen::Matrix3d A;
      A << m[0], m[3], m[4], m[3], m[1], m[5], m[4], m[5], m[2];
      if(m_border[v]) {
        Eigen::Matrix<double, 3, 2> F;
        for(int k = 0; k < 2; ++k)
          for(int c = 0; c < 3; ++c) F(c, k) = m_frame[v][std::size_t(k)][std::size_t(c)];
        Eigen::Matrix2d B = F.transpose() * A * F;
        const double reg = lambda * (std::max)(B.trace() / 2, 1e-300);
        B(0, 0) += reg; B(1, 1) += reg;
        const Eigen::Matrix2d Bi = B.inverse();
        inv[v] = {{ Bi(0, 0), Bi(0, 1), Bi(1, 1), 0, 0, 0, 0, 0, 0 }};
      } else {
        const double reg = lambda * (std::max)(A.trace() / 3, 1e-300);
        A(0, 0) += reg; A(1, 1) += reg; A(2, 2) += reg;
        const Eigen::Matrix3d Ai = A.inverse();
        for(int i = 0; i < 3; ++i)
          for(int j = 0; j < 3; ++j) inv[v][std::size_t(3 * i + j)] = Ai(i, j);
      }
    }
  }
  void apply_block(const std::vector<std::array<double, 9> >& inv, const Eigen::VectorXd& r, Eigen::VectorXd& z) const
  {
    z.resize(m_n);
    apply_block(inv, r, z, 0, m_offset.size());
  }
  /// The same on the vertices [begin, end) (z already sized).
  void apply_block(const std::vector<std::array<double, 9> >& inv, const Eigen::VectorXd& r, Eigen::VectorXd& z,
                   std::size_t begin, std::size_t end) const
  {
    for(std::size_t v = begin; v < end; ++v) {
      const int o = m_offset[v];
      const std::array<double, 9>& a = inv[v];
      if(m_border[v] && m_fixed) continue;
      if(m_border[v]) {
        z[o] = a[0] * r[o] + a[1] * r[o + 1];
        z[o + 1] = a[1] * r[o] + a[2] * r[o + 1];
      } else {
        for(int i = 0; i < 3; ++i) z[o + i] = a[std::size_t(3 * i)] * r[o] + a[std::size_t(3 * i + 1)] * r[o + 1] + a[std::size_t(3 * i + 2)] * r[o + 2];
      }
    }
  }
  /// Projected block diagonal entries times λ (the regularisation added to H).
  void apply_regularization(const std::vector<std::array<double, 6> >& M, double lambda, const Eigen::VectorXd& s,
                            Eigen::VectorXd& y) const
  {
    for(std::size_t v = 0; v < m_offset.size(); ++v) {
      const int o = m_offset[v];
      const std::array<double, 6>& m = M[v];
      const double tr = m[0] + m[1] + m[2];
      if(m_border[v] && m_fixed) continue;
      if(m_border[v]) {
        // trace of FᵀAF ≈ tr(A) − nᵀAn; the scale matters, not the exact value
        const double reg = lambda * tr / 3;
        y[o] += reg * s[o]; y[o + 1] += reg * s[o + 1];
      } else {
        const double reg = lambda * tr / 3;
        y[o] += reg * s[o]; y[o + 1] += reg * s[o + 1]; y[o + 2] += reg * s[o + 2];
      }
    }
  }
  bool on_border(std::size_t v) const { return m_border[v] != 0; }
  /// The first dof of vertex v and how many it has (0, 2 or 3); `c`
  /// receives the dof components of the ambient vector g.
  int components(std::size_t v, const Vec3& g, double c[3]) const
  {
    if(m_border[v] && m_fixed) return 0;
    if(m_border[v]) {
      c[0] = dot(g, m_frame[v][0]);
      c[1] = dot(g, m_frame[v][1]);
      return 2;
    }
    c[0] = g[0]; c[1] = g[1]; c[2] = g[2];
    return 3;
  }
  int offset(std::size_t v) const { return m_offset[v]; }
  /// The ambient vector of the dof components c of vertex v (expand for one vertex).
  Vec3 ambient(std::size_t v, const double* c) const
  {
    if(m_border[v] && m_fixed) return {{ 0, 0, 0 }};
    if(!m_border[v]) return {{ c[0], c[1], c[2] }};
    const Vec3& a = m_frame[v][0];
    const Vec3& b = m_frame[v][1];
    return {{ c[0] * a[0] + c[1] * b[0], c[0] * a[1] + c[1] * b[1], c[0] * a[2] + c[1] * b[2] }};
  }
  /// The first dof of vertex v, or the number of dofs for v = the number of vertices.
  int offset_or_size(std::size_t v) const { return v < m_offset.size() ? m_offset[v] : m_n; }

private:
  std::vector<int> m_offset;
  std::vector<char> m_border;
  std::vector<std::array<Vec3, 2> > m_frame;
  bool m_fixed = false;
  int m_n = 0;
};

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
