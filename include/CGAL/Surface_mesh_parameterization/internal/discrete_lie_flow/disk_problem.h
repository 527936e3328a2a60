// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The planar flow's input in index form (independent of the mesh type).

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_DISK_PROBLEM_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_DISK_PROBLEM_H

#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/geometry.h>

#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// A disk-topology triangle mesh, its targets, and its boundary loop.
struct Disk_problem
{
  std::vector<Vec3> xyz;       ///< input positions
  std::vector<Face> faces;     ///< input triangles, positively oriented in the initial map
  std::vector<double> target;  ///< per face: ρ_f · area_M(f) > 0 (any common scale)
  std::vector<int> boundary;   ///< the boundary loop, counter-clockwise in the domain
};

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
