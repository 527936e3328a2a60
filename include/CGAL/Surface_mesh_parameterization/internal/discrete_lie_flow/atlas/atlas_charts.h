// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// From components to flattened charts: a piece that is a disk, or genus 0
// with holes (they float in the flow), is a chart; any other is cut
// (atlas_cut_graph.h) and its parts go round again; a chart whose flow
// does not converge is split in two (atlas_split.h) while the depth and
// size allow; then it gives up its triangles with three border corners
// (each a chart of its own, laid out isometrically), then it is laid out
// triangle by triangle. The flattening
// itself is the caller's function (the public header runs the certified
// disk flow).

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_ATLAS_CHARTS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_ATLAS_CHARTS_H

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_atlas_options.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/atlas/atlas_cut_graph.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/atlas/atlas_mesh.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/atlas/atlas_split.h>

#include <chrono>
#include <deque>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// A flattened chart: its piece, a uv point per piece vertex, its report.
struct Atlas_chart
{
  Atlas_piece piece;
  std::vector<Vec2> uv;
  Discrete_lie_flow_atlas_chart report;
};

/// The one triangle of `P` in the plane, isometric and counter-clockwise
/// (its D_area is exactly optimal), its longest edge along u so that it
/// fills half its box.
inline std::vector<Vec2> lay_out_triangle(const Atlas_piece& P)
{
  std::size_t k = 0; // the longest edge: corner k to k + 1
  double longest = -1;
  for(std::size_t i = 0; i < 3; ++i) {
    const double l = norm3(sub(P.xyz[std::size_t(P.faces[0][(i + 1) % 3])], P.xyz[std::size_t(P.faces[0][i])]));
    if(l > longest) { longest = l; k = i; }
  }
  const int ia = P.faces[0][k], ib = P.faces[0][(k + 1) % 3], ic = P.faces[0][(k + 2) % 3];
  const Vec3 ab = sub(P.xyz[std::size_t(ib)], P.xyz[std::size_t(ia)]), ac = sub(P.xyz[std::size_t(ic)], P.xyz[std::size_t(ia)]);
  std::vector<Vec2> uv(P.xyz.size(), Vec2{{ 0, 0 }});
  uv[std::size_t(ib)] = {{ longest, 0 }};
  uv[std::size_t(ic)] = {{ dot(ab, ac) / longest, norm3(cross(ab, ac)) / longest }};
  return uv;
}

/// The faces of `P` with all three corners on its border.
inline std::vector<char> three_border_corner_mask(const Atlas_piece& P, const std::vector<long>& twin)
{
  std::vector<char> on_border(P.xyz.size(), 0), mask(P.faces.size(), 0);
  for(std::size_t h = 0; h < twin.size(); ++h)
    if(twin[h] < 0) {
      on_border[std::size_t(P.faces[h / 3][h % 3])] = 1;
      on_border[std::size_t(P.faces[h / 3][(h % 3 + 1) % 3])] = 1;
    }
  for(std::size_t f = 0; f < P.faces.size(); ++f)
    mask[f] = on_border[std::size_t(P.faces[f][0])] && on_border[std::size_t(P.faces[f][1])] && on_border[std::size_t(P.faces[f][2])];
  return mask;
}

/// One piece per face of `P`.
inline std::vector<Atlas_piece> single_faces(const Atlas_piece& P)
{
  std::vector<Atlas_piece> out;
  for(std::size_t f = 0; f < P.faces.size(); ++f) out.push_back(sub_piece(P, std::vector<std::size_t>(1, f)));
  return out;
}

/// A piece waiting for make_atlas_charts(): its depth in splits, whether it
/// was cut open already, how many times it gave up border triangles.
struct Atlas_work_item
{
  Atlas_piece piece;
  std::size_t depth;
  bool cut;
  std::size_t peels;
};

/// The parts of `P` (closed, or of genus > 0) cut open along its seam
/// through `tips` tips (atlas_cut_graph.h); `R` counts the closed
/// components and the largest genus.
inline std::vector<Atlas_piece> cut_open_piece(const Atlas_piece& P, const std::vector<long>& twin,
                                               const Piece_topology& T, std::size_t tips,
                                               Discrete_lie_flow_atlas_report& R)
{
  if(T.loops.empty()) ++R.closed_components;
  R.max_genus = (std::max)(R.max_genus, std::size_t((std::max)(0L, T.genus())));
  double length = 0;
  const std::vector<char> seam = piece_seam(P, twin, T, tips, length);
  Atlas_piece opened = P;
  open_along(opened, twin, seam);
  return split_components(opened);
}

/// The triangles of `it.piece` with three border corners, each a piece of
/// its own, then the components of the rest, back on the `work` queue
/// (counted in `R.peeled_faces`).
inline void peel_border_faces(const Atlas_work_item& it, const std::vector<long>& twin,
                              std::deque<Atlas_work_item>& work, Discrete_lie_flow_atlas_report& R)
{
  const std::vector<char> fixed = three_border_corner_mask(it.piece, twin);
  std::vector<std::size_t> rest;
  for(std::size_t f = 0; f < fixed.size(); ++f)
    if(fixed[f]) {
      work.push_back(Atlas_work_item{ sub_piece(it.piece, std::vector<std::size_t>(1, f)), it.depth, false, it.peels + 1 });
      ++R.peeled_faces;
    }
    else
      rest.push_back(f);
  if(!rest.empty())
    for(Atlas_piece& part : split_components(sub_piece(it.piece, rest)))
      work.push_back(Atlas_work_item{ std::move(part), it.depth, false, it.peels + 1 });
}

/// Cuts and flattens `components` into charts. `flatten(piece, uv, chart)`
/// fills `uv` (all triangles positive) and the chart's code, stop reason,
/// iterations and D_area. Returns `OK`, or the code of a chart that could
/// neither be flattened nor split (`message` names it).
template <class Flatten>
Error_code make_atlas_charts(std::vector<Atlas_piece> components, const Discrete_lie_flow_atlas_options& opt,
                             Flatten flatten, std::vector<Atlas_chart>& charts, Discrete_lie_flow_atlas_report& R)
{
  typedef std::chrono::steady_clock Clock;
  typedef Atlas_work_item Item;
  std::deque<Item> work;
  for(Atlas_piece& c : components) work.push_back(Item{ std::move(c), 0, false, 0 });
  while(!work.empty()) {
    Item it = std::move(work.front());
    work.pop_front();
    const Clock::time_point t0 = Clock::now();
    const std::vector<long> twin = halfedge_twins(it.piece.faces);
    const Piece_topology T = piece_topology(it.piece, twin);
    const bool chart = T.disk() || (T.genus() == 0 && !T.loops.empty());
    if(!chart && !it.cut) {
      for(Atlas_piece& part : cut_open_piece(it.piece, twin, T, opt.tips, R))
        work.push_back(Item{ std::move(part), it.depth, true, 0 });
      R.seconds_cut += std::chrono::duration<double>(Clock::now() - t0).count();
      continue;
    }
    if(!chart) { // a cut left something else than a disk: halve it
      std::vector<Atlas_piece> halves = split_piece(it.piece, twin);
      R.seconds_cut += std::chrono::duration<double>(Clock::now() - t0).count();
      // Tiny closed pieces (a tetrahedron) may have no seam that leaves a
      // disk with a triangle between seams: one chart per triangle then.
      if(halves.size() < 2 || it.depth >= opt.max_split_depth + 4) halves = single_faces(it.piece);
      for(Atlas_piece& h : halves) work.push_back(Item{ std::move(h), it.depth + 1, false, 0 });
      continue;
    }
    Atlas_chart C;
    C.report.faces = it.piece.faces.size();
    C.report.vertices = it.piece.xyz.size();
    C.report.holes = T.loops.size() - 1;
    C.report.split_depth = it.depth;
    C.report.three_border_corner_faces = three_border_corner_faces(it.piece, twin);
    R.seconds_cut += std::chrono::duration<double>(Clock::now() - t0).count();
    const Clock::time_point t1 = Clock::now();
    if(opt.progress)
      opt.progress("chart of " + std::to_string(C.report.faces) + " faces" +
                   (it.depth > 0 ? " (split " + std::to_string(it.depth) + ")" : std::string()));
    if(it.piece.faces.size() == 1) { // no flow needed
      C.uv = lay_out_triangle(it.piece);
      C.report.code = OK;
      C.report.stop_reason = Discrete_lie_flow_stop_reason::CONVERGED;
      C.report.d_area = 2;
    }
    else
      flatten(it.piece, C.uv, C.report);
    R.seconds_flow += std::chrono::duration<double>(Clock::now() - t1).count();
    const bool good = C.report.code == OK && C.report.stop_reason == Discrete_lie_flow_stop_reason::CONVERGED;
    if(!good && it.depth < opt.max_split_depth && it.piece.faces.size() >= opt.min_split_faces) {
      const Clock::time_point t2 = Clock::now();
      std::vector<Atlas_piece> halves = split_piece(it.piece, twin);
      R.seconds_cut += std::chrono::duration<double>(Clock::now() - t2).count();
      if(halves.size() >= 2) {
        ++R.splits;
        for(Atlas_piece& h : halves) work.push_back(Item{ std::move(h), it.depth + 1, false, 0 });
        continue;
      }
    }
    // No split left: the triangles the border pins leave first.
    if(!good && C.report.three_border_corner_faces > 0 && it.peels < opt.max_border_peels) {
      peel_border_faces(it, twin, work, R);
      continue;
    }
    // No split left (the depth, the size, or no two halves): one chart per
    // triangle, each laid out isometrically, when the flow failed or
    // stopped short (a few interior vertices cannot bring every triangle to
    // its share).
    if((C.report.code != OK || !good) && it.piece.faces.size() > 1) {
      for(Atlas_piece& h : single_faces(it.piece)) work.push_back(Item{ std::move(h), it.depth + 1, false, 0 });
      if(C.report.code == OK) R.peeled_faces += it.piece.faces.size();
      continue;
    }
    if(C.report.code != OK) {
      R.message = "a chart of " + std::to_string(C.report.faces) + " faces: " + C.report.message;
      return C.report.code;
    }
    C.piece = std::move(it.piece);
    charts.push_back(std::move(C));
  }
  return OK;
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
