// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The free-border initial maps: LSCM and ARAP, both pinned by two vertices
// (CGAL's Two_vertices_parameterizer_3, their default border).

#include "disk_run_impl.h"

#include <CGAL/Surface_mesh_parameterization/ARAP_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/LSCM_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Two_vertices_parameterizer_3.h>

namespace dlf_cli {

Disk_run run_disk_free_border(const Indexed_mesh& mesh, const Disk_settings& settings)
{
  namespace SMP = CGAL::Surface_mesh_parameterization;
  typedef SMP::Two_vertices_parameterizer_3<Surface_mesh> Two_vertices;
  if(settings.init == "arap") return run_disk_with(mesh, SMP::ARAP_parameterizer_3<Surface_mesh, Two_vertices>(), settings);
  return run_disk_with(mesh, SMP::LSCM_parameterizer_3<Surface_mesh, Two_vertices>(), settings);
}

} // namespace dlf_cli
