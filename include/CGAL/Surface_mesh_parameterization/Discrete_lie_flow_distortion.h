// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_DISCRETE_LIE_FLOW_DISTORTION_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_DISCRETE_LIE_FLOW_DISTORTION_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_report.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_atlas_options.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/atlas/atlas_score.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/certification.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/distortion.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/geometry.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/sphere/sphere_problem.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>

#include <array>
#include <map>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgDiscreteLieFlowParameterizers
/// The distortion metrics (doc/design.md, "Metrics") of the planar map `uv`
/// of the triangles `faces` over the points `xyz`, in index form; inverted
/// faces are counted with the exact predicate. `face_density` (per face,
/// empty for ρ ≡ 1) weighs the input areas as a measure-controlled map's
/// targets do.
inline Discrete_lie_flow_distortion
discrete_lie_flow_distortion(const std::vector<std::array<double, 3> >& xyz,
                             const std::vector<std::array<double, 2> >& uv,
                             const std::vector<std::array<int, 3> >& faces,
                             const std::vector<double>& face_density = std::vector<double>())
{
  return internal::dlf::planar_distortion(xyz, uv, faces, face_density);
}

/// \ingroup PkgDiscreteLieFlowParameterizers
/// The same metrics for a map onto the unit sphere: the domain triangles are
/// the flat triangles between the points `sphere`.
inline Discrete_lie_flow_distortion
discrete_lie_flow_sphere_distortion(const std::vector<std::array<double, 3> >& xyz,
                                    const std::vector<std::array<double, 3> >& sphere,
                                    const std::vector<std::array<int, 3> >& faces,
                                    const std::vector<double>& face_density = std::vector<double>())
{
  return internal::dlf::spherical_distortion(xyz, sphere, faces, face_density);
}

/// \ingroup PkgDiscreteLieFlowParameterizers
/// How far apart two planar maps `a` and `b` of the triangles `faces` over
/// the points `xyz` are (doc/design.md, "Metrics"): the vertex-wise transport
/// cost between them and the Beltrami coefficients of `b ∘ a⁻¹`, e.g. a DLF
/// map against an optimal transport map, both from the same start.
/// `face_density` (per face, empty for ρ ≡ 1) weighs the input areas.
inline Discrete_lie_flow_map_difference
discrete_lie_flow_map_difference(const std::vector<std::array<double, 3> >& xyz,
                                 const std::vector<std::array<double, 2> >& a,
                                 const std::vector<std::array<double, 2> >& b,
                                 const std::vector<std::array<int, 3> >& faces,
                                 const std::vector<double>& face_density = std::vector<double>())
{
  return internal::dlf::map_difference(xyz, a, b, faces, face_density);
}

/// \ingroup PkgDiscreteLieFlowParameterizers
/// The score of an atlas given as per-corner uv (an OBJ's `f v/vt`), whoever
/// made it: `uv` the uv points, `uv_faces` per face its corners' uv points,
/// of the triangles `faces` over `xyz`. Charts are the faces joined across
/// edges whose two sides share their uv; orientations and overlapping uv
/// triangles are decided by CGAL's exact predicates.
inline Discrete_lie_flow_atlas_score
discrete_lie_flow_atlas_score(const std::vector<std::array<double, 3> >& xyz,
                              const std::vector<std::array<int, 3> >& faces,
                              const std::vector<std::array<double, 2> >& uv,
                              const std::vector<std::array<int, 3> >& uv_faces)
{
  return internal::dlf::score_atlas(xyz, faces, uv, uv_faces);
}

/// \ingroup PkgDiscreteLieFlowParameterizers
/// The area of the triangle (a, b, c) in space, in doubles: the measure the
/// flows give an input triangle.
inline double discrete_lie_flow_triangle_area(const std::array<double, 3>& a, const std::array<double, 3>& b,
                                              const std::array<double, 3>& c)
{
  return internal::dlf::triangle_area_3(a, b, c);
}

/// \ingroup PkgDiscreteLieFlowParameterizers
/// The signed area of the planar triangle (a, b, c) in doubles, positive
/// counter-clockwise.
inline double discrete_lie_flow_signed_area_2(const std::array<double, 2>& a, const std::array<double, 2>& b,
                                              const std::array<double, 2>& c)
{
  return internal::dlf::signed_area_2(a, b, c);
}

/// \ingroup PkgDiscreteLieFlowParameterizers
/// The orientation of the planar triangle (a, b, c) by CGAL's exact
/// predicate on the doubles: what the certified flows call fold-free.
inline CGAL::Orientation discrete_lie_flow_orientation_2(const std::array<double, 2>& a,
                                                         const std::array<double, 2>& b,
                                                         const std::array<double, 2>& c)
{
  return internal::dlf::exact_orientation_2(a, b, c);
}

/// \ingroup PkgDiscreteLieFlowParameterizers
/// The signed area of the flat triangle between the sphere points a, b, c:
/// its area, with the sign of det[a, b, c] (positive when the triangle is
/// counter-clockwise seen from outside the unit sphere).
inline double discrete_lie_flow_sphere_signed_area(const std::array<double, 3>& a, const std::array<double, 3>& b,
                                                   const std::array<double, 3>& c)
{
  return internal::dlf::signed_area_sphere(a, b, c);
}

namespace internal {
namespace dlf {

/// Index form of the triangles of `mesh` (vertex order of `vertices(mesh)`)
/// with their positions and the domain point of each vertex from `map`.
template <class TriangleMesh, class VertexMap, class Domain_point, class To_domain>
void indexed_map(const TriangleMesh& mesh, VertexMap map, std::vector<Vec3>& xyz, std::vector<Domain_point>& dom,
                 std::vector<Face>& triangles, const To_domain& to_domain)
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  std::map<vertex_descriptor, int> index;
  const auto ppmap = get(CGAL::vertex_point, mesh);
  for(vertex_descriptor v : vertices(mesh)) {
    index.emplace(v, int(xyz.size()));
    const auto& p = get(ppmap, v);
    xyz.push_back({{ CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()) }});
    dom.push_back(to_domain(get(map, v)));
  }
  for(face_descriptor f : faces(mesh)) {
    Face t{{ -1, -1, -1 }};
    int k = 0;
    for(vertex_descriptor v : vertices_around_face(halfedge(f, mesh), mesh))
      if(k < 3) t[std::size_t(k++)] = index[v];
    triangles.push_back(t);
  }
}

} // namespace dlf
} // namespace internal

/// \ingroup PkgDiscreteLieFlowParameterizers
/// The distortion metrics of the planar map `uvmap` (`vertex_descriptor` →
/// a 2D point) of the triangle mesh `mesh`, e.g. the result of any
/// parameterizer of this package or of CGAL's.
/// \pre `mesh` is a triangle mesh.
template <class TriangleMesh, class VertexUVMap>
Discrete_lie_flow_distortion discrete_lie_flow_distortion(const TriangleMesh& mesh, VertexUVMap uvmap)
{
  std::vector<internal::dlf::Vec3> xyz;
  std::vector<internal::dlf::Vec2> uv;
  std::vector<internal::dlf::Face> tris;
  internal::dlf::indexed_map(mesh, uvmap, xyz, uv, tris, [](const auto& p) {
    return internal::dlf::Vec2{{ CGAL::to_double(p.x()), CGAL::to_double(p.y()) }};
  });
  return internal::dlf::planar_distortion(xyz, uv, tris);
}

/// \ingroup PkgDiscreteLieFlowParameterizers
/// The same for a measure-controlled map: `face_density` (`face_descriptor`
/// → number ρ > 0) weighs the input areas as the flow's targets do.
template <class TriangleMesh, class VertexUVMap, class FaceDensityMap>
Discrete_lie_flow_distortion discrete_lie_flow_distortion(const TriangleMesh& mesh, VertexUVMap uvmap,
                                                          FaceDensityMap face_density)
{
  std::vector<internal::dlf::Vec3> xyz;
  std::vector<internal::dlf::Vec2> uv;
  std::vector<internal::dlf::Face> tris;
  internal::dlf::indexed_map(mesh, uvmap, xyz, uv, tris, [](const auto& p) {
    return internal::dlf::Vec2{{ CGAL::to_double(p.x()), CGAL::to_double(p.y()) }};
  });
  std::vector<double> rho;
  for(typename boost::graph_traits<TriangleMesh>::face_descriptor f : faces(mesh)) rho.push_back(double(get(face_density, f)));
  return internal::dlf::planar_distortion(xyz, uv, tris, rho);
}

/// \ingroup PkgDiscreteLieFlowParameterizers
/// The distortion metrics of the map `sphere_map` (`vertex_descriptor` → a
/// 3D point on the unit sphere) of the closed triangle mesh `mesh`.
/// \pre `mesh` is a triangle mesh.
template <class TriangleMesh, class VertexSphereMap>
Discrete_lie_flow_distortion discrete_lie_flow_sphere_distortion(const TriangleMesh& mesh, VertexSphereMap sphere_map)
{
  std::vector<internal::dlf::Vec3> xyz, sphere;
  std::vector<internal::dlf::Face> tris;
  internal::dlf::indexed_map(mesh, sphere_map, xyz, sphere, tris, [](const auto& p) {
    return internal::dlf::Vec3{{ CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()) }};
  });
  return internal::dlf::spherical_distortion(xyz, sphere, tris);
}

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
