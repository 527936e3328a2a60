// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_DISCRETE_LIE_FLOW_MEDIT_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_DISCRETE_LIE_FLOW_MEDIT_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_tet_mesh.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/volume/volume_medit.h>

#include <array>
#include <cstddef>
#include <istream>
#include <ostream>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgDiscreteLieFlowParameterizers
/// Reads a Medit `.mesh` file (ASCII; what CGAL's Mesh_3 writes with
/// `CGAL::IO::output_to_medit()`) into `mesh`, indices made 0-based.
/// Sections other than Vertices and Tetrahedra are read and ignored when
/// their record size is known (Triangles, Edges, Corners, ...).
/// \returns false on the first problem, with `error` set to "line N: ...".
inline bool read_medit_tet_mesh(std::istream& in, Discrete_lie_flow_tet_mesh& mesh, std::string& error)
{
  return internal::dlf::read_medit(in, mesh, error);
}

/// \ingroup PkgDiscreteLieFlowParameterizers
/// Keeps only the vertices of `mesh` that some tetrahedron uses (CGAL's
/// Medit writer also lists the triangulation's vertices outside the
/// complex), in their order, and renumbers the tetrahedra.
/// `kept[i]` receives the input index of output vertex i.
/// \returns the number of vertices dropped.
inline std::size_t drop_unused_tet_mesh_vertices(Discrete_lie_flow_tet_mesh& mesh, std::vector<int>& kept)
{
  return internal::dlf::drop_unused_vertices(mesh, kept);
}

/// \ingroup PkgDiscreteLieFlowParameterizers
/// Writes a tetrahedral mesh as Medit `.mesh`: `points` with 17 significant
/// digits (the exact orientations survive a round trip), `border_faces`
/// as its Triangles, `tets` with their labels `tet_refs` (1 past its end).
inline void write_medit_tet_mesh(std::ostream& out, const std::vector<std::array<double, 3> >& points,
                                 const std::vector<std::array<int, 4> >& tets, const std::vector<int>& tet_refs,
                                 const std::vector<std::array<int, 3> >& border_faces)
{
  internal::dlf::write_medit(out, points, tets, tet_refs, border_faces);
}

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
