// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The fixed-border initial maps: {Tutte, mean value, discrete conformal} ×
// {circle, square}, each with the direct solver.

#include "disk_run_impl.h"

#include <CGAL/Surface_mesh_parameterization/Circular_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_conformal_map_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Mean_value_coordinates_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Square_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Symmetric_barycentric_mapping_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/square_border_corners.h>

namespace dlf_cli {

namespace {

namespace SMP = CGAL::Surface_mesh_parameterization;

// The square border with the corners of choose_square_border_corners():
// CGAL's default corners can put the three vertices of an ear triangle on one
// side (three_peaks.off, mannequin-devil.off).
class Square_border_with_ear_corners
{
public:
  template <typename VertexUVmap, typename VertexIndexMap, typename VertexParameterizedMap>
  SMP::Error_code parameterize(Surface_mesh& mesh, halfedge_descriptor bhd, VertexUVmap uvmap, VertexIndexMap vimap,
                               VertexParameterizedMap vpmap)
  {
    const auto corners = SMP::choose_square_border_corners(mesh, bhd);
    if(!corners) return SMP::ERROR_BORDER_TOO_SHORT; // fewer than 4 border vertices, or more than 4 ears
    SMP::Square_border_arc_length_parameterizer_3<Surface_mesh> square((*corners)[0], (*corners)[1], (*corners)[2],
                                                                       (*corners)[3]);
    return square.parameterize(mesh, bhd, uvmap, vimap, vpmap);
  }
  bool is_border_convex() const { return true; }
};

template <class Border>
Disk_run run_with_border(const Indexed_mesh& mesh, const Disk_settings& settings)
{
  if(settings.init == "mvc")
    return run_disk_with(mesh, SMP::Mean_value_coordinates_parameterizer_3<Surface_mesh, Border, Direct_solver>(), settings);
  if(settings.init == "dcp")
    return run_disk_with(mesh, SMP::Discrete_conformal_map_parameterizer_3<Surface_mesh, Border, Direct_solver>(), settings);
  // Tutte: the same map as CGAL's Barycentric_mapping_parameterizer_3, solved as an SPD system.
  return run_disk_with(mesh, SMP::Symmetric_barycentric_mapping_parameterizer_3<Surface_mesh, Border>(), settings);
}

} // namespace

Disk_run run_disk_fixed_border(const Indexed_mesh& mesh, const Disk_settings& settings)
{
  // --border free keeps the circle of the initial map and lets the flow
  // slide the border along that polygon (options.disk.border is FREE).
  if(settings.border == "square")
    return run_with_border<Square_border_with_ear_corners>(mesh, settings);
  return run_with_border<SMP::Circular_border_arc_length_parameterizer_3<Surface_mesh> >(mesh, settings);
}

} // namespace dlf_cli
