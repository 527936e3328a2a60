// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// From components to flattened charts: a piece that is a disk, or genus 0
// with holes (they float in the flow), is a chart; any other is cut
// (atlas_cut_graph.h) and its parts go round again; a chart whose flow
// does not converge is split in two (atlas_split.h) while the depth and
// size allow. The flattening itself is the caller's function (the public
// header runs the certified disk flow).

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

/// One piece per face of `P`.
inline std::vector<Atlas_piece> single_faces(const Atlas_piece& P)
{
  std::vector<Atlas_piece> out;
  for(std::size_t f = 0; f < P.faces.size(); ++f) out.push_back(sub_piece(P, std::vector<std::size_t>(1, f)));
  return out;
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
  struct Item { Atlas_piece piece; std::size_t depth; bool cut; };
  std::deque<Item> work;
  for(Atlas_piece& c : components) work.push_back(Item{ std::move(c), 0, false });
  while(!work.empty()) {
    Item it = std::move(work.front());
    work.pop_front();
    const Clock::time_point t0 = Clock::now();
    const std::vector<long> twin = halfedge_twins(it.piece.faces);
    const Piece_topology T = piece_topology(it.piece, twin);
    const bool chart = T.disk() || (T.genus() == 0 && !T.loops.empty());
    if(!chart && !it.cut) {
      if(T.loops.empty()) ++R.closed_components;
      R.max_genus = (std::max)(R.max_genus, std::size_t((std::max)(0L, T.genus())));
      double length = 0;
      const std::vector<char> seam = piece_seam(it.piece, twin, T, opt.tips, length);
      Atlas_piece opened = it.piece;
      open_along(opened, twin, seam);
      for(Atlas_piece& part : split_components(opened)) work.push_back(Item{ std::move(part), it.depth, true });
      R.seconds_cut += std::chrono::duration<double>(Clock::now() - t0).count();
      continue;
    }
    if(!chart) { // a cut left something else than a disk: halve it
      std::vector<Atlas_piece> halves = split_piece(it.piece, twin);
      R.seconds_cut += std::chrono::duration<double>(Clock::now() - t0).count();
      // Tiny closed pieces (a tetrahedron) may have no seam that leaves a
      // disk with a triangle between seams: one chart per triangle then.
      if(halves.size() < 2 || it.depth >= opt.max_split_depth + 4) halves = single_faces(it.piece);
      for(Atlas_piece& h : halves) work.push_back(Item{ std::move(h), it.depth + 1, false });
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
    flatten(it.piece, C.uv, C.report);
    R.seconds_flow += std::chrono::duration<double>(Clock::now() - t1).count();
    const bool good = C.report.code == OK && C.report.stop_reason == Discrete_lie_flow_stop_reason::CONVERGED;
    if(!good && it.depth < opt.max_split_depth && it.piece.faces.size() >= opt.min_split_faces) {
      const Clock::time_point t2 = Clock::now();
      std::vector<Atlas_piece> halves = split_piece(it.piece, twin);
      R.seconds_cut += std::chrono::duration<double>(Clock::now() - t2).count();
      if(halves.size() >= 2) {
        ++R.splits;
        for(Atlas_piece& h : halves) work.push_back(Item{ std::move(h), it.depth + 1, false });
        continue;
      }
    }
    if(C.report.code != OK && it.piece.faces.size() > 1) { // no split left: one chart per triangle
      for(Atlas_piece& h : single_faces(it.piece)) work.push_back(Item{ std::move(h), it.depth + 1, false });
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
