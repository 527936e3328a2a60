// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The area elements of a run as properties of a `Surface_mesh`: per vertex
// the target area A_M and the domain area A_Ω of the final map (both scaled
// to the domain's total), per face the density ρ the flow used. Other mesh
// types have no named properties; their callers pass property maps to
// `area_elements()` instead.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_MESH_PROPERTIES_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_MESH_PROPERTIES_H

#include <CGAL/Surface_mesh/Surface_mesh.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// The names of the properties (doc/user_manual.md, "Area elements").
inline const char* target_area_property() { return "v:dlf_target_area"; }
inline const char* domain_area_property() { return "v:dlf_domain_area"; }
inline const char* face_density_property() { return "f:dlf_density"; }

/// Any mesh but a `Surface_mesh`: nothing to store.
template <class Mesh, class Vertex, class Face_descriptor>
void store_area_elements(Mesh&, const std::vector<Vertex>&, const std::vector<double>&, const std::vector<double>&,
                         const std::vector<Face_descriptor>&, const std::vector<double>&)
{}

/// A `Surface_mesh`: the properties are added (or overwritten) on the mesh.
template <class Point>
void store_area_elements(Surface_mesh<Point>& mesh, const std::vector<typename Surface_mesh<Point>::Vertex_index>& vertex_of,
                         const std::vector<double>& target_area, const std::vector<double>& domain_area,
                         const std::vector<typename Surface_mesh<Point>::Face_index>& face_of,
                         const std::vector<double>& face_density)
{
  typedef typename Surface_mesh<Point>::Vertex_index V;
  typedef typename Surface_mesh<Point>::Face_index F;
  auto target = mesh.template add_property_map<V, double>(target_area_property(), 0.).first;
  auto domain = mesh.template add_property_map<V, double>(domain_area_property(), 0.).first;
  auto density = mesh.template add_property_map<F, double>(face_density_property(), 0.).first;
  for(std::size_t i = 0; i < vertex_of.size() && i < target_area.size() && i < domain_area.size(); ++i) {
    target[vertex_of[i]] = target_area[i];
    domain[vertex_of[i]] = domain_area[i];
  }
  for(std::size_t f = 0; f < face_of.size() && f < face_density.size(); ++f) density[face_of[f]] = face_density[f];
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
