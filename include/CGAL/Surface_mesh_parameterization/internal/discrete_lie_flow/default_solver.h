// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The default sparse symmetric positive definite solver of the flows:
// CHOLMOD's supernodal Cholesky factorisation when the package is built with
// it (CGAL_DLF_USE_CHOLMOD), else Eigen's simplicial LDLᵀ.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_DEFAULT_SOLVER_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_DEFAULT_SOLVER_H

#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/sparse_solver.h>

#include <Eigen/SparseCholesky>
#ifdef CGAL_DLF_USE_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

#ifdef CGAL_DLF_USE_CHOLMOD
typedef Eigen::CholmodSupernodalLLT<Sparse_matrix, Eigen::Lower> Default_spd_solver;
#else
typedef Eigen::SimplicialLDLT<Sparse_matrix, Eigen::Lower> Default_spd_solver;
#endif

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
