// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A textured OBJ that opens as such in MeshLab or Blender: NAME.obj (with
// `mtllib NAME.mtl`), NAME.mtl (`map_Kd NAME.png`) and NAME.png, a
// checkerboard whose squares show how the map stretches the surface.

#ifndef DLF_CLI_TEXTURE_OUTPUT_H
#define DLF_CLI_TEXTURE_OUTPUT_H

#include "mesh_input.h"

#include <ostream>
#include <string>
#include <vector>

namespace dlf_cli {

/// The three file names of `--texture NAME.obj`; throws `Cli_error` unless
/// the name ends in ".obj".
struct Texture_paths
{
  std::string obj, mtl, png;
};
Texture_paths texture_paths(const std::string& obj_path);

/// `uv` moved and scaled uniformly into [0, 1]²: vt = (uv − min) / extent,
/// extent the larger side of the bounding box (the shape is kept).
std::vector<Vec2> unit_square_uv(const std::vector<Vec2>& uv);

/// The OBJ: `v` = `xyz`, `vt` = `uv` (full precision), faces `f a/a b/b c/c`
/// in the material of `mtl_file` (a name relative to the OBJ); with
/// `uv_faces` (per-corner uv, a seamed map), `f a/p b/q c/r`.
void write_textured_obj(std::ostream& out, const std::vector<Vec3>& xyz, const std::vector<Vec2>& uv,
                        const std::vector<Triangle>& faces, const std::string& mtl_file, const std::string& comment,
                        const std::vector<Triangle>& uv_faces = std::vector<Triangle>());

void write_checker_mtl(std::ostream& out, const std::string& png_file);

/// A `size` × `size` RGB PNG (libpng): `squares` × `squares` squares
/// alternating white with a colour that varies along u and v, so that a
/// rotated or mirrored map shows.
void write_checker_png(std::ostream& out, int size, int squares);

} // namespace dlf_cli

#endif
