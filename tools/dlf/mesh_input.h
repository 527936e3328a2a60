// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Reading the input mesh in the vertex and face order of the file, and the
// checks that turn unsuitable input into one clear line.

#ifndef DLF_CLI_MESH_INPUT_H
#define DLF_CLI_MESH_INPUT_H

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace dlf_cli {

typedef std::array<double, 2> Vec2; ///< a point of the plane, as the library's index-form functions take it
typedef std::array<double, 3> Vec3; ///< a point in space, likewise
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

/// The checks of `read_triangle_mesh()` on a mesh given as arrays (the
/// Python module's input): throws `Cli_error` prefixed by `name`.
Indexed_mesh checked_triangle_mesh(std::vector<Vec3> xyz, std::vector<std::vector<std::size_t> > polygons,
                                   const std::string& name);

/// The file's vertices and polygons as they are (no check, no
/// reordering): OFF by the package's own reader, other formats by CGAL's.
/// False when the file cannot be read as a mesh; throws `Cli_error` for an
/// OFF whose header announces more than the file holds.
bool read_polygon_soup(const std::string& path, std::vector<Vec3>& xyz, std::vector<std::vector<std::size_t> >& polygons);

/// Whether a soup of triangles (each of 3 distinct vertices below `n`) is
/// a consistently oriented manifold mesh: no directed edge used twice, the
/// faces around each vertex one fan (by sorting; CGAL's
/// is_polygon_soup_a_polygon_mesh() decides the same with trees of pairs).
bool is_oriented_manifold_soup(std::size_t n, const std::vector<std::vector<std::size_t> >& triangles);

/// A border loop: its vertices in walking order, from its smallest index.
struct Border_loop
{
  std::vector<int> vertices;
  double length = 0; ///< 3D length
};

/// The border loops of a manifold triangle mesh (orientation not needed),
/// longest first by 3D length, ties by smallest vertex index: the order in
/// which `dlf info` lists them and `dlf disk --outer-loop K` counts them from 0.
std::vector<Border_loop> border_loops(const std::vector<Vec3>& xyz, const std::vector<Triangle>& faces);

/// Throws `Cli_error` naming what was found (connected components, border
/// loops, genus) unless `mesh` is a topological disk or a disk with holes
/// (one component, genus 0, at least one border loop); returns its border
/// loops, as `border_loops()` orders them.
std::vector<Border_loop> check_disk_topology(const Indexed_mesh& mesh, const std::string& path);

} // namespace dlf_cli

#endif
