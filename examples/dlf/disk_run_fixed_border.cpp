// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The fixed-border initial maps: {Tutte, mean value, discrete conformal} ×
// {circle, square}, each with the direct solver.

#include "disk_run_impl.h"

#include <CGAL/Surface_mesh_parameterization/Barycentric_mapping_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Circular_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_conformal_map_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Mean_value_coordinates_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Square_border_parameterizer_3.h>

namespace dlf_cli {

namespace {

namespace SMP = CGAL::Surface_mesh_parameterization;

template <class Border>
Disk_run run_with_border(const Indexed_mesh& mesh, const Disk_settings& settings)
{
  if(settings.init == "mvc")
    return run_disk_with(mesh, SMP::Mean_value_coordinates_parameterizer_3<Surface_mesh, Border, Direct_solver>(), settings);
  if(settings.init == "dcp")
    return run_disk_with(mesh, SMP::Discrete_conformal_map_parameterizer_3<Surface_mesh, Border, Direct_solver>(), settings);
  return run_disk_with(mesh, SMP::Barycentric_mapping_parameterizer_3<Surface_mesh, Border, Direct_solver>(), settings);
}

} // namespace

Disk_run run_disk_fixed_border(const Indexed_mesh& mesh, const Disk_settings& settings)
{
  // --border free keeps the circle of the initial map and lets the flow
  // slide the border along that polygon (options.border is FREE).
  if(settings.border == "square")
    return run_with_border<SMP::Square_border_arc_length_parameterizer_3<Surface_mesh> >(mesh, settings);
  return run_with_border<SMP::Circular_border_arc_length_parameterizer_3<Surface_mesh> >(mesh, settings);
}

} // namespace dlf_cli
