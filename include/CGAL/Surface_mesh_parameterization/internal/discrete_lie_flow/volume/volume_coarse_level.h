// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The coarse level of the volumetric flow's conjugate gradients: the
// vertices, in the flow's Morton order, cut into aggregates of consecutive
// ones (spatially compact), each aggregate moving by one translation
// (tangentially on the border). The Gauss–Newton matrix on that space,
// Pᵀ H P, is assembled per tet and factorised; the two-level preconditioner
// adds the exact coarse correction P (Pᵀ H P)⁻¹ Pᵀ r to the 3 × 3 blocks'
// (additive Schwarz): the blocks take every vertex's own scale, the coarse
// level the smooth, long-range part that a block preconditioner leaves to
// many steps (doc/volume.md, "Speed of the flow at 1M tetrahedra").

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_VOLUME_COARSE_LEVEL_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_VOLUME_COARSE_LEVEL_H

#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/default_solver.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/parallel_ranges.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/volume/volume_dofs.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/volume/volume_mesh.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <algorithm>
#include <array>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// The coarse space of aggregates of `aggregate` consecutive vertices (3
/// unknowns each), its matrix Pᵀ H P and its factorisation. The pattern is
/// made at the first factorisation, the symbolic analysis done once.
class Volume_coarse_level
{
public:
  explicit Volume_coarse_level(std::size_t aggregate) : m_k(aggregate)
  {
#ifdef CGAL_DLF_USE_CHOLMOD
    m_factor.cholmod().print = 0; // a singular Pᵀ H P is handled in factorize(), not an error to print
#endif
  }

  /// The number of aggregates (0 before the first factorisation).
  std::size_t aggregates() const { return m_aggregates; }
  /// The last factorisation succeeded.
  bool ok() const { return m_ok; }

  /// Assembles Pᵀ H P (P: an aggregate's translation e moves its vertices
  /// by e, tangentially on the border) for H = Σ_t w_t G_t G_tᵀ + the
  /// damping (per vertex `lambda` times a third of the trace of its block
  /// `M`, on its dofs), G_t the tet's corner gradients `grad`; factorises it.
  void factorize(const std::vector<Tet>& tets, const Volume_dofs& dofs, const std::vector<std::array<Vec3, 4> >& grad,
                 const std::vector<double>& w, const std::vector<std::array<double, 6> >& M, double lambda)
  {
    const std::size_t k = m_k;
    if(m_aggregates == 0) pattern(tets, M.size());
    std::fill(m_blocks.begin(), m_blocks.end(), std::array<double, 9>{{ 0, 0, 0, 0, 0, 0, 0, 0, 0 }});
    for(std::size_t t = 0; t < tets.size(); ++t) {
      const Tet& q = tets[t];
      // The tet's projected corner gradients, summed per aggregate.
      std::size_t agg[4];
      Vec3 h[4];
      int n = 0;
      for(int j = 0; j < 4; ++j) {
        const std::size_t v = std::size_t(q[std::size_t(j)]);
        double c[3];
        if(dofs.components(v, grad[t][std::size_t(j)], c) == 0) continue;
        const Vec3 g = dofs.ambient(v, c);
        const std::size_t a = v / k;
        int i = 0;
        while(i < n && agg[i] != a) ++i;
        if(i == n) { agg[n] = a; h[n] = {{ 0, 0, 0 }}; ++n; }
        for(std::size_t c3 = 0; c3 < 3; ++c3) h[i][c3] += g[c3];
      }
      for(int i = 0; i < n; ++i)
        for(int l = 0; l < n; ++l) {
          if(agg[i] < agg[l]) continue;
          std::array<double, 9>& B = m_blocks[block(agg[i], agg[l])];
          for(std::size_t c = 0; c < 3; ++c)
            for(std::size_t d = 0; d < 3; ++d) B[3 * c + d] += w[t] * h[i][c] * h[l][d];
        }
    }
    // The damping: per vertex reg·FFᵀ (border: the tangent projector) or reg·I.
    for(std::size_t v = 0; v < M.size(); ++v) {
      const double reg = lambda * (M[v][0] + M[v][1] + M[v][2]) / 3;
      std::array<double, 9>& B = m_blocks[block(v / k, v / k)];
      for(std::size_t d = 0; d < 3; ++d) {
        Vec3 u = {{ 0, 0, 0 }};
        u[d] = 1;
        double cc[3];
        dofs.components(v, u, cc);
        const Vec3 fu = dofs.ambient(v, cc);
        for(std::size_t c = 0; c < 3; ++c) B[3 * c + d] += reg * fu[c];
      }
    }
    m_triplets.clear();
    for(std::size_t a = 0; a < m_aggregates; ++a)
      for(std::size_t i = m_start[a]; i < m_start[a + 1]; ++i) {
        const std::size_t b = m_col[i];
        for(std::size_t c = 0; c < 3; ++c)
          for(std::size_t d = 0; d < 3; ++d)
            if(a > b || c >= d) m_triplets.emplace_back(int(3 * a + c), int(3 * b + d), m_blocks[i][3 * c + d]);
      }
    const int n = int(3 * m_aggregates);
    m_Hc.resize(n, n);
    m_Hc.setFromTriplets(m_triplets.begin(), m_triplets.end());
    if(!m_analyzed) { m_factor.analyzePattern(m_Hc); m_analyzed = true; }
    m_factor.factorize(m_Hc);
    m_ok = m_factor.info() == Eigen::Success;
    if(!m_ok) {
      // An aggregate of a few border vertices whose tangent planes miss a
      // direction (the last, short one; or nearly coplanar normals) makes
      // P rank-deficient and Pᵀ H P singular. Its null vectors move no
      // vertex and Pᵀ r has no component along them, so a small shift of
      // the diagonal leaves the correction P (Pᵀ H P)⁻¹ Pᵀ r as it is.
      double trace = 0;
      for(int i = 0; i < n; ++i) trace += m_Hc.coeff(i, i);
      const double shift = 1e-10 * trace / (std::max)(n, 1);
      for(int i = 0; i < n; ++i) m_Hc.coeffRef(i, i) += shift;
      m_factor.factorize(m_Hc);
      m_ok = m_factor.info() == Eigen::Success;
      for(int i = 0; i < n; ++i) m_Hc.coeffRef(i, i) -= shift; // product() stays Pᵀ H P
    }
  }

  /// rc = Pᵀ r: per aggregate the sum of its vertices' ambient vectors.
  void restrict(const Volume_dofs& dofs, const Eigen::VectorXd& r, Eigen::VectorXd& rc, int threads) const
  {
    const std::size_t k = m_k;
    rc.resize(Eigen::Index(3 * m_aggregates));
    parallel_ranges(m_aggregates, threads, [&](std::size_t begin, std::size_t end, std::size_t) {
      for(std::size_t a = begin; a < end; ++a) {
        Vec3 sum = {{ 0, 0, 0 }};
        for(std::size_t v = a * k; v < (std::min)(m_vertices, (a + 1) * k); ++v) {
          const Vec3 g = dofs.ambient(v, r.data() + dofs.offset(v));
          sum[0] += g[0]; sum[1] += g[1]; sum[2] += g[2];
        }
        for(std::size_t c = 0; c < 3; ++c) rc[Eigen::Index(3 * a + c)] = sum[c];
      }
    });
  }

  /// z += P ec: every vertex moves by its aggregate's translation (tangentially on the border).
  void prolong_add(const Volume_dofs& dofs, const Eigen::VectorXd& ec, Eigen::VectorXd& z, int threads) const
  {
    const std::size_t k = m_k;
    parallel_ranges(m_vertices, threads, [&](std::size_t begin, std::size_t end, std::size_t) {
      for(std::size_t v = begin; v < end; ++v) {
        const std::size_t a = v / k;
        const Vec3 e = {{ ec[Eigen::Index(3 * a)], ec[Eigen::Index(3 * a + 1)], ec[Eigen::Index(3 * a + 2)] }};
        double c[3];
        const int m = dofs.components(v, e, c);
        for(int i = 0; i < m; ++i) z[dofs.offset(v) + i] += c[i];
      }
    });
  }

  /// z += P (Pᵀ H P)⁻¹ Pᵀ r.
  void correct(const Volume_dofs& dofs, const Eigen::VectorXd& r, Eigen::VectorXd& z, int threads)
  {
    restrict(dofs, r, m_rc, threads);
    m_ec = m_factor.solve(m_rc);
    prolong_add(dofs, m_ec, z, threads);
  }

  /// The coarse matrix times ec (for tests: against Pᵀ H P ec by products).
  Eigen::VectorXd product(const Eigen::VectorXd& ec) const { return m_Hc.selfadjointView<Eigen::Lower>() * ec; }

private:
  /// The aggregates' pairs (a ≥ b) that share a tet, per a in increasing b.
  void pattern(const std::vector<Tet>& tets, std::size_t vertices)
  {
    const std::size_t k = m_k;
    m_vertices = vertices;
    m_aggregates = (vertices + k - 1) / k;
    std::vector<std::pair<std::size_t, std::size_t> > pairs;
    for(std::size_t a = 0; a < m_aggregates; ++a) pairs.emplace_back(a, a);
    for(const Tet& q : tets)
      for(std::size_t i = 0; i < 4; ++i)
        for(std::size_t l = 0; l < 4; ++l) {
          const std::size_t a = std::size_t(q[i]) / k, b = std::size_t(q[l]) / k;
          if(a > b) pairs.emplace_back(a, b);
        }
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    m_start.assign(m_aggregates + 1, 0);
    m_col.resize(pairs.size());
    for(std::size_t i = 0; i < pairs.size(); ++i) {
      ++m_start[pairs[i].first + 1];
      m_col[i] = pairs[i].second;
    }
    for(std::size_t a = 0; a < m_aggregates; ++a) m_start[a + 1] += m_start[a];
    m_blocks.resize(pairs.size());
  }

  std::size_t block(std::size_t a, std::size_t b) const
  {
    const auto first = m_col.begin() + std::ptrdiff_t(m_start[a]);
    const auto last = m_col.begin() + std::ptrdiff_t(m_start[a + 1]);
    return std::size_t(std::lower_bound(first, last, b) - m_col.begin());
  }

  std::size_t m_k;
  std::size_t m_vertices = 0, m_aggregates = 0;
  std::vector<Eigen::Triplet<double> > m_triplets;
  std::vector<std::size_t> m_start, m_col; // the pattern's blocks, per aggregate
  std::vector<std::array<double, 9> > m_blocks;
  Sparse_matrix m_Hc;
  Default_spd_solver m_factor;
  bool m_analyzed = false, m_ok = false;
  Eigen::VectorXd m_rc, m_ec;
};

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
