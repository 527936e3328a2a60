// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The default sparse symmetric positive definite solver of the flows:
// CHOLMOD's supernodal Cholesky factorisation when the package is built with
// it (CGAL_DLF_USE_CHOLMOD), else Eigen's simplicial LDLᵀ.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_DEFAULT_SOLVER_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_DEFAULT_SOLVER_H

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_solver.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/sparse_solver.h>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

// Defined in the public header: it is the parameterizers' default too.
typedef Discrete_lie_flow_default_spd_solver Default_spd_solver;

/// Coarser supernodes for the repeated factorisations of a large mesh's
/// matrices (to be called before the first one). CHOLMOD enters OpenMP
/// regions per supernode and per update between supernodes, a system call
/// each even on one thread; CHOLMOD's default amalgamation (nrelax 4, 16,
/// 48) leaves the 96K-vertex stiffness of a scanned mesh with tens of
/// thousands of them. Merging up to 16, 48, 128 columns (zrelax 0.8, 0.3,
/// 0.1) factorised it 10% faster (doc/sphere.md, "Large irregular meshes:
/// the cost of an iteration").
/// Other solvers are left as they are.
template <class Solver>
void use_coarse_supernodes(Solver&) {}

#ifdef CGAL_DLF_USE_CHOLMOD
template <class Matrix, int UpLo>
void use_coarse_supernodes(Eigen::CholmodSupernodalLLT<Matrix, UpLo>& solver)
{
  cholmod_common& c = solver.cholmod();
  c.nrelax[0] = 16; c.nrelax[1] = 48; c.nrelax[2] = 128;
  c.zrelax[0] = 0.8; c.zrelax[1] = 0.3; c.zrelax[2] = 0.1;
}
#endif

/// CHOLMOD's ordering by AMD alone. By default CHOLMOD also tries METIS when
/// AMD's fill looks high, as on large planar meshes, where METIS's fewer
/// nonzeros pay off over many factorizations of one pattern; for a single
/// factorization its ordering costs more than it saves (the Tutte start of
/// a 4.3M-face disk: 19.3 s with METIS tried, 9.9 s with AMD alone).
template <class Solver>
void use_amd_ordering(Solver&) {}

#ifdef CGAL_DLF_USE_CHOLMOD
template <class Matrix, int UpLo>
void use_amd_ordering(Eigen::CholmodSupernodalLLT<Matrix, UpLo>& solver)
{
  cholmod_common& c = solver.cholmod();
  c.nmethods = 1;
  c.method[0].ordering = CHOLMOD_AMD;
}
#endif

/// Frees the numeric values of the solver's factor and keeps its symbolic
/// analysis: a later factorization of a matrix of the same pattern needs no
/// new analysis, but no solve may come before it. For a factor that waits
/// unused (the Tutte start's, while the coarse levels run), the values are
/// most of its memory. Other solvers are left as they are.
template <class Solver>
void release_numeric_factor(Solver&) {}

#ifdef CGAL_DLF_USE_CHOLMOD
template <class Matrix, int UpLo>
void release_numeric_factor(Eigen::CholmodSupernodalLLT<Matrix, UpLo>& solver)
{
  typedef Eigen::CholmodSupernodalLLT<Matrix, UpLo> Solver;
  // Eigen keeps the factor protected: reached through a derived class.
  struct Access : Solver
  {
    static cholmod_factor* factor(Solver& s) { return s.*(&Access::m_cholmodFactor); }
  };
  cholmod_factor* L = Access::factor(solver);
  if(L == nullptr || L->xtype == CHOLMOD_PATTERN) return;
  // Numeric supernodal to symbolic supernodal: L->x goes, the supernodes stay.
  if constexpr(sizeof(typename Matrix::StorageIndex) == sizeof(SuiteSparse_long))
    cholmod_l_change_factor(CHOLMOD_PATTERN, L->is_ll, L->is_super, true, L->is_monotonic, L, &solver.cholmod());
  else
    cholmod_change_factor(CHOLMOD_PATTERN, L->is_ll, L->is_super, true, L->is_monotonic, L, &solver.cholmod());
}
#endif

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
