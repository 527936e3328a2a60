// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The tool's OBJ convention: `v` the input 3D positions, `vt` the uv of the
// same vertex (same order), faces `f a/a b/b c/c`; a map of a mesh cut along
// seams has one `vt` per side of a seam and faces `f a/p b/q c/r`. Each
// number in the shortest form that reads back as the same double
// (bit-identical).

#ifndef DLF_CLI_OBJ_IO_H
#define DLF_CLI_OBJ_IO_H

#include "mesh_input.h"

#include <ostream>
#include <string>
#include <vector>

namespace dlf_cli {

/// Writes `xyz` as `v`, `uv` as `vt` and `faces` (0-based indices into both).
void write_uv_obj(std::ostream& out, const std::vector<Vec3>& xyz, const std::vector<Vec2>& uv,
                  const std::vector<Triangle>& faces, const std::string& comment);
/// The same with per-corner uv: `faces` index `xyz`, `uv_faces` index `uv`.
void write_uv_obj(std::ostream& out, const std::vector<Vec3>& xyz, const std::vector<Vec2>& uv,
                  const std::vector<Triangle>& faces, const std::vector<Triangle>& uv_faces, const std::string& comment);

/// The `v` and `vt` lines and faces of `faces`/`uv_faces` as above, into `text`
/// (shared with the textured OBJ, whose header and material differ).
class Text_buffer;
void write_obj_vertices(Text_buffer& text, const std::vector<Vec3>& xyz, const std::vector<Vec2>& uv);
void write_obj_faces(Text_buffer& text, const std::vector<Triangle>& faces, const std::vector<Triangle>& uv_faces);

/// Reads the per-vertex uv of an OBJ written as above: its `vt` lines, or, if
/// it has none, the x and y of its `v` lines when every z is 0 (a flat
/// layout). Throws `Cli_error` unless there are exactly `vertices` of them.
std::vector<Vec2> read_uv_obj(const std::string& path, std::size_t vertices);

/// The map of `mesh`'s triangles that an OBJ holds, and the surface it maps.
struct Obj_map
{
  Indexed_mesh surface;    ///< `mesh`, or, with per-corner uv, `mesh` cut open: one vertex per `vt`
  std::vector<Vec2> uv;    ///< per vertex of `surface`
  bool per_corner = false; ///< the faces name `vt` other than their `v`
};

/// Per-vertex uv as read_uv_obj() reads them; or, when the OBJ's faces
/// `f a/p b/q c/r` name texture coordinates other than their vertices (a
/// seamed map), per corner: then its faces must be `mesh`'s, in order, and
/// each `vt` the side of one vertex. Throws `Cli_error` naming the line.
Obj_map read_map_obj(const std::string& path, const Indexed_mesh& mesh);

} // namespace dlf_cli

#endif
