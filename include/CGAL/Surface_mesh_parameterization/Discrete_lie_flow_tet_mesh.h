// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_DISCRETE_LIE_FLOW_TET_MESH_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_DISCRETE_LIE_FLOW_TET_MESH_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_options.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/volume/volume_mesh.h>

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgDiscreteLieFlowOptions
/// A tetrahedral mesh as index arrays, as a Medit `.mesh` file holds it
/// (`read_medit_tet_mesh()`), with 0-based indices.
struct Discrete_lie_flow_tet_mesh
{
  std::vector<std::array<double, 3> > points; ///< the vertices' coordinates
  std::vector<int> point_refs;                ///< per vertex, the file's reference label
  std::vector<std::array<int, 4> > tets;      ///< four vertex indices per tetrahedron
  std::vector<int> tet_refs;                  ///< subdomain labels (Mesh_3: the subdomain index)
};

/// \ingroup PkgDiscreteLieFlowOptions
/// The border of a tetrahedral mesh of a ball (`discrete_lie_flow_ball_border()`).
struct Discrete_lie_flow_ball_border
{
  /// The border triangles, oriented outward (from the tetrahedra's orientation).
  std::vector<std::array<int, 3> > faces;
  std::vector<int> face_tet;   ///< per border triangle, the tetrahedron it bounds
  std::size_t vertices = 0;    ///< the number of vertices on the border
};

/// \ingroup PkgDiscreteLieFlowParameterizers
/// Checks that `tets` over `points` is a tetrahedral mesh of a topological
/// ball, as `Discrete_lie_flow_volume_parameterizer_3` requires, and returns
/// its border in `border`: indices in range and distinct, finite
/// coordinates, every vertex in some tetrahedron, every tetrahedron positive
/// by CGAL's exact orientation, every triangle in at most two tetrahedra,
/// the border a closed connected genus-0 surface and the Euler
/// characteristic V − E + F − T = 1.
///
/// \returns `OK`, or the code of the first fault (`ERROR_EMPTY_MESH`,
/// `ERROR_WRONG_PARAMETER`, `ERROR_DEGENERATE_INPUT`,
/// `ERROR_NO_TOPOLOGICAL_BALL`), with `message` naming the offending element
/// (0-based indices).
inline Error_code discrete_lie_flow_ball_border(const std::vector<std::array<double, 3> >& points,
                                                const std::vector<std::array<int, 4> >& tets,
                                                Discrete_lie_flow_ball_border& border, std::string& message)
{
  internal::dlf::Ball_topology topology;
  const int code = internal::dlf::check_ball(points, tets, topology, message);
  border.faces.swap(topology.border_faces);
  border.face_tet.swap(topology.border_tet);
  border.vertices = topology.border_vertices;
  return Error_code(code);
}

/// \ingroup PkgDiscreteLieFlowParameterizers
/// det[b − a, c − a, d − a] in doubles: six times the signed volume of the
/// tetrahedron (a, b, c, d), positive when it is positively oriented. The
/// volumetric flow's own measure of a tetrahedron.
inline double discrete_lie_flow_tet_determinant(const std::array<double, 3>& a, const std::array<double, 3>& b,
                                                const std::array<double, 3>& c, const std::array<double, 3>& d)
{
  return internal::dlf::tet_det(a, b, c, d);
}

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
