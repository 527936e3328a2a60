// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Sparse linear algebra of the flows: the matrix type, a matrix refilled in
// its fixed pattern, and a symmetric positive definite solver that reuses its
// symbolic analysis while the pattern does not change.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_SPARSE_SOLVER_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_SPARSE_SOLVER_H

#include <CGAL/assertions.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

typedef Eigen::SparseMatrix<double> Sparse_matrix;

/// A square sparse matrix whose pattern the mesh fixes, assembled from the
/// same contributions in the same order at every iteration. The first
/// assembly sorts them (setFromTriplets) and records where each one lands;
/// later ones add them straight into the value array, which gives the same
/// sums in the same order (bit-identical values) without the sort, and the
/// same pattern keeps the solver's symbolic analysis.
class Fixed_pattern_matrix
{
public:
  /// `contributions(add)` calls add(i, j, v) for each contribution.
  template <class Contributions>
  const Sparse_matrix& assemble(std::size_t n, Contributions&& contributions)
  {
    return assemble(n, n, std::forward<Contributions>(contributions));
  }

  /// The same for a `rows` × `cols` matrix.
  template <class Contributions>
  const Sparse_matrix& assemble(std::size_t rows, std::size_t cols, Contributions&& contributions)
  {
    if(!m_built || std::size_t(m_matrix.rows()) != rows || std::size_t(m_matrix.cols()) != cols) {
      std::vector<Eigen::Triplet<double> > trip;
      trip.reserve(m_slot.size());
      contributions([&trip](int i, int j, double v) { trip.emplace_back(i, j, v); });
      m_matrix.resize(Eigen::Index(rows), Eigen::Index(cols));
      m_matrix.setFromTriplets(trip.begin(), trip.end());
      m_matrix.makeCompressed();
      const int* outer = m_matrix.outerIndexPtr();
      const int* inner = m_matrix.innerIndexPtr();
      m_slot.resize(trip.size());
      for(std::size_t k = 0; k < trip.size(); ++k)
        m_slot[k] = int(std::lower_bound(inner + outer[trip[k].col()], inner + outer[trip[k].col() + 1], trip[k].row()) - inner);
      m_built = true;
      return m_matrix;
    }
    double* value = m_matrix.valuePtr();
    std::fill(value, value + m_matrix.nonZeros(), 0.);
    const int* slot = m_slot.data();
    contributions([value, &slot](int, int, double v) { value[*slot++] += v; });
    CGAL_assertion(slot == m_slot.data() + m_slot.size());
    return m_matrix;
  }

  /// The last assembled matrix.
  const Sparse_matrix& matrix() const { return m_matrix; }

private:
  Sparse_matrix m_matrix;
  std::vector<int> m_slot; // per contribution, its index in the value array
  bool m_built = false;
};

/// Factorises a sequence of SPD matrices, redoing the symbolic analysis only
/// when the sparsity pattern changes (paper mode after flips).
template <class EigenSolver>
class Pattern_reusing_solver
{
public:
  explicit Pattern_reusing_solver(EigenSolver& solver) : m_solver(solver) {}

  /// The symbolic analysis of `A`'s pattern, unless it is the last one's:
  /// the next factorize() of that pattern does not redo it.
  void analyze(const Sparse_matrix& A)
  {
    if(same_pattern(A)) return;
    m_solver.analyzePattern(A);
    m_outer.assign(A.outerIndexPtr(), A.outerIndexPtr() + A.outerSize() + 1);
    m_inner.assign(A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros());
    ++m_analyses;
  }

  bool factorize(const Sparse_matrix& A)
  {
    analyze(A);
    m_solver.factorize(A);
    return m_solver.info() == Eigen::Success;
  }

  bool solve(const Eigen::VectorXd& b, Eigen::VectorXd& x)
  {
    x = m_solver.solve(b);
    return m_solver.info() == Eigen::Success && x.allFinite();
  }

  /// Several right-hand sides in one pass over the factor.
  bool solve(const Eigen::MatrixXd& b, Eigen::MatrixXd& x)
  {
    x = m_solver.solve(b);
    return m_solver.info() == Eigen::Success && x.allFinite();
  }

  std::size_t analyses() const { return m_analyses; }

  /// The wrapped solver.
  EigenSolver& solver() { return m_solver; }

  /// Takes over the analysis that `other`, wrapping the same solver, made
  /// (its last factorization's pattern): a matrix of that pattern is then
  /// factorised without a new analysis. The Tutte system of the start and
  /// the interior stiffness of the flow share their pattern.
  void adopt_analysis(const Pattern_reusing_solver& other)
  {
    CGAL_precondition(&other.m_solver == &m_solver);
    m_outer = other.m_outer;
    m_inner = other.m_inner;
    m_analyses += other.m_analyses;
  }

private:
  bool same_pattern(const Sparse_matrix& A) const
  {
    if(!A.isCompressed() || m_outer.size() != std::size_t(A.outerSize() + 1) ||
       m_inner.size() != std::size_t(A.nonZeros()))
      return false;
    return std::equal(m_outer.begin(), m_outer.end(), A.outerIndexPtr()) &&
           std::equal(m_inner.begin(), m_inner.end(), A.innerIndexPtr());
  }

  EigenSolver& m_solver;
  std::vector<typename Sparse_matrix::StorageIndex> m_outer, m_inner;
  std::size_t m_analyses = 0;
};

/// The interior of a Tutte-like embedding: solves L x = rhs (both columns)
/// for the unknowns numbered by `idx` (−1: a fixed vertex, left as it is in
/// `uv`) and writes them into `uv`. False when the factorization or a solve
/// fails or gives a non-finite value.
template <class EigenSolver, class Point2>
bool solve_interior_2(Eigen::Index unknowns, const std::vector<Eigen::Triplet<double> >& trip,
                      const Eigen::MatrixXd& rhs, const std::vector<int>& idx, std::vector<Point2>& uv)
{
  Sparse_matrix L(unknowns, unknowns);
  L.setFromTriplets(trip.begin(), trip.end());
  L.makeCompressed();
  EigenSolver solver;
  solver.compute(L);
  if(solver.info() != Eigen::Success) return false;
  for(int c = 0; c < 2; ++c) {
    const Eigen::VectorXd x = solver.solve(Eigen::VectorXd(rhs.col(c)));
    if(solver.info() != Eigen::Success || !x.allFinite()) return false;
    for(std::size_t v = 0; v < uv.size(); ++v)
      if(idx[v] >= 0) uv[v][std::size_t(c)] = x[idx[v]];
  }
  return true;
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
