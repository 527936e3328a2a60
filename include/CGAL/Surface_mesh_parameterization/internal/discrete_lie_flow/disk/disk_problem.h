// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The planar flow's input in index form (independent of the mesh type).

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_DISK_PROBLEM_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_DISK_PROBLEM_H

#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/geometry.h>

#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// A disk-topology triangle mesh, its targets, and its boundary loop.
///
/// A genus-0 mesh with holes becomes a disk by filling each inner border
/// loop (disk_holes.h): the fill's vertices and faces come after the
/// caller's, so that the caller's keep their indices.
struct Disk_problem
{
  std::vector<Vec3> xyz;       ///< input positions
  std::vector<Face> faces;     ///< input triangles, positively oriented in the initial map
  std::vector<double> target;  ///< per face: ρ_f · area_M(f) > 0 (any common scale)
  std::vector<int> boundary;   ///< the boundary loop, counter-clockwise in the domain
  std::size_t fill_vertices = 0; ///< the last `fill_vertices` of `xyz` are virtual (0 for a disk)
  std::size_t fill_faces = 0;    ///< the last `fill_faces` of `faces` fill the holes (0 for a disk)
  std::size_t holes = 0;         ///< inner border loops filled

  std::size_t caller_vertices() const { return xyz.size() - fill_vertices; }
  std::size_t caller_faces() const { return faces.size() - fill_faces; }
};

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
