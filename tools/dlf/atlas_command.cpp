// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// `dlf atlas MESH -o OUT.obj`: any triangle or polygon mesh to a certified
// area-preserving atlas in the unit square (discrete_lie_flow_atlas()).
// Input hygiene with CGAL's Polygon_mesh_processing, said aloud: polygons
// triangulated, non-manifold vertices duplicated (appended after the
// file's vertices), degenerate faces dropped (they cannot have a positive
// uv area), isolated vertices kept and counted, a polygon soup's duplicate
// vertices on open edges merged; one stderr line and one report field
// each. The OBJ keeps the file's `v` lines in order; `vt` one per chart
// vertex, faces `f v/vt`. `--svg`: the packed atlas, each triangle
// coloured by its uv area against its share of the surface; `--texture`:
// the OBJ with a checkerboard of squares equal in surface area.

#include "cli_error.h"
#include "commands.h"
#include "mesh_input.h"
#include "obj_io.h"
#include "output_files.h"
#include "progress.h"
#include "svg_common.h"
#include "texture_output.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_atlas_3.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace dlf_cli {

namespace {

namespace SMP = CGAL::Surface_mesh_parameterization;
typedef CGAL::Simple_cartesian<double> Atlas_kernel;
typedef CGAL::Surface_mesh<Atlas_kernel::Point_3> Atlas_mesh;
typedef CGAL::Exact_predicates_inexact_constructions_kernel EK;

const char* atlas_help =
  "Usage: dlf atlas MESH -o OUT.obj [options]\n"
  "  Any triangle or polygon mesh (every component, any genus, holes) to an atlas\n"
  "  in the unit square: charts cut and flattened by the certified flow, every\n"
  "  triangle's uv area its share of the surface, no fold, no overlap.\n"
  "Options:\n"
  "  -o, --output OUT.obj   the atlas: the file's v lines in order, vt per chart vertex, f v/vt\n"
  "  --report R.json        the report (charts, seam length, packing, D_area, repairs, checks)\n"
  "  --csv R.csv            the report as CSV: a header and one row, its keys flattened\n"
  "  --svg A.svg            the packed atlas, each triangle coloured by its uv area over its share\n"
  "  --texture NAME.obj     the mesh textured by a checkerboard (NAME.obj, .mtl, .png): the atlas\n"
  "                         preserves area, so every square covers the same area of the surface\n"
  "  --texture-size N       the checkerboard's pixels a side (default 1024)\n"
  "  --border square|circle the charts' border (default square: fills its cell)\n"
  "  --tips K               tips a closed component's seam runs through (default 2)\n"
  "  --gutter G             space around each chart, uv units (default 1/1024)\n"
  "  --no-stretch           keep the charts' shapes (shelf packing) instead of\n"
  "                         filling treemap cells by area-preserving stretches\n"
  "  --keep-duplicates      keep vertices at one position on open edges apart (by default\n"
  "                         they are merged: a polygon soup's pieces are joined)\n"
  "  -q, --quiet            no progress lines, no summary\n"
  "Exit: 0 valid atlas, every chart converged; 3 valid atlas, a chart stopped short;\n"
  "      1 bad input (nothing written); 2 no atlas.\n";

struct Atlas_args
{
  std::string input, output, report, csv, svg, texture;
  int texture_size = 1024;
  bool texture_size_given = false;
  SMP::Discrete_lie_flow_atlas_options options;
  bool quiet = false;
  bool merge_duplicates = true;
};

Atlas_args parse(const std::vector<std::string>& args)
{
  Atlas_args a;
  auto value = [&](std::size_t& i) -> const std::string& {
    if(i + 1 >= args.size()) throw Cli_error("atlas: " + args[i] + " needs a value (see 'dlf atlas --help')");
    return args[++i];
  };
  auto number = [&](std::size_t& i) {
    const std::string& s = value(i);
    std::size_t end = 0;
    double x = 0;
    try { x = std::stod(s, &end); } catch(...) { end = 0; }
    if(end != s.size() || !std::isfinite(x)) throw Cli_error("atlas: " + args[i - 1] + " wants a number, not '" + s + "'");
    return x;
  };
  for(std::size_t i = 0; i < args.size(); ++i) {
    const std::string& s = args[i];
    if(s == "-h" || s == "--help") { std::cout << atlas_help; std::exit(EXIT_OK); }
    else if(s == "-o" || s == "--output") a.output = value(i);
    else if(s == "--report") a.report = value(i);
    else if(s == "--csv") a.csv = value(i);
    else if(s == "--svg") a.svg = value(i);
    else if(s == "--texture") {
      a.texture = value(i);
      texture_paths(a.texture); // a name that is not NAME.obj fails now, not after the flow
    }
    else if(s == "--texture-size") {
      const double n = number(i);
      if(!(n >= 16 && n <= 16384 && n == std::floor(n))) throw Cli_error("atlas: --texture-size is a whole number from 16 to 16384");
      a.texture_size = int(n);
      a.texture_size_given = true;
    }
    else if(s == "--border") {
      const std::string& b = value(i);
      if(b != "square" && b != "circle") throw Cli_error("atlas: --border is square or circle, not '" + b + "'");
      a.options.border = b == "square" ? SMP::Discrete_lie_flow_border::SQUARE : SMP::Discrete_lie_flow_border::CIRCLE;
    }
    else if(s == "--tips") {
      const double k = number(i);
      if(!(k >= 2 && k <= 1000 && k == std::floor(k))) throw Cli_error("atlas: --tips is a whole number from 2 to 1000");
      a.options.tips = std::size_t(k);
    }
    else if(s == "--gutter") {
      const double g = number(i);
      if(!(g >= 0 && g < 0.5)) throw Cli_error("atlas: --gutter is in [0, 0.5)");
      a.options.gutter = g;
    }
    else if(s == "--no-stretch") a.options.stretch_to_fill = false;
    else if(s == "--keep-duplicates") a.merge_duplicates = false;
    else if(s == "-q" || s == "--quiet") a.quiet = true;
    else if(!s.empty() && s[0] == '-') throw Cli_error("atlas: unknown option " + s + " (see 'dlf atlas --help')");
    else if(a.input.empty()) a.input = s;
    else throw Cli_error("atlas: one mesh only ('" + a.input + "', then '" + s + "')");
  }
  if(a.input.empty()) throw Cli_error("atlas: missing MESH (see 'dlf atlas --help')");
  if(a.output.empty()) throw Cli_error("atlas: missing -o OUT.obj");
  if(a.texture_size_given && a.texture.empty()) throw Cli_error("atlas: --texture-size applies to --texture only");
  return a;
}

/// What the input needed.
struct Repairs
{
  std::size_t polygons_triangulated = 0;
  std::size_t nonmanifold_vertices_added = 0;
  std::size_t degenerate_faces_dropped = 0;
  std::size_t isolated_vertices = 0;
  std::size_t duplicate_vertices_merged = 0;
};

/// Reads MESH into a triangle mesh, repairing what Polygon_mesh_processing
/// repairs and saying so; throws `Cli_error` for what cannot be an atlas.
/// A polygon soup's vertices at one position on open edges (a face whose
/// edge no other face shares) become one, the smallest index: CAD exports
/// and per-corner formats repeat a vertex on each side of a seam between
/// pieces, which would otherwise each become charts of their own. The
/// polygons are renumbered; returns the copies merged.
std::size_t merge_seam_duplicates(const std::vector<Atlas_kernel::Point_3>& points,
                                  std::vector<std::vector<std::size_t> >& polygons)
{
  const std::size_t n = points.size();
  std::vector<std::pair<std::size_t, std::size_t> > edges;
  for(const auto& p : polygons)
    for(std::size_t k = 0; k < p.size(); ++k) {
      const std::size_t a = p[k], b = p[(k + 1) % p.size()];
      if(a < n && b < n && a != b) edges.emplace_back((std::min)(a, b), (std::max)(a, b));
    }
  std::sort(edges.begin(), edges.end());
  std::vector<char> open(n, 0);
  for(std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while(j < edges.size() && edges[j] == edges[i]) ++j;
    if(j - i == 1) open[edges[i].first] = open[edges[i].second] = 1;
    i = j;
  }
  std::vector<std::size_t> on_open;
  for(std::size_t v = 0; v < n; ++v)
    if(open[v]) on_open.push_back(v);
  const auto position = [&points](std::size_t v) { return std::make_tuple(points[v].x(), points[v].y(), points[v].z()); };
  std::stable_sort(on_open.begin(), on_open.end(), [&](std::size_t a, std::size_t b) { return position(a) < position(b); });
  std::vector<std::size_t> to(n);
  for(std::size_t v = 0; v < n; ++v) to[v] = v;
  std::size_t merged = 0;
  for(std::size_t i = 1; i < on_open.size(); ++i)
    if(position(on_open[i]) == position(on_open[i - 1])) {
      to[on_open[i]] = to[on_open[i - 1]];
      ++merged;
    }
  if(merged > 0)
    for(auto& p : polygons)
      for(std::size_t& v : p)
        if(v < n) v = to[v];
  return merged;
}

Atlas_mesh read_and_repair(const std::string& path, Repairs& rep, std::size_t& file_vertices, bool quiet, bool merge)
{
  std::vector<Atlas_kernel::Point_3> points;
  std::vector<std::vector<std::size_t> > polygons;
  {
    std::ifstream probe(path);
    if(!probe) throw Cli_error(path + ": cannot open");
  }
  {
    // OFF by the package's own reader (CGAL's parses numbers several times slower).
    std::vector<Vec3> xyz;
    if(!dlf_cli::read_polygon_soup(path, xyz, polygons) && xyz.empty())
      throw Cli_error(path + ": empty or unreadable mesh file");
    points.reserve(xyz.size());
    for(const Vec3& p : xyz) points.emplace_back(p[0], p[1], p[2]);
  }
  file_vertices = points.size();
  if(points.empty()) throw Cli_error(path + ": empty mesh (no vertices)");
  for(std::size_t i = 0; i < points.size(); ++i)
    if(!std::isfinite(points[i].x()) || !std::isfinite(points[i].y()) || !std::isfinite(points[i].z()))
      throw Cli_error(path + ": vertex " + std::to_string(i) + " has a non-finite coordinate");
  if(polygons.empty())
    throw Cli_error(path + ": a point cloud (" + std::to_string(points.size()) + " vertices, no faces); an atlas needs faces");
  auto say = [&](const std::string& line) { if(!quiet) std::cerr << "dlf: atlas: " << line << "\n"; };
  // Polygons with a repeated or out-of-range corner, or fewer than 3, have no area.
  if(merge) rep.duplicate_vertices_merged = merge_seam_duplicates(points, polygons);
  std::vector<std::vector<std::size_t> > kept;
  for(const auto& p : polygons) {
    bool ok = p.size() >= 3;
    for(std::size_t k = 0; ok && k < p.size(); ++k) ok = p[k] < points.size() && p[k] != p[(k + 1) % p.size()];
    if(ok) kept.push_back(p); else ++rep.degenerate_faces_dropped;
  }
  // Triangles of zero area (exact), dropped now; polygons after triangulation.
  auto zero_area = [&](const std::vector<std::size_t>& p) {
    auto P = [&](std::size_t i) { return EK::Point_3(points[i].x(), points[i].y(), points[i].z()); };
    return p.size() == 3 && CGAL::collinear(P(p[0]), P(p[1]), P(p[2]));
  };
  auto build = [&](std::vector<std::vector<std::size_t> >& soup) {
    std::vector<std::vector<std::size_t> > good;
    for(auto& p : soup)
      if(zero_area(p)) ++rep.degenerate_faces_dropped; else good.push_back(p);
    if(good.empty())
      throw Cli_error(path + ": all " + std::to_string(polygons.size()) + " faces are degenerate (zero area)");
    const std::size_t before = points.size();
    // Orienting costs more than the rest of the reading at a million faces:
    // a triangle soup that is already an oriented manifold skips it.
    bool triangles = true;
    for(const auto& p : good) triangles = triangles && p.size() == 3;
    if(!triangles || !is_oriented_manifold_soup(points.size(), good))
      CGAL::Polygon_mesh_processing::orient_polygon_soup(points, good);
    rep.nonmanifold_vertices_added += points.size() - before;
    Atlas_mesh mesh;
    CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, good, mesh);
    return mesh;
  };
  Atlas_mesh mesh = build(kept);
  for(auto f : faces(mesh))
    if(degree(f, mesh) > 3) ++rep.polygons_triangulated;
  if(rep.polygons_triangulated > 0) {
    CGAL::Polygon_mesh_processing::triangulate_faces(mesh);
    // Triangulation may make zero-area triangles: back to a soup, and again.
    std::vector<std::vector<std::size_t> > tris;
    for(auto f : faces(mesh)) {
      std::vector<std::size_t> t;
      for(auto v : vertices_around_face(halfedge(f, mesh), mesh)) t.push_back(std::size_t(v));
      tris.push_back(t);
    }
    points.assign(mesh.points().begin(), mesh.points().end());
    mesh = build(tris);
  }
  std::vector<char> used(num_vertices(mesh), 0);
  for(auto f : faces(mesh))
    for(auto v : vertices_around_face(halfedge(f, mesh), mesh)) used[std::size_t(v)] = 1;
  for(char u : used) rep.isolated_vertices += u ? 0 : 1;
  rep.isolated_vertices -= (std::min)(rep.isolated_vertices, rep.duplicate_vertices_merged);
  if(rep.duplicate_vertices_merged)
    say(std::to_string(rep.duplicate_vertices_merged) + " duplicate vertices merged (a polygon soup: vertices at one position on open edges; their v lines kept, unused; --keep-duplicates keeps them apart)");
  if(rep.polygons_triangulated) say(std::to_string(rep.polygons_triangulated) + " polygons triangulated");
  if(rep.nonmanifold_vertices_added)
    say(std::to_string(rep.nonmanifold_vertices_added) + " vertices added to make the mesh manifold (non-manifold vertices and edges split; appended after the file's vertices)");
  if(rep.degenerate_faces_dropped)
    say(std::to_string(rep.degenerate_faces_dropped) + " degenerate faces (zero area) dropped: they have no uv");
  if(rep.isolated_vertices) say(std::to_string(rep.isolated_vertices) + " isolated vertices kept as v lines, ignored");
  return mesh;
}

} // namespace

nlohmann::ordered_json atlas_report_json(const SMP::Discrete_lie_flow_atlas_report& r)
{
  nlohmann::ordered_json j;
  j["status"] = r.converged() ? "ok" : "not_converged";
  j["message"] = r.message;
  j["components"] = r.components;
  j["isolated_vertices"] = r.isolated_vertices;
  j["closed_components"] = r.closed_components;
  j["max_genus"] = r.max_genus;
  j["charts"] = r.charts;
  j["splits"] = r.splits;
  j["peeled_faces"] = r.peeled_faces;
  j["unconverged_charts"] = r.unconverged_charts;
  j["converged"] = r.converged();
  j["valid"] = r.valid();
  j["seam_length"] = r.seam_length;
  j["surface_area"] = r.surface_area;
  j["packing_efficiency"] = r.packing_efficiency;
  j["max_chart_stretch"] = r.max_chart_stretch;
  j["d_area"] = r.metrics.d_area;
  j["log_area_max_abs"] = r.metrics.log_area_max_abs;
  j["inverted_faces"] = r.inverted_faces;
  j["degenerate_faces"] = r.degenerate_faces;
  j["overlapping_chart_pairs"] = r.overlapping_chart_pairs;
  j["points_outside"] = r.points_outside;
  j["three_border_corner_faces"] = r.three_border_corner_faces;
  j["seconds"] = r.seconds;
  j["seconds_cut"] = r.seconds_cut;
  j["seconds_flow"] = r.seconds_flow;
  j["seconds_pack"] = r.seconds_pack;
  nlohmann::ordered_json charts = nlohmann::ordered_json::array();
  for(const auto& c : r.chart_reports)
    charts.push_back({ { "faces", c.faces }, { "holes", c.holes }, { "split_depth", c.split_depth },
                       { "area_share", c.area_share }, { "iterations", c.iterations }, { "d_area", c.d_area },
                       { "stop_reason", SMP::discrete_lie_flow_stop_reason_name(c.stop_reason) },
                       { "three_border_corner_faces", c.three_border_corner_faces } });
  j["chart_list"] = charts;
  return j;
}

namespace {

// Runs the atlas on the repaired mesh: one line per chart on stderr; the
// iterations of a chart large enough to take seconds as the other commands
// print them (in place on a terminal). Throws `Cli_error` when there is no
// valid atlas.
SMP::Discrete_lie_flow_atlas_report run_atlas(const Atlas_args& a, Atlas_mesh& mesh,
                                              Atlas_mesh::Property_map<Atlas_mesh::Halfedge_index, Atlas_kernel::Point_2> uv)
{
  SMP::Discrete_lie_flow_atlas_options options = a.options;
  Progress progress(a.quiet ? Verbosity::QUIET : Verbosity::NORMAL, false, stderr);
  if(!a.quiet) {
    options.progress = [&progress](const std::string& s) { progress.finish(); std::cerr << "dlf: atlas: " << s << "\n"; };
    options.flow.callback = progress.callback();
    options.callback_faces = 20000;
  }
  const SMP::Discrete_lie_flow_atlas_report r = SMP::discrete_lie_flow_atlas(mesh, uv, options);
  progress.finish();
  if(r.code != SMP::OK) {
    const Exit_code code = (r.code == SMP::ERROR_EMPTY_MESH || int(r.code) == int(SMP::ERROR_DEGENERATE_INPUT) ||
                            r.code == SMP::ERROR_NON_TRIANGULAR_MESH) ? EXIT_BAD_INPUT : EXIT_FLOW_ERROR;
    throw Cli_error(a.input + ": " + SMP::discrete_lie_flow_error_message(r.code) + ": " + r.message, code);
  }
  if(!r.valid()) throw Cli_error(a.input + ": the atlas failed its exact checks (nothing written)", EXIT_FLOW_ERROR);
  return r;
}

// The atlas as OBJ arrays: v in the mesh's vertex order (the file's, then
// added ones), one vt per (vertex, uv) in the order the faces first name them.
struct Atlas_obj
{
  std::vector<Vec3> xyz;
  std::vector<Vec2> vt;
  std::vector<Triangle> faces, vt_faces;
};

Atlas_obj atlas_obj(const Atlas_mesh& mesh, Atlas_mesh::Property_map<Atlas_mesh::Halfedge_index, Atlas_kernel::Point_2> uv)
{
  Atlas_obj obj;
  obj.xyz.reserve(num_vertices(mesh));
  for(auto v : vertices(mesh)) {
    const auto& p = mesh.point(v);
    obj.xyz.push_back({{ p.x(), p.y(), p.z() }});
  }
  obj.faces.reserve(num_faces(mesh));
  obj.vt_faces.reserve(num_faces(mesh));
  // The vt of each vertex in a list of their own (a vertex on a seam has
  // one per side): head[v], then next[].
  std::vector<int> head(obj.xyz.size(), -1), next;
  for(auto f : faces(mesh)) {
    Triangle t, w;
    int k = 0;
    for(auto h : halfedges_around_face(halfedge(f, mesh), mesh)) {
      const int v = int(target(h, mesh));
      const Vec2 q{{ uv[h].x(), uv[h].y() }};
      int i = head[std::size_t(v)];
      while(i >= 0 && obj.vt[std::size_t(i)] != q) i = next[std::size_t(i)];
      if(i < 0) {
        i = int(obj.vt.size());
        obj.vt.push_back(q);
        next.push_back(head[std::size_t(v)]);
        head[std::size_t(v)] = i;
      }
      t[std::size_t(k)] = v;
      w[std::size_t(k)] = i;
      ++k;
    }
    obj.faces.push_back(t);
    obj.vt_faces.push_back(w);
  }
  return obj;
}

// -o, and --texture: the atlas is the unit square already, so the
// checkerboard's squares are equal in uv area, hence in surface area.
void write_atlas_meshes(const Atlas_args& a, const Atlas_obj& obj, const std::string& comment)
{
  {
    std::ofstream out(a.output, std::ios::binary);
    write_uv_obj(out, obj.xyz, obj.vt, obj.faces, obj.vt_faces, comment);
    if(!(out.flush())) throw Cli_error("atlas: cannot write " + a.output);
  }
  if(a.texture.empty()) return;
  const Texture_paths t = texture_paths(a.texture);
  std::ofstream out(t.obj, std::ios::binary), mtl(t.mtl), png(t.png, std::ios::binary);
  write_textured_obj(out, obj.xyz, obj.vt, obj.faces, std::filesystem::path(t.mtl).filename().string(),
                     comment + " (a checkerboard: squares of equal surface area)", obj.vt_faces);
  write_checker_mtl(mtl, std::filesystem::path(t.png).filename().string());
  write_checker_png(png, a.texture_size, 16);
  if(!out.flush() || !mtl.flush() || !png.flush()) throw Cli_error("atlas: cannot write " + a.texture + " (or its .mtl, .png)");
}

// --svg: the unit square at 800 px, v up; each triangle's colour: log of
// its uv area over its share of the surface (white: exact).
void write_atlas_svg(const Atlas_args& a, const Atlas_mesh& mesh,
                     Atlas_mesh::Property_map<Atlas_mesh::Halfedge_index, Atlas_kernel::Point_2> uv,
                     const SMP::Discrete_lie_flow_atlas_report& r)
{
  const double side = 800, margin = 30, bar = 110; // bar: the colour bar and its labels
  double uv_total = 0, area_total = 0;
  std::vector<std::array<Atlas_kernel::Point_2, 3> > tri;
  std::vector<double> area3;
  for(auto f : faces(mesh)) {
    std::array<Atlas_kernel::Point_2, 3> t;
    std::array<Atlas_kernel::Point_3, 3> p;
    std::size_t k = 0;
    for(auto h : halfedges_around_face(halfedge(f, mesh), mesh)) { t[k] = uv[h]; p[k] = mesh.point(target(h, mesh)); ++k; }
    tri.push_back(t);
    area3.push_back(std::sqrt(CGAL::squared_area(p[0], p[1], p[2])));
    uv_total += CGAL::area(t[0], t[1], t[2]);
    area_total += area3.back();
  }
  char d_area_text[32];
  std::snprintf(d_area_text, sizeof d_area_text, "%.4f", r.metrics.d_area);
  std::ostringstream svg;
  write_svg_header(svg, side + 2 * margin + bar, side + 2 * margin,
                   "dlf atlas " + a.input + ": " + std::to_string(r.charts) + " charts, D_area " + d_area_text +
                   ", uv area over share");
  svg << "<rect x=\"" << margin << "\" y=\"" << margin << "\" width=\"" << side << "\" height=\"" << side
      << "\" fill=\"none\" stroke=\"#888\"/>\n";
  for(std::size_t f = 0; f < tri.size(); ++f) {
    const double ratio = (CGAL::area(tri[f][0], tri[f][1], tri[f][2]) / uv_total) / (area3[f] / area_total);
    svg << "<polygon points=\"";
    for(int k = 0; k < 3; ++k)
      svg << (k ? " " : "") << margin + side * tri[f][std::size_t(k)].x() << ',' << margin + side * (1 - tri[f][std::size_t(k)].y());
    svg << "\" fill=\"" << colour_of_log_ratio(std::log(ratio)) << "\"/>\n";
  }
  write_colour_bar(svg, side + 2 * margin, margin, side, false, false);
  svg << "</svg>\n";
  std::ofstream out(a.svg);
  if(!(out << svg.str())) throw Cli_error("atlas: cannot write " + a.svg);
}

// --report and --csv: the input, its repairs, the library's report, the
// command's own seconds.
void write_atlas_report(const Atlas_args& a, std::size_t file_vertices, std::size_t faces, const Repairs& rep,
                        const SMP::Discrete_lie_flow_atlas_report& r, double seconds_read, double seconds_write)
{
  nlohmann::json j;
  j["input"] = a.input;
  j["vertices_in_file"] = file_vertices;
  j["faces"] = faces;
  j["repairs"] = { { "polygons_triangulated", rep.polygons_triangulated },
                   { "nonmanifold_vertices_added", rep.nonmanifold_vertices_added },
                   { "degenerate_faces_dropped", rep.degenerate_faces_dropped },
                   { "isolated_vertices", rep.isolated_vertices },
                   { "duplicate_vertices_merged", rep.duplicate_vertices_merged } };
  const nlohmann::ordered_json atlas = atlas_report_json(r);
  for(const auto& item : atlas.items()) j[item.key()] = item.value();
  j["seconds_read"] = seconds_read;
  j["seconds_write"] = seconds_write;
  if(!a.report.empty()) {
    std::ofstream out(a.report);
    if(!(out << j.dump(2) << "\n")) throw Cli_error("atlas: cannot write " + a.report);
  }
  if(!a.csv.empty()) {
    std::ofstream out(a.csv);
    write_csv_report(out, nlohmann::ordered_json::parse(j.dump()));
    if(!out) throw Cli_error("atlas: cannot write " + a.csv);
  }
}

} // namespace

int atlas_command(const std::vector<std::string>& args)
{
  const Atlas_args a = parse(args);
  Repairs rep;
  std::size_t file_vertices = 0;
  auto t0 = std::chrono::steady_clock::now();
  Atlas_mesh mesh = read_and_repair(a.input, rep, file_vertices, a.quiet, a.merge_duplicates);
  const double seconds_read = seconds_since(t0);
  auto uv = mesh.add_property_map<Atlas_mesh::Halfedge_index, Atlas_kernel::Point_2>("h:uv").first;
  const SMP::Discrete_lie_flow_atlas_report r = run_atlas(a, mesh, uv);
  t0 = std::chrono::steady_clock::now();
  std::ostringstream comment;
  comment << "dlf atlas " << a.input << ": " << r.charts << " charts, packing efficiency " << r.packing_efficiency
          << ", D_area " << r.metrics.d_area;
  write_atlas_meshes(a, atlas_obj(mesh, uv), comment.str());
  const double seconds_write = seconds_since(t0);
  if(!a.svg.empty()) write_atlas_svg(a, mesh, uv, r);
  if(!a.report.empty() || !a.csv.empty())
    write_atlas_report(a, file_vertices, num_faces(mesh), rep, r, seconds_read, seconds_write);
  if(!a.quiet)
    std::cerr << "dlf: atlas: " << r.charts << " charts, seam " << r.seam_length << ", packing efficiency "
              << r.packing_efficiency << ", D_area " << r.metrics.d_area << ", " << r.inverted_faces + r.degenerate_faces
              << " inverted or degenerate, " << r.overlapping_chart_pairs << " overlapping charts, " << r.seconds << " s\n";
  if(r.converged()) return EXIT_OK;
  std::cerr << "dlf: warning: " << r.message << "\n";
  return EXIT_NOT_CONVERGED;
}

} // namespace dlf_cli
