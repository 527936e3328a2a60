// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The templated part of a run, instantiated once per initial parameterizer
// in disk_run_fixed_border.cpp and disk_run_free_border.cpp (two translation
// units, so that a two-core build compiles them side by side).

#ifndef DLF_CLI_DISK_RUN_IMPL_H
#define DLF_CLI_DISK_RUN_IMPL_H

#include "disk_run.h"
#include "surface_mesh.h"

#include <CGAL/Surface_mesh_parameterization/Error_code.h>
#include <CGAL/Dynamic_property_map.h>

#include <Eigen/SparseLU>

#include <chrono>
#include <utility>

namespace dlf_cli {

/// The direct solver CGAL's fixed-border parameterizers use (and the
/// library's default initial map), so that Tutte on a circle is the very
/// instantiation the library's default makes.
typedef CGAL::Eigen_solver_traits<Eigen::SparseLU<CGAL::Eigen_sparse_matrix<double>::EigenType,
                                                  Eigen::COLAMDOrdering<int> > > Direct_solver;

/// Runs the flow with the initial parameterizer `init` on any face graph
/// (`Surface_mesh`, `Seam_mesh`), calling the parameterizer's own
/// parameterize() (as SMP's free function does) with `vimap`, which numbers
/// the vertices 0..n-1: the run's maps and the report's `domain_faces` use
/// those numbers.
template <class Mesh, class Init, class VertexIndexMap>
Disk_run run_disk_on(Mesh& mesh, typename boost::graph_traits<Mesh>::halfedge_descriptor bhd, VertexIndexMap vimap,
                     const Init& init, const Disk_settings& settings)
{
  namespace SMP = CGAL::Surface_mesh_parameterization;
  typedef SMP::Discrete_lie_flow_parameterizer_3<Mesh, Init> Parameterizer;
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor Vertex;

  // Every vertex gets its entry now: on a Seam_mesh these maps are hash
  // maps, which a later insertion could rehash under a reference that a
  // parameterizer holds.
  auto uvmap = get(CGAL::dynamic_vertex_property_t<Kernel::Point_2>(), mesh);
  auto vpmap = get(CGAL::dynamic_vertex_property_t<bool>(), mesh);
  for(Vertex v : vertices(mesh)) {
    put(uvmap, v, Kernel::Point_2(0, 0));
    put(vpmap, v, false);
  }

  Disk_run run;
  Parameterizer parameterizer(init, settings.options);
  const auto t0 = std::chrono::steady_clock::now();
  // The precise code is the report's (the call returns CGAL's nearest).
  parameterizer.parameterize(mesh, bhd, uvmap, vimap, vpmap);
  run.status = parameterizer.report().status;
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  run.report = parameterizer.report();
  run.initial_uv = std::move(run.report.initial_uv); // the flow overwrote the map; the report kept the start
  if(run.status == SMP::OK) {
    run.final_uv.resize(num_vertices(mesh));
    for(Vertex v : vertices(mesh)) {
      const Kernel::Point_2 p = get(uvmap, v);
      run.final_uv[std::size_t(get(vimap, v))] = {{ p.x(), p.y() }};
    }
  }
  return run;
}

/// The same on the Surface_mesh of `mesh`, built in input order.
template <class Init>
Disk_run run_disk_with(const Indexed_mesh& mesh, const Init& init, const Disk_settings& settings)
{
  Surface_mesh sm;
  build_surface_mesh(mesh, sm);
  halfedge_descriptor bhd = boost::graph_traits<Surface_mesh>::null_halfedge();
  for(halfedge_descriptor h : halfedges(sm))
    if(is_border(h, sm) && (settings.on_outer_loop.empty() || settings.on_outer_loop[target(h, sm).idx()])) {
      bhd = h; // the first on the outer loop (checked: a disk, or a disk with holes)
      break;
    }
  auto vimap = sm.add_property_map<vertex_descriptor, int>("v:dlf_index", -1).first;
  for(vertex_descriptor v : vertices(sm)) put(vimap, v, int(v.idx()));
  return run_disk_on(sm, bhd, vimap, init, settings);
}

} // namespace dlf_cli

#endif
