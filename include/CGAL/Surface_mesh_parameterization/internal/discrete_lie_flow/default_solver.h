// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The default sparse SPD solver of the package's parameterizers. With
// CHOLMOD available, its supernodal LLT pays only on large systems: on the
// meshes of CGAL's data set Eigen's simplicial LDLT was faster up to tens of
// thousands of unknowns (doc/certified_mode.md, "Solver"), so the choice is
// made per matrix, by its size.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_DEFAULT_SOLVER_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_DEFAULT_SOLVER_H

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#ifdef DLF_USE_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

#ifdef DLF_USE_CHOLMOD

/// An Eigen-style SPD solver (`analyzePattern`, `factorize`, `compute`,
/// `info`, `solve`) that factorises matrices of at least `large_rows` rows
/// with CHOLMOD's supernodal LLT and smaller ones with Eigen's simplicial
/// LDLT. The choice is made when the pattern is analysed (or in `compute`).
class Size_switched_spd_solver
{
public:
  typedef double Scalar;
  typedef Eigen::SparseMatrix<double> MatrixType;
  typedef MatrixType::StorageIndex StorageIndex;

  /// Measured on whole runs (doc/certified_mode.md, "Solver"): 50,000 beat
  /// both CHOLMOD alone and SimplicialLDLT alone, with one thread and with
  /// two, except bear.off after Loop on one thread (+2% against CHOLMOD).
  static constexpr Eigen::Index large_rows = 50000;

  Size_switched_spd_solver() = default;
  Size_switched_spd_solver(const Size_switched_spd_solver&) = delete;
  Size_switched_spd_solver& operator=(const Size_switched_spd_solver&) = delete;

  void analyzePattern(const MatrixType& A)
  {
    m_large = A.rows() >= large_rows;
    if(m_large) m_supernodal.analyzePattern(A);
    else m_simplicial.analyzePattern(A);
  }

  void factorize(const MatrixType& A)
  {
    if(m_large) m_supernodal.factorize(A);
    else m_simplicial.factorize(A);
  }

  Size_switched_spd_solver& compute(const MatrixType& A)
  {
    analyzePattern(A);
    factorize(A);
    return *this;
  }

  Eigen::ComputationInfo info() const { return m_large ? m_supernodal.info() : m_simplicial.info(); }

  /// Whether the last analysed matrix went to CHOLMOD.
  bool supernodal() const { return m_large; }

  template <class Rhs>
  Eigen::Matrix<double, Eigen::Dynamic, Rhs::ColsAtCompileTime> solve(const Eigen::MatrixBase<Rhs>& b) const
  {
    if(m_large) return m_supernodal.solve(b);
    return m_simplicial.solve(b);
  }

private:
  Eigen::SimplicialLDLT<MatrixType, Eigen::Lower> m_simplicial;
  Eigen::CholmodSupernodalLLT<MatrixType, Eigen::Lower> m_supernodal;
  bool m_large = false;
};

typedef Size_switched_spd_solver Default_spd_solver;

#else

typedef Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower> Default_spd_solver;

#endif

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
