// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The score of any atlas given as per-corner uv (an OBJ's `f v/vt`), whoever
// made it: charts (faces joined across edges whose two sides share their uv),
// seam length, packing efficiency, global D_area, inverted and degenerate uv
// triangles, and pairs of uv triangles whose interiors overlap. Orientations
// and overlaps are decided by CGAL's exact predicates on the stored doubles;
// the overlap test does not trust the charts' boxes (another tool's charts
// need not be boxes apart, and a chart may fold onto itself).

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_ATLAS_SCORE_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_ATLAS_SCORE_H

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_atlas_options.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/certification.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/distortion.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/geometry.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// What `score_atlas()` measured.
typedef Discrete_lie_flow_atlas_score Atlas_score;

/// Do the interiors of the non-degenerate uv triangles `a` and `b` meet?
/// Two convex polygons have disjoint interiors exactly when a line through
/// an edge of one of them leaves them on its two closed sides.
inline bool interiors_overlap_2(const std::array<const Vec2*, 3>& a, const std::array<const Vec2*, 3>& b)
{
  for(int pass = 0; pass < 2; ++pass) {
    const std::array<const Vec2*, 3>& s = pass == 0 ? a : b;
    const std::array<const Vec2*, 3>& t = pass == 0 ? b : a;
    const int own = int(exact_orientation_2(*s[0], *s[1], *s[2]));
    for(int k = 0; k < 3; ++k) {
      const Vec2 &p = *s[k], &q = *s[(k + 1) % 3];
      bool separated = true;
      for(int j = 0; j < 3 && separated; ++j)
        separated = int(exact_orientation_2(p, q, *t[j])) * own <= 0;
      if(separated) return false;
    }
  }
  return true;
}

/// The charts of an atlas (faces joined across the 3D mesh's edges whose
/// two sides share their uv points, `uv_faces`), a chart's root face per
/// face; `S` gets their number and the seams' length (non-manifold edges
/// count as cut, border edges not).
inline std::vector<std::size_t> score_charts(const std::vector<Vec3>& xyz, const std::vector<Face>& faces,
                                             const std::vector<Face>& uv_faces, Atlas_score& S)
{
  const std::size_t F = faces.size();
  std::vector<std::size_t> parent(F);
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  auto find = [&parent](std::size_t x) {
    while(parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  std::unordered_map<std::uint64_t, std::vector<std::size_t> > edge_corners; // corner 3f+k: edge k → k+1
  edge_corners.reserve(2 * F);
  for(std::size_t f = 0; f < F; ++f)
    for(std::size_t k = 0; k < 3; ++k) {
      const std::uint64_t a = std::uint64_t(faces[f][k]), b = std::uint64_t(faces[f][(k + 1) % 3]);
      edge_corners[(std::min)(a, b) << 32 | (std::max)(a, b)].push_back(3 * f + k);
    }
  for(const auto& e : edge_corners) {
    const std::vector<std::size_t>& c = e.second;
    const std::size_t f0 = c[0] / 3, k0 = c[0] % 3;
    const double length = norm3(sub(xyz[std::size_t(faces[f0][k0])], xyz[std::size_t(faces[f0][(k0 + 1) % 3])]));
    if(c.size() != 2) { // a border edge (or a non-manifold one: cut)
      if(c.size() > 2) S.seam_length += length;
      continue;
    }
    const std::size_t f1 = c[1] / 3, k1 = c[1] % 3;
    // The same edge seen from the two faces: vertex (k0) = vertex (k1 + 1) when consistently oriented.
    const bool flipped = faces[f0][k0] == faces[f1][k1];
    const int u0a = uv_faces[f0][k0], u0b = uv_faces[f0][(k0 + 1) % 3];
    const int u1a = uv_faces[f1][flipped ? k1 : (k1 + 1) % 3], u1b = uv_faces[f1][flipped ? (k1 + 1) % 3 : k1];
    if(u0a == u1a && u0b == u1b) parent[find(f0)] = find(f1);
    else S.seam_length += length;
  }
  std::vector<std::size_t> chart(F);
  for(std::size_t f = 0; f < F; ++f) {
    chart[f] = find(f);
    if(chart[f] == f) ++S.charts;
  }
  return chart;
}

/// The mirrored charts and the folds of an atlas on corners (`corner_uv`,
/// face f at 3f, 3f + 1, 3f + 2): a chart mirrored as a whole is a valid
/// map (another tool may emit one); a triangle against its own chart's
/// orientation is a fold.
inline void score_orientations(const std::vector<Vec2>& corner_uv, const std::vector<std::size_t>& chart,
                               Atlas_score& S)
{
  const std::size_t F = chart.size();
  std::vector<double> chart_signed_area(F, 0.);
  std::vector<CGAL::Orientation> orientation(F);
  for(std::size_t f = 0; f < F; ++f) {
    orientation[f] = exact_orientation_2(corner_uv[3 * f], corner_uv[3 * f + 1], corner_uv[3 * f + 2]);
    chart_signed_area[chart[f]] += signed_area_2(corner_uv[3 * f], corner_uv[3 * f + 1], corner_uv[3 * f + 2]);
  }
  for(std::size_t f = 0; f < F; ++f) {
    if(chart[f] == f && chart_signed_area[f] < 0) ++S.mirrored_charts;
    if(orientation[f] == CGAL::COLLINEAR) continue;
    if((orientation[f] == CGAL::POSITIVE) != (chart_signed_area[chart[f]] >= 0)) ++S.inverted_faces;
  }
}

/// The pairs of uv triangles whose interiors overlap, in all and within a
/// chart: candidate pairs from a uniform grid of the uv box (lower corner
/// `lo`, size in `S`; a pair is tested in the one cell holding the
/// lower-left corner of its boxes' intersection), then the exact test.
inline void score_overlaps(const std::vector<Vec2>& corner_uv, const std::vector<std::size_t>& chart, const Vec2& lo,
                           Atlas_score& S)
{
  const std::size_t F = chart.size();
  const std::size_t n = (std::max)(std::size_t(1), std::size_t(std::sqrt(double(F))));
  auto cell = [&](double x, int i) {
    const double w = i == 0 ? S.bounding_width : S.bounding_height;
    return (std::min)(n - 1, std::size_t((std::max)(0., (x - lo[i]) / w * double(n))));
  };
  std::vector<std::array<double, 4> > box(F); // lo u, lo v, hi u, hi v
  std::vector<std::vector<std::size_t> > grid(n * n);
  for(std::size_t f = 0; f < F; ++f) {
    const Vec2 &a = corner_uv[3 * f], &b = corner_uv[3 * f + 1], &c = corner_uv[3 * f + 2];
    if(exact_orientation_2(a, b, c) == CGAL::COLLINEAR) continue; // counted as degenerate
    box[f] = {{ (std::min)({ a[0], b[0], c[0] }), (std::min)({ a[1], b[1], c[1] }), (std::max)({ a[0], b[0], c[0] }),
                (std::max)({ a[1], b[1], c[1] }) }};
    for(std::size_t i = cell(box[f][0], 0); i <= cell(box[f][2], 0); ++i)
      for(std::size_t j = cell(box[f][1], 1); j <= cell(box[f][3], 1); ++j) grid[i * n + j].push_back(f);
  }
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t j = 0; j < n; ++j) {
      const std::vector<std::size_t>& in = grid[i * n + j];
      for(std::size_t x = 0; x < in.size(); ++x)
        for(std::size_t y = x + 1; y < in.size(); ++y) {
          const std::array<double, 4> &A = box[in[x]], &B = box[in[y]];
          if(!(A[0] < B[2] && B[0] < A[2] && A[1] < B[3] && B[1] < A[3])) continue;
          if(cell((std::max)(A[0], B[0]), 0) != i || cell((std::max)(A[1], B[1]), 1) != j) continue;
          const std::size_t f = in[x], g = in[y];
          const std::array<const Vec2*, 3> ta = {{ &corner_uv[3 * f], &corner_uv[3 * f + 1], &corner_uv[3 * f + 2] }};
          const std::array<const Vec2*, 3> tb = {{ &corner_uv[3 * g], &corner_uv[3 * g + 1], &corner_uv[3 * g + 2] }};
          if(!interiors_overlap_2(ta, tb)) continue;
          ++S.overlapping_face_pairs;
          if(chart[f] == chart[g]) ++S.overlapping_pairs_in_a_chart;
        }
    }
}

/// The score of the atlas `uv` (points) / `uv_faces` (per face, its corners'
/// uv points) of the triangles `faces` over `xyz`.
inline Atlas_score score_atlas(const std::vector<Vec3>& xyz, const std::vector<Face>& faces, const std::vector<Vec2>& uv,
                               const std::vector<Face>& uv_faces)
{
  Atlas_score S;
  const std::size_t F = faces.size();
  S.faces = F;
  if(F == 0) return S;
  const std::vector<std::size_t> chart = score_charts(xyz, faces, uv_faces, S);

  // Areas, the uv box and the whole atlas's distortion, on corners.
  std::vector<Vec3> corner_xyz(3 * F);
  std::vector<Vec2> corner_uv(3 * F);
  std::vector<Face> corner_faces(F);
  Vec2 lo = uv[std::size_t(uv_faces[0][0])], hi = lo;
  for(std::size_t f = 0; f < F; ++f) {
    corner_faces[f] = {{ int(3 * f), int(3 * f + 1), int(3 * f + 2) }};
    for(std::size_t k = 0; k < 3; ++k) {
      corner_xyz[3 * f + k] = xyz[std::size_t(faces[f][k])];
      const Vec2& p = corner_uv[3 * f + k] = uv[std::size_t(uv_faces[f][k])];
      for(int i = 0; i < 2; ++i) { lo[i] = (std::min)(lo[i], p[i]); hi[i] = (std::max)(hi[i], p[i]); }
    }
    S.surface_area += triangle_area_3(corner_xyz[3 * f], corner_xyz[3 * f + 1], corner_xyz[3 * f + 2]);
    S.uv_area += std::abs(signed_area_2(corner_uv[3 * f], corner_uv[3 * f + 1], corner_uv[3 * f + 2]));
  }
  S.bounding_width = hi[0] - lo[0];
  S.bounding_height = hi[1] - lo[1];
  if(S.bounding_width > 0 && S.bounding_height > 0) S.packing_efficiency = S.uv_area / (S.bounding_width * S.bounding_height);
  S.metrics = planar_distortion(corner_xyz, corner_uv, corner_faces);
  S.degenerate_faces = S.metrics.degenerate_faces;
  score_orientations(corner_uv, chart, S);
  if(S.bounding_width > 0 && S.bounding_height > 0) score_overlaps(corner_uv, chart, lo, S);
  return S;
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
