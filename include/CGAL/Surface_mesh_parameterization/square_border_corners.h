// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_SQUARE_BORDER_CORNERS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_SQUARE_BORDER_CORNERS_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Surface_mesh_parameterization/internal/kernel_traits.h>
#include <CGAL/Kernel/global_functions.h>
#include <CGAL/squared_distance_3.h>

#include <boost/optional.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgDiscreteLieFlowHelperFunctions
///
/// Chooses the four corners of a square border so that no triangle gets all
/// three vertices on one side of the square. An *ear* (a border vertex with a
/// single incident triangle, whose two neighbours are on the border too)
/// gives a degenerate triangle unless it is a corner, so ears become corners
/// first; the remaining corners go to the border vertices nearest to the
/// quarters of the border's arc length, measured from the first corner.
/// Pass the result to `Square_border_arc_length_parameterizer_3(v0, v1, v2, v3)`.
///
/// \returns the corners in border order, or nothing when the border has
/// fewer than 4 vertices or more than 4 ears (no square border avoids a
/// degenerate triangle then).
template <class TriangleMesh>
boost::optional<std::array<typename boost::graph_traits<TriangleMesh>::vertex_descriptor, 4> >
choose_square_border_corners(const TriangleMesh& mesh,
                             typename boost::graph_traits<TriangleMesh>::halfedge_descriptor bhd)
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  const typename internal::Kernel_traits<TriangleMesh>::PPM ppm = get(vertex_point, mesh);

  std::vector<vertex_descriptor> loop;
  std::vector<double> arc(1, 0.);
  std::vector<bool> ear;
  for(halfedge_descriptor h : halfedges_around_face(bhd, mesh)) {
    loop.push_back(target(h, mesh));
    // a single incident face holds both border edges of the vertex, consecutively
    ear.push_back(next(opposite(next(h, mesh), mesh), mesh) == opposite(h, mesh));
    const auto& p = get(ppm, source(next(h, mesh), mesh));
    const auto& q = get(ppm, target(next(h, mesh), mesh));
    arc.push_back(arc.back() + std::sqrt(CGAL::to_double(CGAL::squared_distance(p, q))));
  }
  const std::size_t n = loop.size();
  if(n < 4) return boost::none;
  std::vector<std::size_t> corners;
  for(std::size_t i = 0; i < n; ++i)
    if(ear[i]) corners.push_back(i);
  if(corners.size() > 4) return boost::none;
  // Fill up to four corners, each at the free vertex farthest (in arc
  // length) from the corners already chosen.
  const double total = arc[n];
  auto gap = [&](std::size_t i) {
    double best = total;
    for(std::size_t c : corners) {
      const double d = std::abs(arc[i] - arc[c]);
      best = (std::min)(best, (std::min)(d, total - d));
    }
    return best;
  };
  while(corners.size() < 4) {
    std::size_t pick = 0;
    double best = -1;
    for(std::size_t i = 0; i < n; ++i) {
      const double g = corners.empty() ? -double(i) : gap(i);
      if(g > best) { best = g; pick = i; }
    }
    corners.push_back(pick);
  }
  std::sort(corners.begin(), corners.end());
  return std::array<vertex_descriptor, 4>{{ loop[corners[0]], loop[corners[1]], loop[corners[2]], loop[corners[3]] }};
}

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
