// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Densities for measure-controlled maps (the paper's §5.5): a region of
// interest gets `factor` times its share of the domain area. The helpers
// write a per-face density into a face property map, to be passed to
// `Discrete_lie_flow_parameterizer_3::set_face_density()`.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_DISCRETE_LIE_FLOW_DENSITY_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_DISCRETE_LIE_FLOW_DENSITY_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/Surface_mesh_parameterization/internal/kernel_traits.h>
#include <CGAL/Kernel/global_functions.h>
#include <CGAL/squared_distance_3.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <queue>
#include <set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

namespace internal {
namespace dlf {

template <class TriangleMesh>
typename internal::Kernel_traits<TriangleMesh>::Kernel::Point_3
face_centroid(const TriangleMesh& mesh, typename boost::graph_traits<TriangleMesh>::face_descriptor f)
{
  typedef typename internal::Kernel_traits<TriangleMesh>::Kernel::Point_3 Point_3;
  const typename internal::Kernel_traits<TriangleMesh>::PPM ppm = get(vertex_point, mesh);
  double x = 0, y = 0, z = 0, n = 0;
  for(auto v : vertices_around_face(halfedge(f, mesh), mesh)) {
    const auto& p = get(ppm, v);
    x += CGAL::to_double(p.x()); y += CGAL::to_double(p.y()); z += CGAL::to_double(p.z());
    n += 1;
  }
  return Point_3(x / n, y / n, z / n);
}

/// Shortest edge-path lengths (3D edge lengths) from `sources` to every
/// vertex, up to `limit` (further vertices keep +∞). Dijkstra.
template <class TriangleMesh>
std::map<typename boost::graph_traits<TriangleMesh>::vertex_descriptor, double>
edge_path_distances(const TriangleMesh& mesh,
                    const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& sources,
                    double limit)
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  const typename internal::Kernel_traits<TriangleMesh>::PPM ppm = get(vertex_point, mesh);
  std::map<vertex_descriptor, double> dist;
  typedef std::pair<double, vertex_descriptor> Item;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item> > queue;
  for(vertex_descriptor s : sources) { dist[s] = 0; queue.push(Item(0, s)); }
  while(!queue.empty()) {
    const Item top = queue.top();
    queue.pop();
    if(top.first > dist[top.second] || top.first > limit) continue;
    for(auto h : halfedges_around_target(halfedge(top.second, mesh), mesh)) {
      const vertex_descriptor w = source(h, mesh);
      const double d = top.first + std::sqrt(CGAL::to_double(CGAL::squared_distance(get(ppm, w), get(ppm, top.second))));
      auto it = dist.find(w);
      if(d <= limit && (it == dist.end() || d < it->second)) {
        dist[w] = d;
        queue.push(Item(d, w));
      }
    }
  }
  return dist;
}

/// ρ on the band: `factor` at distance 0 from the region, 1 at `band`,
/// geometric in between (a density jump would make a sharp front the flow
/// has to push through).
inline double blended_density(double factor, double distance, double band)
{
  if(distance <= 0) return factor;
  if(band <= 0 || distance >= band) return 1.;
  return std::pow(factor, 1 - distance / band);
}

} // namespace dlf
} // namespace internal

/// \ingroup PkgDiscreteLieFlowHelperFunctions
/// Sets ρ = `factor` on the faces of `region` and 1 elsewhere; with
/// `band` > 0, faces within edge-path distance `band` of the region (from
/// their nearest vertex, in 3D length units) blend geometrically from
/// `factor` to 1.
/// \pre `factor` > 0
template <class TriangleMesh, class FaceRange, class FaceDensityMap>
void set_region_density(const TriangleMesh& mesh, const FaceRange& region, double factor,
                        FaceDensityMap density, double band = 0)
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  std::set<face_descriptor> in(std::begin(region), std::end(region));
  std::vector<vertex_descriptor> seeds;
  for(face_descriptor f : in)
    for(vertex_descriptor v : vertices_around_face(halfedge(f, mesh), mesh)) seeds.push_back(v);
  std::map<vertex_descriptor, double> dist;
  if(band > 0) dist = internal::dlf::edge_path_distances(mesh, seeds, band);
  for(face_descriptor f : faces(mesh)) {
    if(in.count(f)) { put(density, f, factor); continue; }
    double d = std::numeric_limits<double>::infinity();
    for(vertex_descriptor v : vertices_around_face(halfedge(f, mesh), mesh)) {
      const auto it = dist.find(v);
      if(it != dist.end()) d = (std::min)(d, it->second);
    }
    // a face touching the region is at distance 0 from it only at a vertex:
    // give it the first step of the band
    put(density, f, internal::dlf::blended_density(factor, (std::max)(d, band > 0 ? 1e-3 * band : 0.), band));
  }
}

/// \ingroup PkgDiscreteLieFlowHelperFunctions
/// The faces whose centroid satisfies `inside(centroid)` (any predicate on
/// a `Point_3`, for example a half-space or a box).
template <class TriangleMesh, class Predicate>
std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>
faces_where(const TriangleMesh& mesh, Predicate inside)
{
  std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor> out;
  for(auto f : faces(mesh))
    if(inside(internal::dlf::face_centroid(mesh, f))) out.push_back(f);
  return out;
}

/// \ingroup PkgDiscreteLieFlowHelperFunctions
/// The faces whose centroid lies in the Euclidean ball of `center` and `radius`.
template <class TriangleMesh, class Point_3>
std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>
faces_in_ball(const TriangleMesh& mesh, const Point_3& center, double radius)
{
  return faces_where(mesh, [&](const Point_3& c) {
    return CGAL::to_double(CGAL::squared_distance(c, center)) <= radius * radius;
  });
}

/// \ingroup PkgDiscreteLieFlowHelperFunctions
/// The faces whose three vertices lie within edge-path distance `radius` of
/// vertex `center` (a geodesic ball along the edges; exact geodesics differ
/// by the zig-zag factor of the mesh, at most 2/√3 on regular triangulations).
template <class TriangleMesh>
std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>
faces_in_geodesic_ball(const TriangleMesh& mesh,
                       typename boost::graph_traits<TriangleMesh>::vertex_descriptor center, double radius)
{
  const auto dist = internal::dlf::edge_path_distances(mesh, { center }, radius);
  std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor> out;
  for(auto f : faces(mesh)) {
    bool all = true;
    for(auto v : vertices_around_face(halfedge(f, mesh), mesh)) all = all && dist.count(v) > 0;
    if(all) out.push_back(f);
  }
  return out;
}

/// \ingroup PkgDiscreteLieFlowHelperFunctions
/// Achieved and prescribed shares of the domain area of a region: the sum of
/// its faces' domain areas over the total, against the sum of ρ·area over
/// the total. `uvmap` maps vertices to `Point_2`, `density` faces to ρ.
template <class TriangleMesh, class FaceRange, class VertexUVMap, class FaceDensityMap>
std::pair<double, double> region_area_fractions(const TriangleMesh& mesh, const FaceRange& region,
                                                VertexUVMap uvmap, FaceDensityMap density)
{
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  const typename internal::Kernel_traits<TriangleMesh>::PPM ppm = get(vertex_point, mesh);
  std::set<face_descriptor> in(std::begin(region), std::end(region));
  double dom_in = 0, dom_all = 0, tgt_in = 0, tgt_all = 0;
  for(face_descriptor f : faces(mesh)) {
    auto h = halfedge(f, mesh);
    const auto a = get(uvmap, source(h, mesh)), b = get(uvmap, target(h, mesh)), c = get(uvmap, target(next(h, mesh), mesh));
    const double dom = std::abs(CGAL::to_double(CGAL::area(a, b, c)));
    const auto p = get(ppm, source(h, mesh)), q = get(ppm, target(h, mesh)), r = get(ppm, target(next(h, mesh), mesh));
    const double tgt = CGAL::to_double(get(density, f)) * std::sqrt(CGAL::to_double(CGAL::squared_area(p, q, r)));
    dom_all += dom;
    tgt_all += tgt;
    if(in.count(f)) { dom_in += dom; tgt_in += tgt; }
  }
  return std::make_pair(dom_in / dom_all, tgt_in / tgt_all);
}

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
