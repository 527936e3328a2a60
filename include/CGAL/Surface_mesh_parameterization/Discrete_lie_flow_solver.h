// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_DISCRETE_LIE_FLOW_SOLVER_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_DISCRETE_LIE_FLOW_SOLVER_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#ifdef CGAL_DLF_USE_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgDiscreteLieFlowOptions
/// The sparse symmetric positive definite solver of the Discrete Lie Flow
/// parameterizers' `Solver_traits` default
/// (`Eigen_solver_traits<Discrete_lie_flow_default_spd_solver>`), which
/// their flows also factorise with: CHOLMOD's supernodal LLᵀ when the
/// package is built with it (`CGAL_DLF_USE_CHOLMOD`), else Eigen's
/// simplicial LDLᵀ; both on the lower triangle of an
/// `Eigen::SparseMatrix<double>`.
#ifdef CGAL_DLF_USE_CHOLMOD
typedef Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> Discrete_lie_flow_default_spd_solver;
#else
typedef Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower> Discrete_lie_flow_default_spd_solver;
#endif

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
