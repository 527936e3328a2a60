// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The report of `dlf info` for a mesh given as arrays (the Python module's
// `info()`), built by the same code as the command's.

#ifndef DLF_CLI_MESH_INFO_H
#define DLF_CLI_MESH_INFO_H

#include "mesh_input.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace dlf_cli {

/// Counts, topology, degeneracies and which command the mesh fits, as
/// `dlf info --report` writes them; `name` fills the report's "mesh". Every
/// index of `polygons` must be below `xyz.size()` (the caller checks).
nlohmann::ordered_json mesh_info(const std::string& name, const std::vector<Vec3>& xyz,
                                 const std::vector<std::vector<std::size_t> >& polygons);

} // namespace dlf_cli

#endif
