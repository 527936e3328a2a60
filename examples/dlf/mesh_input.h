// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Reading the input mesh in the vertex and face order of the file, and the
// checks that turn unsuitable input into one clear line.

#ifndef DLF_CLI_MESH_INPUT_H
#define DLF_CLI_MESH_INPUT_H

#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/critical_step.h>

#include <array>
#include <string>
#include <vector>

namespace dlf_cli {

typedef CGAL::Surface_mesh_parameterization::internal::dlf::Vec2 Vec2;
typedef CGAL::Surface_mesh_parameterization::internal::dlf::Vec3 Vec3;
typedef std::array<int, 3> Triangle;

/// A triangle mesh as index arrays, in the order of the input file.
struct Indexed_mesh
{
  std::vector<Vec3> xyz;
  std::vector<Triangle> faces;
};

/// Reads any format CGAL reads (OFF, OBJ, PLY, STL, ...) into index arrays
/// without reordering vertices or faces. Faces are re-oriented consistently
/// only when the file's orientation is inconsistent. Throws `Cli_error` for a
/// missing or unreadable file, an empty mesh, non-finite coordinates,
/// non-triangle faces, unreferenced vertices, or non-manifold input.
Indexed_mesh read_triangle_mesh(const std::string& path);

/// Throws `Cli_error` naming what was found (connected components, border
/// loops, genus) unless `mesh` is a topological disk.
void check_disk_topology(const Indexed_mesh& mesh, const std::string& path);

} // namespace dlf_cli

#endif
