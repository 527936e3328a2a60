// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_DISCRETE_LIE_FLOW_ATLAS_3_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_DISCRETE_LIE_FLOW_ATLAS_3_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_atlas_options.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/atlas/atlas_charts.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/atlas/atlas_mesh.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/atlas/atlas_packing.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/certification.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/distortion.h>
#include <CGAL/Surface_mesh_parameterization/square_border_corners.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/Square_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Symmetric_barycentric_mapping_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/internal/kernel_traits.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

typedef CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3> Atlas_chart_mesh;

/// The square border with the corners of `choose_square_border_corners()`
/// (ears become corners, so no triangle has its three corners on one side).
class Atlas_square_border
{
public:
  template <typename VertexUVmap, typename VertexIndexMap, typename VertexParameterizedMap>
  Error_code parameterize(Atlas_chart_mesh& mesh, boost::graph_traits<Atlas_chart_mesh>::halfedge_descriptor bhd,
                          VertexUVmap uvmap, VertexIndexMap vimap, VertexParameterizedMap vpmap)
  {
    const auto corners = choose_square_border_corners(mesh, bhd);
    if(!corners) return ERROR_BORDER_TOO_SHORT;
    Square_border_arc_length_parameterizer_3<Atlas_chart_mesh> square((*corners)[0], (*corners)[1], (*corners)[2],
                                                                       (*corners)[3]);
    return square.parameterize(mesh, bhd, uvmap, vimap, vpmap);
  }
  bool is_border_convex() const { return true; }
};

/// Flattens one chart with the certified disk flow: its outer loop (the
/// longest) on a square (when `choose_square_border_corners()` finds
/// corners) or a circle, its holes floating. `uv` gets one point per vertex
/// of `piece`, every triangle positive.
inline void flatten_atlas_chart(const Atlas_piece& piece, const Discrete_lie_flow_atlas_options& opt,
                                std::vector<Vec2>& uv, Discrete_lie_flow_atlas_chart& chart)
{
  typedef boost::graph_traits<Atlas_chart_mesh>::halfedge_descriptor halfedge_descriptor;
  typedef Atlas_chart_mesh::Vertex_index Vertex_index;
  Atlas_chart_mesh mesh;
  for(const Vec3& p : piece.xyz) mesh.add_vertex(Atlas_chart_mesh::Point(p[0], p[1], p[2]));
  for(const Face& t : piece.faces)
    if(mesh.add_face(Vertex_index(t[0]), Vertex_index(t[1]), Vertex_index(t[2])) == Atlas_chart_mesh::null_face()) {
      chart.code = ERROR_NO_TOPOLOGICAL_DISC;
      chart.message = "the chart is not a manifold surface";
      return;
    }
  halfedge_descriptor bhd;
  double longest = -1;
  auto visited = mesh.add_property_map<halfedge_descriptor, bool>("h:atlas_visited", false).first;
  for(halfedge_descriptor h : halfedges(mesh)) {
    if(!is_border(h, mesh) || visited[h]) continue;
    double length = 0;
    for(halfedge_descriptor b : halfedges_around_face(h, mesh)) {
      visited[b] = true;
      length += norm3(sub(piece.xyz[source(b, mesh)], piece.xyz[target(b, mesh)]));
    }
    if(length > longest) { longest = length; bhd = h; }
  }
  Discrete_lie_flow_options flow = opt.flow;
  // Below the coarse-to-fine size a chart's flow is cheap to take further.
  if(opt.small_chart_tolerance > 0 && piece.faces.size() < flow.disk.coarse_to_fine_faces)
    flow.tolerance = (std::min)(flow.tolerance, opt.small_chart_tolerance);
  flow.face_density = piece.density;
  if(piece.faces.size() < opt.callback_faces) flow.callback = nullptr;
  auto uvmap = mesh.add_property_map<Vertex_index, CGAL::Simple_cartesian<double>::Point_2>("v:atlas_uv").first;
  auto run = [&](auto& parameterizer) {
    const Error_code code = parameterize(mesh, parameterizer, bhd, uvmap);
    const Discrete_lie_flow_report& r = parameterizer.report();
    chart.code = code;
    chart.stop_reason = r.stop_reason;
    chart.iterations = r.iterations;
    chart.d_area = r.final_d_area;
    chart.message = r.message;
  };
  // The square, where it has corners and Tutte's map on it is fold-free
  // (three corners on one side flatten a triangle); else the circle.
  bool square = opt.border == Discrete_lie_flow_border::SQUARE && choose_square_border_corners(mesh, bhd);
  if(square) {
    flow.disk.border = Discrete_lie_flow_border::SQUARE;
    typedef Symmetric_barycentric_mapping_parameterizer_3<Atlas_chart_mesh, Atlas_square_border> Square_tutte;
    Discrete_lie_flow_parameterizer_3<Atlas_chart_mesh, Square_tutte> parameterizer(Square_tutte(), flow);
    run(parameterizer);
    square = chart.code == OK;
  }
  if(!square) {
    flow.disk.border = Discrete_lie_flow_border::CIRCLE;
    typedef Discrete_lie_flow_parameterizer_3<Atlas_chart_mesh> Circle_flow;
    Circle_flow parameterizer(Circle_flow::Initial_parameterizer(), flow);
    run(parameterizer);
  }
  if(chart.code != OK) return;
  // Converged is the atlas's tolerance (`flow.tolerance`); the small-chart
  // tolerance is a goal beyond it, not a reason to split.
  if(chart.stop_reason != Discrete_lie_flow_stop_reason::CONVERGED && chart.d_area - 2 <= opt.flow.tolerance)
    chart.stop_reason = Discrete_lie_flow_stop_reason::CONVERGED;
  uv.resize(piece.xyz.size());
  for(Vertex_index v : vertices(mesh)) uv[v] = {{ uvmap[v].x(), uvmap[v].y() }};
}

/// Turns a flattened chart counter-clockwise (mirrored if it came clockwise,
/// exact) and scales it so that its uv area is its surface area `area`.
inline void normalize_chart(const Atlas_piece& piece, std::vector<Vec2>& uv, double area)
{
  double signed_area = 0;
  for(const Face& t : piece.faces)
    signed_area += signed_area_2(uv[std::size_t(t[0])], uv[std::size_t(t[1])], uv[std::size_t(t[2])]);
  const double s = std::sqrt(area / std::abs(signed_area));
  for(Vec2& p : uv) p = {{ (signed_area < 0 ? -p[0] : p[0]) * s, p[1] * s }};
}

/// The caller's mesh in index form, faces in the order of faces(mesh), and
/// the halfedge of every corner (3f + k: the halfedge whose target is
/// corner k); `OK`, or the error and `message` (a non-finite coordinate, a
/// face that is not a triangle).
template <class TriangleMesh>
Error_code index_atlas_mesh(const TriangleMesh& mesh, Atlas_piece& all,
                            std::vector<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor>& corner_halfedge,
                            std::string& message)
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  auto index = get(CGAL::dynamic_vertex_property_t<int>(), mesh);
  const typename internal::Kernel_traits<TriangleMesh>::PPM ppmap = get(vertex_point, mesh);
  for(vertex_descriptor v : vertices(mesh)) {
    const auto& p = get(ppmap, v);
    put(index, v, int(all.xyz.size()));
    all.xyz.push_back({{ CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()) }});
    const Vec3& q = all.xyz.back();
    if(!std::isfinite(q[0]) || !std::isfinite(q[1]) || !std::isfinite(q[2])) {
      message = "vertex " + std::to_string(all.xyz.size() - 1) + " has a non-finite coordinate";
      return Error_code(ERROR_DEGENERATE_INPUT);
    }
  }
  for(face_descriptor f : faces(mesh)) {
    Face t;
    std::size_t k = 0;
    for(halfedge_descriptor h : halfedges_around_face(next(halfedge(f, mesh), mesh), mesh)) {
      if(k < 3) { t[k] = get(index, target(h, mesh)); corner_halfedge.push_back(h); }
      ++k;
    }
    if(k != 3) {
      message = "face " + std::to_string(all.faces.size()) + " has " + std::to_string(k) +
                " vertices; triangulate the mesh first";
      return ERROR_NON_TRIANGULAR_MESH;
    }
    all.caller_face.push_back(all.faces.size());
    all.faces.push_back(t);
  }
  return OK;
}

/// The atlas's checks of the faces: some, none of zero area, and a valid
/// `face_density` (then copied into `all`); `OK`, or the error and `message`.
inline Error_code check_atlas_faces(Atlas_piece& all, const std::vector<double>& face_density, std::string& message)
{
  if(all.faces.empty()) {
    message = "the mesh has no faces (" + std::to_string(all.xyz.size()) + " vertices)";
    return ERROR_EMPTY_MESH;
  }
  std::size_t degenerate = 0, first_degenerate = 0;
  for(std::size_t f = 0; f < all.faces.size(); ++f) {
    const Face& t = all.faces[f];
    if(!(triangle_area_3(all.xyz[std::size_t(t[0])], all.xyz[std::size_t(t[1])], all.xyz[std::size_t(t[2])]) > 0))
      if(degenerate++ == 0) first_degenerate = f;
  }
  if(degenerate == all.faces.size()) {
    message = "all " + std::to_string(degenerate) + " faces have zero area";
    return Error_code(ERROR_DEGENERATE_INPUT);
  }
  if(degenerate > 0) {
    const Face& t = all.faces[first_degenerate];
    message = std::to_string(degenerate) + " faces have zero area; first: face " + std::to_string(first_degenerate) +
              " (vertices " + std::to_string(t[0]) + " " + std::to_string(t[1]) + " " + std::to_string(t[2]) + ")";
    return Error_code(ERROR_DEGENERATE_INPUT);
  }
  if(face_density.empty()) return OK;
  if(face_density.size() != all.faces.size()) {
    message = "the density has " + std::to_string(face_density.size()) + " values for " +
              std::to_string(all.faces.size()) + " faces";
    return Error_code(ERROR_INVALID_DENSITY);
  }
  for(std::size_t f = 0; f < all.faces.size(); ++f)
    if(!(face_density[f] > 0) || !std::isfinite(face_density[f])) {
      message = "the density of face " + std::to_string(f) + " is " + std::to_string(face_density[f]);
      return Error_code(ERROR_INVALID_DENSITY);
    }
  all.density = face_density;
  return OK;
}

/// The vertices of `all` that no face uses.
inline std::size_t isolated_vertices(const Atlas_piece& all)
{
  std::vector<char> used(all.xyz.size(), 0);
  for(const Face& t : all.faces)
    for(int v : t) used[std::size_t(v)] = 1;
  return std::size_t(std::count(used.begin(), used.end(), char(0)));
}

/// The charts, each turned counter-clockwise and scaled to its share
/// `area[c] / total` of the surface, packed into the unit square: treemap
/// cells with `stretch_to_fill`, else (or where a cell has no room for the
/// gutter) shelves. `uv` gets the charts' points; `OK` with the report's
/// scale and stretch, or the error and `message` when they do not fit.
inline Error_code pack_atlas_charts(std::vector<Atlas_chart>& charts, const std::vector<double>& area, double total,
                                    const Discrete_lie_flow_atlas_options& options,
                                    std::vector<std::vector<Vec2> >& uv, Discrete_lie_flow_atlas_report& R,
                                    std::string& message)
{
  uv.resize(charts.size());
  for(std::size_t c = 0; c < charts.size(); ++c) {
    normalize_chart(charts[c].piece, charts[c].uv, area[c] / total);
    uv[c].swap(charts[c].uv);
  }
  double stretch = 1;
  bool filled = options.stretch_to_fill;
  const std::vector<std::vector<Vec2> > unplaced = uv;
  double s = filled ? fill_charts(uv, options.gutter, stretch) : 0.;
  if(!(s > 0)) { // no room for the gutter in some cell: shelves
    uv = unplaced;
    filled = false;
    stretch = 1;
    s = pack_charts(uv, options.gutter);
  }
  if(!(s > 0)) {
    message = "the " + std::to_string(charts.size()) + " charts do not fit in the unit square with a gutter of " +
              std::to_string(options.gutter);
    return ERROR_WRONG_PARAMETER;
  }
  R.scale = (filled ? s : s * s) / total;
  R.max_chart_stretch = stretch;
  return OK;
}

/// Per corner 3f + k of the caller's `faces`: its uv, and its vertex among
/// the charts' vertices numbered chart after chart (the seam's sides).
inline void atlas_corners(const std::vector<Atlas_chart>& charts, const std::vector<std::vector<Vec2> >& uv,
                          std::size_t faces, std::vector<Vec2>& corner_uv, std::vector<std::size_t>& corner_vertex)
{
  corner_uv.resize(3 * faces);
  corner_vertex.resize(3 * faces);
  std::size_t offset = 0;
  for(std::size_t c = 0; c < charts.size(); ++c) {
    const Atlas_piece& P = charts[c].piece;
    for(std::size_t f = 0; f < P.faces.size(); ++f)
      for(std::size_t k = 0; k < 3; ++k) {
        const std::size_t corner = 3 * P.caller_face[f] + k;
        corner_uv[corner] = uv[c][std::size_t(P.faces[f][k])];
        corner_vertex[corner] = offset + std::size_t(P.faces[f][k]);
      }
    offset += P.xyz.size();
  }
}

/// Every chart's report, with its share `area[c] / total`, into the atlas's.
inline void add_chart_reports(std::vector<Atlas_chart>& charts, const std::vector<double>& area, double total,
                              Discrete_lie_flow_atlas_report& R)
{
  for(std::size_t c = 0; c < charts.size(); ++c) {
    charts[c].report.area_share = area[c] / total;
    R.three_border_corner_faces += charts[c].report.three_border_corner_faces;
    if(charts[c].report.stop_reason != Discrete_lie_flow_stop_reason::CONVERGED) ++R.unconverged_charts;
    R.chart_reports.push_back(charts[c].report);
  }
  R.charts = charts.size();
}

/// The length of the seams: the caller's edges whose sides lie at
/// different chart vertices (`corner_vertex`, atlas_corners()).
inline double atlas_seam_length(const std::vector<Vec3>& xyz, const std::vector<Face>& faces,
                                const std::vector<long>& twin, const std::vector<std::size_t>& corner_vertex)
{
  double length = 0;
  for(std::size_t h = 0; h < twin.size(); ++h) {
    const long o = twin[h];
    if(o < 0 || std::size_t(o) < h) continue;
    if(corner_vertex[h] != corner_vertex[next_in_face(std::size_t(o))] ||
       corner_vertex[next_in_face(h)] != corner_vertex[std::size_t(o)])
      length += norm3(sub(xyz[std::size_t(faces[h / 3][h % 3])], xyz[std::size_t(faces[h / 3][(h % 3 + 1) % 3])]));
  }
  return length;
}

/// The exact checks of the atlas (uv triangles' orientations, overlapping
/// charts, points outside the square) and its distortion, uv area and
/// surface area, on the corners of the caller's `faces` of `all`.
inline void measure_atlas(const Atlas_piece& all, const std::vector<Face>& faces, const std::vector<Vec2>& corner_uv,
                          const std::vector<std::vector<Vec2> >& uv, Discrete_lie_flow_atlas_report& R)
{
  std::vector<Vec3> corner_xyz(corner_uv.size());
  std::vector<Face> corner_faces(faces.size());
  for(std::size_t f = 0; f < faces.size(); ++f) {
    corner_faces[f] = {{ int(3 * f), int(3 * f + 1), int(3 * f + 2) }};
    for(std::size_t k = 0; k < 3; ++k) corner_xyz[3 * f + k] = all.xyz[std::size_t(faces[f][k])];
  }
  const Orientation_count oc = count_orientations_2(corner_uv, corner_faces);
  R.inverted_faces = oc.inverted;
  R.degenerate_faces = oc.degenerate;
  R.overlapping_chart_pairs = overlapping_chart_pairs(uv, R.points_outside);
  R.metrics = planar_distortion(corner_xyz, corner_uv, corner_faces, all.density);
  double uv_area = 0, area = 0;
  for(std::size_t f = 0; f < faces.size(); ++f) {
    uv_area += signed_area_2(corner_uv[3 * f], corner_uv[3 * f + 1], corner_uv[3 * f + 2]);
    area += triangle_area_3(corner_xyz[3 * f], corner_xyz[3 * f + 1], corner_xyz[3 * f + 2]);
  }
  R.packing_efficiency = uv_area;
  R.surface_area = area;
}

/// "Success"; short of the goals, how many charts, and the first one's own
/// message, which names the goal its flow missed and its value.
inline std::string atlas_message(const Discrete_lie_flow_atlas_report& R)
{
  for(std::size_t c = 0; c < R.chart_reports.size() && R.unconverged_charts > 0; ++c)
    if(R.chart_reports[c].stop_reason != Discrete_lie_flow_stop_reason::CONVERGED)
      return "not converged: " + std::to_string(R.unconverged_charts) + " of " + std::to_string(R.charts) +
             " charts stopped short of their goals (a valid atlas still); the first, chart " + std::to_string(c) +
             " (" + std::to_string(R.chart_reports[c].faces) + " faces): " + R.chart_reports[c].message;
  return "Success";
}

} // namespace dlf
} // namespace internal

/// \ingroup PkgDiscreteLieFlowParameterizers
///
/// Maps any triangle mesh to an area-preserving atlas in the unit square:
/// every triangle gets uv coordinates, charts do not overlap, and every
/// triangle's uv area is its share of the whole surface's (density-weighted)
/// area times one common scale (`report.scale`), fold-free by CGAL's exact
/// orientation predicate.
///
/// Every connected component is handled (isolated vertices are ignored and
/// counted); non-manifold vertices are split, one copy per wedge. A
/// component that is a disk, or genus 0 with holes (the holes float), is one
/// chart; a closed genus-0 component is cut along a tree of shortest paths
/// through `options.tips` tips; a component of genus g > 0 along a
/// tree–cotree cut graph (through its holes, if any), pruned and shortened so
/// that the seam turns around no triangle. Each chart is flattened with the
/// certified flow of `Discrete_lie_flow_parameterizer_3` (square border by
/// default), scaled to its share of the area; a chart whose flow does not
/// converge is split in two geodesic halves, each flattened again (at most
/// `options.max_split_depth` times); one that cannot be split gives up its
/// triangles with three corners on its border, then is laid out triangle
/// by triangle, each isometric (`report.peeled_faces`), so that every chart
/// converges. The charts are packed into the unit
/// square with `options.gutter` around each: by default each fills a cell of
/// a squarified treemap, stretched to the cell's shape by an area-preserving
/// affine map (u, v) → (a·u, v/a), which changes no area ratio
/// (`report.max_chart_stretch` is the largest a or 1/a); with
/// `options.stretch_to_fill` false, the charts keep their shape on shelves.
/// The result is checked exactly (`report.valid()`).
///
/// The uv map is per corner, as CGAL's `Seam_mesh` users expect: for every
/// halfedge `h` with a face, `get(uvmap, h)` is the uv of `target(h, mesh)`
/// as a corner of `face(h, mesh)`. Border halfedges are not written.
///
/// \tparam TriangleMesh a model of `FaceGraph` whose points have a kernel
///   with `Point_2` (e.g. `Surface_mesh<Point_3>`)
/// \tparam HalfedgeUVMap a model of `WritablePropertyMap` with
///   `halfedge_descriptor` as key and the kernel's `Point_2` as value
///
/// \param mesh the input; its faces must be triangles of positive area
/// \param uvmap receives the uv of every corner
/// \param options the settings, see `Discrete_lie_flow_atlas_options`
///
/// \returns the report: `code` is `OK` when an atlas was written;
/// `ERROR_EMPTY_MESH` without faces, `ERROR_NON_TRIANGULAR_MESH`,
/// `ERROR_DEGENERATE_INPUT` (a zero-area face or a non-finite coordinate,
/// named in `message`), `ERROR_INVALID_DENSITY`, `ERROR_WRONG_PARAMETER`
/// (a non-certified mode, a negative gutter) otherwise, and the uv map is
/// then untouched. `converged()` tells whether every chart's flow converged,
/// `valid()` whether the exact checks passed.
template <class TriangleMesh, class HalfedgeUVMap>
Discrete_lie_flow_atlas_report discrete_lie_flow_atlas(const TriangleMesh& mesh, HalfedgeUVMap uvmap,
                                                       const Discrete_lie_flow_atlas_options& options =
                                                         Discrete_lie_flow_atlas_options())
{
  namespace D = internal::dlf;
  typedef std::chrono::steady_clock Clock;
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  typedef typename internal::Kernel_traits<TriangleMesh>::Kernel::Point_2 Point_2;
  const Clock::time_point start = Clock::now();
  Discrete_lie_flow_atlas_report R;
  auto fail = [&R, start](Error_code code, const std::string& message) {
    R.code = code;
    R.message = message;
    R.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return R;
  };
  if(options.flow.mode != Discrete_lie_flow_mode::CERTIFIED)
    return fail(ERROR_WRONG_PARAMETER, "the atlas runs the certified flow only (options.flow.mode)");
  if(!(options.gutter >= 0 && options.gutter < 1))
    return fail(ERROR_WRONG_PARAMETER, "the gutter must be in [0, 1), not " + std::to_string(options.gutter));

  D::Atlas_piece all;
  std::vector<halfedge_descriptor> corner_halfedge;
  std::string message;
  Error_code code = D::index_atlas_mesh(mesh, all, corner_halfedge, message);
  if(code == OK) code = D::check_atlas_faces(all, options.flow.face_density, message);
  if(code != OK) return fail(code, message);
  R.isolated_vertices = D::isolated_vertices(all);
  const std::vector<D::Face> caller_faces = all.faces;
  const std::vector<long> caller_twin = D::halfedge_twins(caller_faces);

  // Components → charts, each flattened.
  std::vector<D::Atlas_piece> components = D::split_components(all);
  R.components = components.size();
  if(options.progress) options.progress(std::to_string(R.components) + " component(s), " + std::to_string(all.faces.size()) + " faces");
  std::vector<D::Atlas_chart> charts;
  code = D::make_atlas_charts(std::move(components), options,
    [&options](const D::Atlas_piece& p, std::vector<D::Vec2>& uv, Discrete_lie_flow_atlas_chart& c) {
      D::flatten_atlas_chart(p, options, uv, c);
    }, charts, R);
  if(code != OK) return fail(code, R.message);

  // Each chart scaled to its share of the area, the charts packed.
  const Clock::time_point t1 = Clock::now();
  double total = 0;
  std::vector<double> chart_area(charts.size());
  for(std::size_t c = 0; c < charts.size(); ++c) total += (chart_area[c] = D::piece_area(charts[c].piece));
  std::vector<std::vector<D::Vec2> > uv;
  code = D::pack_atlas_charts(charts, chart_area, total, options, uv, R, message);
  if(code != OK) return fail(code, message);

  std::vector<D::Vec2> corner_uv;
  std::vector<std::size_t> corner_vertex;
  D::atlas_corners(charts, uv, caller_faces.size(), corner_uv, corner_vertex);
  D::add_chart_reports(charts, chart_area, total, R);
  R.seam_length = D::atlas_seam_length(all.xyz, caller_faces, caller_twin, corner_vertex);
  D::measure_atlas(all, caller_faces, corner_uv, uv, R);
  for(std::size_t corner = 0; corner < corner_uv.size(); ++corner)
    put(uvmap, corner_halfedge[corner], Point_2(corner_uv[corner][0], corner_uv[corner][1]));
  R.seconds_pack = std::chrono::duration<double>(Clock::now() - t1).count();
  R.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  R.message = D::atlas_message(R);
  return R;
}

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
