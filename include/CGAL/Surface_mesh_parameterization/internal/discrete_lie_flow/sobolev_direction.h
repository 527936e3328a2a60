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

#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/cotangent_laplacian.h>

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

  /// Assembles the cotangent stiffness of `faces` over `uv` straight into
  /// the fixed patterns of L_II and L_IB (and diag(L_BB)). The patterns and
  /// the slot of every face's contribution are built on the first call:
  /// later calls only add numbers.
  void assemble(const std::vector<Vec2>& uv, const std::vector<Face>& faces)
  {
    if(m_slots.empty()) build_patterns(uv.size(), faces);
    std::fill(m_LII.valuePtr(), m_LII.valuePtr() + m_LII.nonZeros(), 0.);
    std::fill(m_LIB.valuePtr(), m_LIB.valuePtr() + m_LIB.nonZeros(), 0.);
    std::fill(m_diag.begin(), m_diag.end(), 0.);
    double* vii = m_LII.valuePtr();
    double* vib = m_LIB.valuePtr();
    const int* slot = m_slots.data();
    for(const Face& t : faces) {
      const std::array<double, 3> w = half_cotangents(uv[t[0]], uv[t[1]], uv[t[2]]);
      for(int k = 0; k < 3; ++k, slot += 4) {
        const int i = t[(k + 1) % 3], j = t[(k + 2) % 3];
        m_diag[std::size_t(i)] += w[k];
        m_diag[std::size_t(j)] += w[k];
        // slots: (i,j), (j,i) off-diagonal; (i,i), (j,j) diagonal; ≥ 2^30 marks L_IB
        for(int e = 0; e < 4; ++e) {
          const int sl = slot[e];
          if(sl < 0) continue;
          const double value = e < 2 ? -w[k] : w[k];
          if(sl >= ib_mark) vib[sl - ib_mark] += value; else vii[sl] += value;
        }
      }
    }
  }

  /// Factorises the assembled L_II.
  bool factorize() { return m_ni == 0 || m_solver.factorize(m_LII); }

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
    Eigen::MatrixXd lbz = (m_ni > 0) ? Eigen::MatrixXd(m_LIB.transpose() * z) : Eigen::MatrixXd::Zero(Eigen::Index(n), 2);
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
      if(!solve_interior(Eigen::MatrixXd(m_LIB * db), w)) return false;
      z -= w;
      for(std::size_t v = 0; v < n; ++v)
        if(m_interior[v] >= 0) d[v] = {{ z(m_interior[v], 0), z(m_interior[v], 1) }};
    }
    return true;
  }

private:
  static const int ib_mark = 1 << 30;

  void build_patterns(std::size_t n, const std::vector<Face>& faces)
  {
    std::vector<Eigen::Triplet<double> > tii, tib;
    for(const Face& t : faces)
      for(int k = 0; k < 3; ++k) {
        const int i = t[(k + 1) % 3], j = t[(k + 2) % 3];
        const int ii = m_interior[std::size_t(i)], ij = m_interior[std::size_t(j)];
        if(ii >= 0 && ij >= 0) { tii.emplace_back(ii, ij, 1.); tii.emplace_back(ij, ii, 1.); }
        if(ii >= 0) tii.emplace_back(ii, ii, 1.);
        if(ij >= 0) tii.emplace_back(ij, ij, 1.);
        if(ii >= 0 && ij < 0) tib.emplace_back(ii, j, 1.);
        if(ij >= 0 && ii < 0) tib.emplace_back(ij, i, 1.);
      }
    m_LII.resize(m_ni, m_ni);
    m_LII.setFromTriplets(tii.begin(), tii.end());
    m_LII.makeCompressed();
    m_LIB.resize(m_ni, Eigen::Index(n));
    m_LIB.setFromTriplets(tib.begin(), tib.end());
    m_LIB.makeCompressed();
    m_diag.assign(n, 0.);
    auto find = [](const Sparse_matrix& M, int r, int c) {
      const int* inner = M.innerIndexPtr();
      const int* lo = inner + M.outerIndexPtr()[c];
      const int* hi = inner + M.outerIndexPtr()[c + 1];
      return int(std::lower_bound(lo, hi, r) - inner);
    };
    m_slots.assign(faces.size() * 12, -1);
    int* slot = m_slots.data();
    for(const Face& t : faces)
      for(int k = 0; k < 3; ++k, slot += 4) {
        const int i = t[(k + 1) % 3], j = t[(k + 2) % 3];
        const int ii = m_interior[std::size_t(i)], ij = m_interior[std::size_t(j)];
        if(ii >= 0 && ij >= 0) { slot[0] = find(m_LII, ii, ij); slot[1] = find(m_LII, ij, ii); }
        else if(ii >= 0) slot[0] = ib_mark + find(m_LIB, ii, j);
        else if(ij >= 0) slot[1] = ib_mark + find(m_LIB, ij, i);
        if(ii >= 0) slot[2] = find(m_LII, ii, ii);
        if(ij >= 0) slot[3] = find(m_LII, ij, ij);
      }
  }

  bool solve_interior(const Eigen::MatrixXd& b, Eigen::MatrixXd& x)
  {
    x.resize(b.rows(), b.cols());
    for(Eigen::Index c = 0; c < b.cols(); ++c) {
      Eigen::VectorXd xc;
      if(!m_solver.solve(b.col(c), xc)) return false;
      x.col(c) = xc;
    }
    return true;
  }

  std::vector<int> m_interior;
  int m_ni = 0;
  Pattern_reusing_solver<EigenSolver> m_solver;
  Sparse_matrix m_LII, m_LIB;
  std::vector<double> m_diag;
  std::vector<int> m_slots; // per face, per edge: 4 slots in L_II (or L_IB, offset by ib_mark)
};

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
