// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The degrees of freedom of the planar flows (interior vertices move freely,
// boundary vertices slide along the boundary curve or, floating, move freely), the trial move along a
// dof direction, the vertex velocities, the gradient of a per-face energy
// with respect to the positions, and the paper's direction and critical
// step on the plane.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_PLANAR_DOFS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_PLANAR_DOFS_H

#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/disk/boundary_curve.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/cotangent_laplacian.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/critical_step.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/geometry.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/flow/flow_driver.h>

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// ∂E/∂p for a planar mesh from per-face ∂E/∂u_t:
/// ∂u/∂p_k = ½ (y_{k+1} − y_{k+2}, x_{k+2} − x_{k+1}).
inline void planar_position_gradient(const std::vector<Vec2>& uv, const std::vector<Face>& faces,
                                     const std::vector<double>& dE, std::vector<Vec2>& g)
{
  g.assign(uv.size(), Vec2{{ 0, 0 }});
  for(std::size_t t = 0; t < faces.size(); ++t) {
    const Face& f = faces[t];
    for(int k = 0; k < 3; ++k) {
      const Vec2& a = uv[f[(k + 1) % 3]];
      const Vec2& b = uv[f[(k + 2) % 3]];
      g[f[k]][0] += dE[t] * 0.5 * (a[1] - b[1]);
      g[f[k]][1] += dE[t] * 0.5 * (b[0] - a[0]);
    }
  }
}

/// The degrees of freedom of the planar flows: interior vertices move freely
/// (two dofs), boundary vertices slide along the curve (one dof, along the
/// tangent), fixed corners do not move. A floating border's vertices move
/// freely too, but its first one, which holds the map in place (the
/// energy does not see translations, and the Sobolev metric needs one
/// fixed vertex to be definite): it is then the only "boundary" vertex.
struct Planar_dofs
{
  std::vector<int> first;       ///< first dof of each vertex (−1: none)
  std::vector<int> count;       ///< 0, 1 or 2
  std::vector<int> boundary_of; ///< position in the boundary loop, −1 inside
  int size = 0;

  Planar_dofs(std::size_t n, const std::vector<int>& boundary, const Boundary_curve& curve)
    : first(n, -1), count(n, 2), boundary_of(n, -1)
  {
    if(curve.kind() == Discrete_lie_flow_border::FLOATING) {
      if(!boundary.empty()) { boundary_of[std::size_t(boundary[0])] = 0; count[std::size_t(boundary[0])] = 0; }
    } else
      for(std::size_t k = 0; k < boundary.size(); ++k) {
        boundary_of[boundary[k]] = int(k);
        count[boundary[k]] = curve.is_fixed(k) ? 0 : 1;
      }
    for(std::size_t v = 0; v < n; ++v)
      if(count[v] > 0) { first[v] = size; size += count[v]; }
  }

  /// Basis vector of the j-th dof of vertex v.
  Vec2 basis(int v, int j, const Boundary_curve& curve) const
  {
    if(boundary_of[v] >= 0) return curve.tangent(std::size_t(boundary_of[v]));
    return j == 0 ? Vec2{{ 1, 0 }} : Vec2{{ 0, 1 }};
  }
};

/// Moves the domain by λ along the dof direction `d`; false when a boundary
/// vertex leaves its piece of curve.
inline bool planar_trial(const std::vector<Vec2>& uv, const Planar_dofs& dofs, const std::vector<Vec2>& basis,
                         const Eigen::VectorXd& d, double lambda, const Boundary_curve& curve,
                         std::vector<Vec2>& out)
{
  out = uv;
  for(std::size_t v = 0; v < uv.size(); ++v) {
    if(dofs.count[v] == 0) continue;
    const int a = dofs.first[v];
    if(dofs.boundary_of[v] >= 0) {
      if(d[a] == 0) continue;
      if(!curve.slide(std::size_t(dofs.boundary_of[v]), lambda * d[a], out[v])) return false;
    } else {
      out[v][0] += lambda * (d[a] * basis[a][0] + d[a + 1] * basis[a + 1][0]);
      out[v][1] += lambda * (d[a] * basis[a][1] + d[a + 1] * basis[a + 1][1]);
    }
  }
  return true;
}

/// Velocity of every vertex for dof direction `d` (linearised on the curve).
inline void planar_velocity(std::size_t n, const Planar_dofs& dofs, const std::vector<Vec2>& basis,
                            const Eigen::VectorXd& d, std::vector<Vec2>& vel)
{
  vel.assign(n, Vec2{{ 0, 0 }});
  for(std::size_t v = 0; v < n; ++v)
    for(int j = 0; j < dofs.count[v]; ++j) {
      const int a = dofs.first[v] + j;
      vel[v][0] += d[a] * basis[a][0];
      vel[v][1] += d[a] * basis[a][1];
    }
}

/// The paper's vertex direction for the potential `h`: ∇h per face,
/// area-weighted (by `u`) at the vertices, in dof coordinates (`basis` is
/// filled; a border vertex keeps its tangential part). Returns whether any
/// dof moves.
inline bool potential_gradient_direction(const std::vector<Vec2>& uv, const std::vector<Face>& faces,
                                         const std::vector<double>& u, const std::vector<double>& h,
                                         const Planar_dofs& dofs, const Boundary_curve& curve,
                                         std::vector<Vec2>& basis, Eigen::VectorXd& d)
{
  const std::size_t n = uv.size();
  std::vector<Vec2> grad(n, Vec2{{ 0, 0 }});
  std::vector<double> wsum(n, 0.);
  for(std::size_t t = 0; t < faces.size(); ++t) {
    const Face& f = faces[t];
    const Vec2 gt = p1_gradient(uv[f[0]], uv[f[1]], uv[f[2]], h[f[0]], h[f[1]], h[f[2]]);
    for(int k = 0; k < 3; ++k) {
      grad[f[k]][0] += u[t] * gt[0];
      grad[f[k]][1] += u[t] * gt[1];
      wsum[f[k]] += u[t];
    }
  }
  d.resize(dofs.size);
  bool moves = false;
  for(std::size_t v = 0; v < n; ++v)
    for(int j = 0; j < dofs.count[v]; ++j) {
      const int a = dofs.first[v] + j;
      basis[std::size_t(a)] = dofs.basis(int(v), j, curve);
      d[a] = (grad[v][0] * basis[a][0] + grad[v][1] * basis[a][1]) / wsum[v];
      moves = moves || d[a] != 0;
    }
  return moves;
}

/// After a step of length `lambda` along the dof direction `d`: each
/// border vertex's place on `curve` moves by its dof (a fixed corner stays).
inline void commit_border_step(const Planar_dofs& dofs, double lambda, const Eigen::VectorXd& d, Boundary_curve& curve)
{
  for(std::size_t v = 0; v < dofs.boundary_of.size(); ++v)
    if(dofs.boundary_of[v] >= 0 && dofs.count[v] > 0)
      curve.commit(std::size_t(dofs.boundary_of[v]), lambda * d[dofs.first[v]]);
}

/// The smallest critical step of the flowing faces `F` of `uv` at the
/// vertex velocities `vel` (Eq. 5 with the corrected coefficients of
/// Eq. 4); its face in `limiting`.
inline double planar_critical_step(const std::vector<Vec2>& uv, const std::vector<Face>& F,
                                   const std::vector<Vec2>& vel, int& limiting)
{
  return smallest_critical_step(F.size(), [&](std::size_t t, double) {
    return critical_step_2(uv[F[t][0]], uv[F[t][1]], uv[F[t][2]], vel[F[t][0]], vel[F[t][1]], vel[F[t][2]]);
  }, limiting);
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
