// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The tool's OBJ convention: `v` the input 3D positions, `vt` the uv of the
// same vertex (same order), faces `f a/a b/b c/c`; each number in the
// shortest form that reads back as the same double (bit-identical).

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

/// Reads the per-vertex uv of an OBJ written as above: its `vt` lines, or, if
/// it has none, the x and y of its `v` lines when every z is 0 (a flat
/// layout). Throws `Cli_error` unless there are exactly `vertices` of them.
std::vector<Vec2> read_uv_obj(const std::string& path, std::size_t vertices);

} // namespace dlf_cli

#endif
