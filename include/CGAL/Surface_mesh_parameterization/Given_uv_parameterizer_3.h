// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_GIVEN_UV_PARAMETERIZER_3_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_GIVEN_UV_PARAMETERIZER_3_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/Surface_mesh_parameterization/Error_code.h>

#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <cmath>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgDiscreteLieFlowParameterizers
///
/// A map the caller already has, as an initial parameterizer: copies a uv
/// property map into the parameterization. With
/// `Discrete_lie_flow_parameterizer_3<Mesh, Given_uv_parameterizer_3<Mesh, Map> >`
/// the flow starts from any flip-free map — a non-convex domain included
/// (the paper's Fig. 10): set `options().disk.border` to `FREE` and the
/// border slides along the given map's border polygon. The flow checks the
/// map with the exact predicate and refuses a folded one
/// (`ERROR_INITIAL_MAP_FOLDED`).
///
/// \tparam TriangleMesh_ a model of `FaceGraph`
/// \tparam VertexUVMap_ a readable property map `vertex_descriptor` → a 2D
///   point with `x()` and `y()`
///
/// \cgalModels `Parameterizer_3`
template <class TriangleMesh_, class VertexUVMap_>
class Given_uv_parameterizer_3
{
public:
  /// The mesh type.
  typedef TriangleMesh_ Triangle_mesh;
  /// The given map's type.
  typedef VertexUVMap_ Vertex_uv_map;

  /// \param given the uv of every vertex of the mesh
  explicit Given_uv_parameterizer_3(Vertex_uv_map given = Vertex_uv_map()) : m_given(given) {}

  /// Copies the given uv into `uvmap` and marks every vertex parameterized.
  /// `ERROR_WRONG_PARAMETER` if a given coordinate is not finite.
  template <typename VertexUVmap, typename VertexIndexMap, typename VertexParameterizedMap>
  Error_code parameterize(Triangle_mesh& mesh, typename boost::graph_traits<Triangle_mesh>::halfedge_descriptor,
                          VertexUVmap uvmap, VertexIndexMap, VertexParameterizedMap vpmap)
  {
    typedef typename boost::property_traits<VertexUVmap>::value_type Point_2;
    for(auto v : vertices(mesh)) {
      const auto& p = get(m_given, v);
      const double x = double(p.x()), y = double(p.y());
      if(!std::isfinite(x) || !std::isfinite(y)) return ERROR_WRONG_PARAMETER;
      put(uvmap, v, Point_2(x, y));
      put(vpmap, v, true);
    }
    return OK;
  }

private:
  Vertex_uv_map m_given;
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
