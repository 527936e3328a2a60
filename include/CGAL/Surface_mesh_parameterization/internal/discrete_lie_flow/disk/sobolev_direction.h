// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Sobolev direction of the certified flow: d = −M⁻¹ g, with M the
// Dirichlet energy of displacement fields on the current domain mesh
// restricted to the dofs (interior: free; boundary: along the curve).
//
// M is applied through a block factorisation that only ever factorises the
// scalar interior stiffness L_II (x and y share it):
//   M = [I 0; Cᵀ A⁻¹ I] · diag(A, S̃) · [I A⁻¹ C; 0 I],  A = L_II ⊗ I₂,
// with the boundary Schur complement S̃ replaced by its diagonal bound
// diag(L_BB). M stays symmetric positive definite, so −M⁻¹g is a descent
// direction; the interior follows the boundary's move harmonically. The
// exactly coupled system costs 4–5 scalar factorisations (fill through the
// tangential coupling of x and y), this one costs one.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_SOBOLEV_DIRECTION_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_SOBOLEV_DIRECTION_H

#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/cotangent_laplacian.h>

#include <algorithm>
#include <array>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

template <class EigenSolver>
class Split_sobolev_direction
{
public:
  /// `boundary_of[v]` ≥ 0 for boundary vertices; interior vertices get
  /// consecutive interior indices.
  Split_sobolev_direction(const std::vector<int>& boundary_of, EigenSolver& solver)
    : m_interior(boundary_of.size(), -1), m_solver(solver)
  {
    for(std::size_t v = 0; v < boundary_of.size(); ++v)
      if(boundary_of[v] < 0) m_interior[v] = m_ni++;
  }

  std::size_t analyses() const { return m_solver.analyses(); }

  /// The analysis of `analysed` (same solver, a matrix of L_II's pattern) serves L_II.
  void adopt_analysis(const Pattern_reusing_solver<EigenSolver>& analysed) { m_solver.adopt_analysis(analysed); }

  /// Assembles the cotangent stiffness of `faces` over `uv` into L_II and
  /// L_IB (fixed patterns: after the first call only numbers are added) and
  /// diag(L_BB).
  void assemble(const std::vector<Vec2>& uv, const std::vector<Face>& faces)
  {
    const std::size_t n = uv.size();
    m_diag.assign(n, 0.);
    std::vector<std::array<double, 3> >& w = m_cotangents;
    w.resize(faces.size());
    for(std::size_t f = 0; f < faces.size(); ++f) {
      const Face& t = faces[f];
      w[f] = half_cotangents(uv[t[0]], uv[t[1]], uv[t[2]]);
      for(int k = 0; k < 3; ++k) {
        m_diag[std::size_t(t[(k + 1) % 3])] += w[f][std::size_t(k)];
        m_diag[std::size_t(t[(k + 2) % 3])] += w[f][std::size_t(k)];
      }
    }
    // Edge (i, j) opposite corner k: −w off the diagonal, +w on it.
    const auto edges = [&](auto&& edge) {
      for(std::size_t f = 0; f < faces.size(); ++f)
        for(int k = 0; k < 3; ++k)
          edge(faces[f][(k + 1) % 3], faces[f][(k + 2) % 3], w[f][std::size_t(k)]);
    };
    m_LII.assemble(std::size_t(m_ni), std::size_t(m_ni), [&](auto&& add) {
      edges([&](int i, int j, double c) {
        const int ii = m_interior[std::size_t(i)], ij = m_interior[std::size_t(j)];
        if(ii >= 0 && ij >= 0) { add(ii, ij, -c); add(ij, ii, -c); }
        if(ii >= 0) add(ii, ii, c);
        if(ij >= 0) add(ij, ij, c);
      });
    });
    m_LIB.assemble(std::size_t(m_ni), n, [&](auto&& add) {
      edges([&](int i, int j, double c) {
        const int ii = m_interior[std::size_t(i)], ij = m_interior[std::size_t(j)];
        if(ii >= 0 && ij < 0) add(ii, j, -c);
        if(ij >= 0 && ii < 0) add(ij, i, -c);
      });
    });
  }

  /// Factorises the assembled L_II.
  bool factorize() { return m_ni == 0 || m_solver.factorize(L_II()); }

  /// Direction (per vertex, 2D) and its boundary slides, for the gradient
  /// `g` (per vertex, 2D); `tangent[v]` is the unit tangent of a sliding
  /// boundary vertex and (0, 0) for a fixed one.
  bool solve(const std::vector<Vec2>& g, const std::vector<Vec2>& tangent, std::vector<Vec2>& d)
  {
    const std::size_t n = g.size();
    d.assign(n, Vec2{{ 0, 0 }});
    Eigen::MatrixXd gi(m_ni, 2), z;
    for(std::size_t v = 0; v < n; ++v)
      if(m_interior[v] >= 0) { gi(m_interior[v], 0) = g[v][0]; gi(m_interior[v], 1) = g[v][1]; }
    if(m_ni > 0 && !solve_interior(-gi, z)) return false;
    // Boundary: s = −S̃⁻¹ Tᵀ (g_B + L_BI z).
    Eigen::MatrixXd lbz = (m_ni > 0) ? Eigen::MatrixXd(L_IB().transpose() * z) : Eigen::MatrixXd::Zero(Eigen::Index(n), 2);
    Eigen::MatrixXd db = Eigen::MatrixXd::Zero(Eigen::Index(n), 2);
    for(std::size_t v = 0; v < n; ++v) {
      if(m_interior[v] >= 0 || m_diag[v] <= 0) continue;
      const Vec2& t = tangent[v];
      const double gs = t[0] * (g[v][0] + lbz(Eigen::Index(v), 0)) + t[1] * (g[v][1] + lbz(Eigen::Index(v), 1));
      const double s = -gs / m_diag[v];
      d[v] = {{ s * t[0], s * t[1] }};
      db(Eigen::Index(v), 0) = d[v][0];
      db(Eigen::Index(v), 1) = d[v][1];
    }
    // Interior: z − A⁻¹ C d_B, the harmonic follow-up of the boundary move.
    if(m_ni > 0) {
      Eigen::MatrixXd w;
      if(!solve_interior(Eigen::MatrixXd(L_IB() * db), w)) return false;
      z -= w;
      for(std::size_t v = 0; v < n; ++v)
        if(m_interior[v] >= 0) d[v] = {{ z(m_interior[v], 0), z(m_interior[v], 1) }};
    }
    return true;
  }

private:
  const Sparse_matrix& L_II() const { return m_LII.matrix(); }
  const Sparse_matrix& L_IB() const { return m_LIB.matrix(); }

  // x and y in one pass over the factor.
  bool solve_interior(const Eigen::MatrixXd& b, Eigen::MatrixXd& x) { return m_solver.solve(b, x); }

  std::vector<int> m_interior;
  int m_ni = 0;
  Pattern_reusing_solver<EigenSolver> m_solver;
  Fixed_pattern_matrix m_LII, m_LIB;
  std::vector<double> m_diag;
  std::vector<std::array<double, 3> > m_cotangents; // per face, per corner
};

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
