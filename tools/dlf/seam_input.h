// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// `dlf disk --seam FILE`: the seam edges of a CGAL selection file, and the
// input cut open along them as CGAL's Seam_mesh sees it (one vertex per side
// of a seam), checked to be a surface the parameterizer takes.

#ifndef DLF_CLI_SEAM_INPUT_H
#define DLF_CLI_SEAM_INPUT_H

#include "mesh_input.h"

#include <array>
#include <functional>
#include <string>
#include <vector>

namespace dlf_cli {

typedef std::array<int, 2> Vertex_pair;

/// The seams of a selection file (CGAL's format: line 1 vertex indices,
/// line 2 face indices, line 3 edges as pairs of vertex indices).
struct Seam_selection
{
  std::vector<Vertex_pair> edges; ///< interior edges of the mesh, each once
  std::size_t cones = 0;          ///< when line 3 is empty: the line-1 vertices joined by shortest paths
};

/// Reads the seams of `path` for `mesh`. Line 3 gives the seam edges; when
/// it is empty, the vertices of line 1 (at least two, e.g. the cones of
/// CGAL's orbifold example) are joined in order, each by a shortest path of
/// interior edges to the seam built so far (a tree). Throws `Cli_error`
/// naming the line and pair at fault: not an index, a vertex out of range,
/// two vertices that no edge joins, a border edge, an odd count.
Seam_selection read_seam_selection(const std::string& path, const Indexed_mesh& mesh);

/// The seams given as vertex pairs (a0 b0 a1 b1 ...: the Python module's
/// `seam` array), with the checks of a selection file's line 3; `name`
/// prefixes messages.
Seam_selection seam_selection_of_pairs(const std::vector<long>& pairs, const Indexed_mesh& mesh, const std::string& name);

/// The input cut open along `edges`: vertex i < V of the cut is the side of
/// input vertex i met first in face order, the other sides follow; faces
/// keep the input order and orientation.
struct Seam_cut
{
  Seam_selection seams;
  Indexed_mesh mesh;             ///< the cut surface: xyz per side, faces by side
  std::vector<int> input_vertex; ///< per cut vertex, the input vertex it is a side of
};
Seam_cut cut_along_seams(const Indexed_mesh& mesh, const Seam_selection& seams);

/// Reads `seam_path`, cuts `mesh` (read from `mesh_path`) and checks the
/// cut surface with `check`, the check the caller applies to an uncut input
/// (e.g. `check_disk_topology()`), whose `Cli_error` (what the surface is:
/// components, border loops, genus) is rethrown naming the cut.
Seam_cut read_and_cut(const Indexed_mesh& mesh, const std::string& mesh_path, const std::string& seam_path,
                      const std::function<void(const Indexed_mesh&, const std::string&)>& check);

/// `read_and_cut()` with seams already read; `seam_name` names them in messages.
Seam_cut checked_cut(const Indexed_mesh& mesh, const std::string& mesh_path, const Seam_selection& seams,
                     const std::string& seam_name, const std::function<void(const Indexed_mesh&, const std::string&)>& check);

} // namespace dlf_cli

#endif
