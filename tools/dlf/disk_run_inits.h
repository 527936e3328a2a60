// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The initial parameterizer the command line names, for any face graph: the
// same choice on the input's Surface_mesh and on a Seam_mesh. `run` is called
// with the parameterizer (e.g. a lambda forwarding to run_disk_on()).

#ifndef DLF_CLI_DISK_RUN_INITS_H
#define DLF_CLI_DISK_RUN_INITS_H

#include "disk_run_impl.h"

#include <CGAL/Surface_mesh_parameterization/ARAP_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Circular_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_conformal_map_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Given_uv_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/LSCM_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Mean_value_coordinates_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Square_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Symmetric_barycentric_mapping_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Two_vertices_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/square_border_corners.h>

#include <boost/property_map/function_property_map.hpp>

#include <type_traits>
#include <vector>

namespace dlf_cli {

/// The square border with the corners of choose_square_border_corners():
/// CGAL's default corners can put the three vertices of an ear triangle on
/// one side (three_peaks.off, mannequin-devil.off).
template <class Mesh>
class Square_border_with_ear_corners
{
public:
  template <typename VertexUVmap, typename VertexIndexMap, typename VertexParameterizedMap>
  CGAL::Surface_mesh_parameterization::Error_code
  parameterize(Mesh& mesh, typename boost::graph_traits<Mesh>::halfedge_descriptor bhd, VertexUVmap uvmap,
               VertexIndexMap vimap, VertexParameterizedMap vpmap)
  {
    namespace SMP = CGAL::Surface_mesh_parameterization;
    const auto corners = SMP::choose_square_border_corners(mesh, bhd);
    if(!corners) return SMP::ERROR_BORDER_TOO_SHORT; // fewer than 4 border vertices, or more than 4 ears
    SMP::Square_border_arc_length_parameterizer_3<Mesh> square((*corners)[0], (*corners)[1], (*corners)[2],
                                                               (*corners)[3]);
    return square.parameterize(mesh, bhd, uvmap, vimap, vpmap);
  }
  bool is_border_convex() const { return true; }
};

template <class Mesh, class Border, class Run>
Disk_run run_with_border(const Disk_settings& settings, Run run)
{
  namespace SMP = CGAL::Surface_mesh_parameterization;
  if(settings.init == "mvc") return run(SMP::Mean_value_coordinates_parameterizer_3<Mesh, Border, Direct_solver>());
  if(settings.init == "dcp") return run(SMP::Discrete_conformal_map_parameterizer_3<Mesh, Border, Direct_solver>());
  // Tutte: the same map as CGAL's Barycentric_mapping_parameterizer_3, solved as an SPD system.
  return run(SMP::Symmetric_barycentric_mapping_parameterizer_3<Mesh, Border>());
}

/// tutte, mvc or dcp on a circle or a square, each with the direct solver.
template <class Mesh, class Run>
Disk_run run_fixed_border_init(const Disk_settings& settings, Run run)
{
  // --border free keeps the circle of the initial map and lets the flow
  // slide the border along that polygon (options.disk.border is FREE).
  if(settings.border == "square") return run_with_border<Mesh, Square_border_with_ear_corners<Mesh> >(settings, run);
  return run_with_border<Mesh, CGAL::Surface_mesh_parameterization::Circular_border_arc_length_parameterizer_3<Mesh> >(
    settings, run);
}

/// lscm or arap, both pinned by two vertices (CGAL's Two_vertices_parameterizer_3,
/// their default border); or the caller's map (`--init-uv`).
template <class Mesh, class Run>
Disk_run run_free_border_init(const Disk_settings& settings, Run run)
{
  namespace SMP = CGAL::Surface_mesh_parameterization;
  typedef SMP::Two_vertices_parameterizer_3<Mesh> Two_vertices;
  // The caller's map (`--init-uv`, on the input's Surface_mesh only: input
  // vertex i is its vertex i, and the file has one uv per input vertex).
  if constexpr(std::is_same<Mesh, Surface_mesh>::value)
    if(settings.init == "uv") {
      const std::vector<Vec2>& uv = settings.init_uv;
      const auto given = boost::make_function_property_map<vertex_descriptor>(
        [&uv](vertex_descriptor v) { return Kernel::Point_2(uv[v.idx()][0], uv[v.idx()][1]); });
      return run(SMP::Given_uv_parameterizer_3<Mesh, std::remove_const_t<decltype(given)> >(given));
    }
  if(settings.init == "arap") return run(SMP::ARAP_parameterizer_3<Mesh, Two_vertices>());
  return run(SMP::LSCM_parameterizer_3<Mesh, Two_vertices>());
}

} // namespace dlf_cli

#endif
