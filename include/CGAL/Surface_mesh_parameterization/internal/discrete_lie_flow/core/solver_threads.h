// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The threads of the BLAS under the sparse solver, for the length of a flow.
// CHOLMOD's supernodal factorization calls the BLAS; a threaded OpenBLAS
// keeps its threads spinning between calls, and on a small or busy machine
// they take the cores the flow needs (measured on 2 cores: the default run
// of a 66K-face disk took 3x its single-threaded time, doc/design.md,
// "Solver threads"). The flow factorizes matrices of one to a few
// hundred thousand unknowns many times, which gain nothing measurable from
// more threads there.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_SOLVER_THREADS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_SOLVER_THREADS_H

#include <cstddef>
#include <cstdlib>

#if defined(__unix__) || defined(__APPLE__)
#include <dlfcn.h>
#define CGAL_DLF_CAN_SET_BLAS_THREADS 1
#endif

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// Below this many vertices the automatic setting runs the BLAS on one thread.
constexpr std::size_t single_blas_thread_below = 500000;

/// Sets the number of OpenBLAS threads for its lifetime and restores the
/// previous number after: `threads` > 0 that many; 0 automatic (one below
/// `single_blas_thread_below` vertices, unchanged above); < 0 unchanged.
/// Automatic also settles CHOLMOD's own parallel loops (it asks for 4
/// threads whatever the machine) for the same lifetime: below
/// `single_blas_thread_below` vertices they run on the calling thread
/// (OpenMP's max-active-levels 0), above they get at most as many threads
/// as there are idle cores (OpenMP's dynamic adjustment: the number of
/// cores minus the load average, at least 1). Below, the dynamic adjustment
/// still gave teams of 2 on an idle 2-core machine, for loops of a few
/// dozen entries; their threads spun on the core the flow's own threads
/// use (a 96K-vertex sphere: 22.4 s against 20.8 s on one thread).
/// Does nothing when the user chose through the environment
/// (OPENBLAS_NUM_THREADS, GOTO_NUM_THREADS, OMP_NUM_THREADS,
/// OMP_THREAD_LIMIT; OMP_DYNAMIC for the dynamic adjustment) or when the
/// process has no OpenBLAS or no OpenMP runtime (looked up at run time, so
/// that nothing is linked for them).
class Scoped_blas_threads
{
public:
  Scoped_blas_threads(int threads, std::size_t vertices)
  {
#ifdef CGAL_DLF_CAN_SET_BLAS_THREADS
    for(const char* v : { "OPENBLAS_NUM_THREADS", "GOTO_NUM_THREADS", "OMP_NUM_THREADS", "OMP_THREAD_LIMIT" })
      if(std::getenv(v) != nullptr) return;
    if(threads == 0 && vertices < single_blas_thread_below && std::getenv("OMP_MAX_ACTIVE_LEVELS") == nullptr &&
       std::getenv("OMP_NESTED") == nullptr) {
      m_set_levels = reinterpret_cast<Set>(dlsym(RTLD_DEFAULT, "omp_set_max_active_levels"));
      const Get get_levels = reinterpret_cast<Get>(dlsym(RTLD_DEFAULT, "omp_get_max_active_levels"));
      if(m_set_levels == nullptr || get_levels == nullptr) m_set_levels = nullptr;
      else { m_previous_levels = get_levels(); m_set_levels(0); }
    } else if(threads == 0 && std::getenv("OMP_DYNAMIC") == nullptr) {
      m_set_dynamic = reinterpret_cast<Set>(dlsym(RTLD_DEFAULT, "omp_set_dynamic"));
      const Get get_dynamic = reinterpret_cast<Get>(dlsym(RTLD_DEFAULT, "omp_get_dynamic"));
      if(m_set_dynamic == nullptr || get_dynamic == nullptr || get_dynamic() != 0) m_set_dynamic = nullptr;
      else m_set_dynamic(1);
    }
    if(threads == 0) threads = vertices < single_blas_thread_below ? 1 : -1;
    if(threads < 0) return;
    m_set = reinterpret_cast<Set>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
    const Get get = reinterpret_cast<Get>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
    if(m_set == nullptr || get == nullptr) { m_set = nullptr; return; }
    m_previous = get();
    if(m_previous == threads) { m_set = nullptr; return; }
    m_set(threads);
#else
    (void)threads;
    (void)vertices;
#endif
  }
  ~Scoped_blas_threads()
  {
    if(m_set != nullptr) m_set(m_previous);
    if(m_set_dynamic != nullptr) m_set_dynamic(0);
    if(m_set_levels != nullptr) m_set_levels(m_previous_levels);
  }
  Scoped_blas_threads(const Scoped_blas_threads&) = delete;
  Scoped_blas_threads& operator=(const Scoped_blas_threads&) = delete;

private:
  typedef void (*Set)(int);
  typedef int (*Get)();
  Set m_set = nullptr, m_set_dynamic = nullptr, m_set_levels = nullptr;
  int m_previous = 0, m_previous_levels = 0;
};

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
