// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// `dlf info`: topology and degeneracy report of any mesh file, and which
// command fits it. Reads the file as a polygon soup, so that what `dlf disk`
// refuses (non-manifold, polygons, unreferenced vertices) is described
// rather than refused.

#include "cli_util.h"
#include "arguments.h"
#include "cli_error.h"
#include "commands.h"
#include "mesh_info.h"
#include "mesh_input.h"
#include "output_files.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>

#include <boost/program_options.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <numeric>
#include <sstream>

namespace dlf_cli {

namespace {

namespace po = boost::program_options;
using json = nlohmann::ordered_json;
typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
typedef Epick::Point_3 Point_3;
typedef std::vector<std::size_t> Polygon;

const char* info_help =
  "Usage: dlf info MESH [--report R.json]\n"
  "\n"
  "Reads MESH (OFF, OBJ, PLY, STL, ...) as it is and reports its topology and\n"
  "degeneracies: vertices (unreferenced, duplicate positions, non-finite; duplicates\n"
  "on the border are the two sides of a seam, fine for 'dlf disk'), faces\n"
  "(triangles or not), edges (border, non-manifold, inconsistently oriented),\n"
  "connected components, border loops (each with its length and vertex count,\n"
  "longest first: the order of 'dlf disk --outer-loop'), Euler characteristic\n"
  "and genus, non-manifold vertices, degenerate and zero-area faces, the\n"
  "smallest angle, the bounding box; and which command fits: 'dlf disk' (a\n"
  "topological disk, or a genus-0 mesh with holes), 'dlf sphere' (closed,\n"
  "genus 0), or neither, and why.\n"
  "\n"
  "Exit status: 0 when MESH was read (whatever it is), 1 otherwise.\n"
  "\n"
  "Examples:\n"
  "  dlf info face.off\n"
  "  dlf info scan.ply --report scan_info.json\n";


struct Mesh_info
{
  std::size_t vertices = 0, faces = 0, triangles = 0, unreferenced = 0, duplicate_positions = 0, non_finite = 0;
  std::size_t duplicate_positions_on_border = 0; ///< both copies on the border: the sides of a seam, legal
  std::size_t edges = 0, border_edges = 0, non_manifold_edges = 0, misoriented_edges = 0;
  std::size_t components = 0, border_loops = 0, non_manifold_vertices = 0;
  std::size_t repeated_vertex_faces = 0, zero_area_faces = 0, faces_below_1_degree = 0;
  long euler = 0;
  double min_angle_degrees = 180, area = 0;
  std::array<double, 3> lo{ { 0, 0, 0 } }, hi{ { 0, 0, 0 } };
  bool manifold() const { return non_manifold_edges == 0 && non_manifold_vertices == 0; }
  bool orientable() const { return misoriented_edges == 0; }
  bool usable() const
  {
    return triangles == faces && unreferenced == 0 && non_finite == 0 && repeated_vertex_faces == 0 && manifold();
  }
  /// Genus of a connected orientable manifold: χ = 2 − 2g − b; −1 if unknown.
  long genus() const
  {
    if(components != 1 || !manifold() || triangles != faces) return -1;
    const long twice = 2 - euler - long(border_loops);
    return twice >= 0 && twice % 2 == 0 ? twice / 2 : -1;
  }
};

// The smallest angle (radians) of a triangle; π for a flat one with a repeated point.
double min_angle(const Point_3& a, const Point_3& b, const Point_3& c)
{
  const Point_3* p[3] = { &a, &b, &c };
  double m = M_PI;
  for(int k = 0; k < 3; ++k) {
    const Epick::Vector_3 u = *p[(k + 1) % 3] - *p[k], v = *p[(k + 2) % 3] - *p[k];
    const double nu = std::sqrt(u.squared_length()), nv = std::sqrt(v.squared_length());
    if(nu == 0 || nv == 0) return 0;
    m = std::min(m, std::acos(std::max(-1., std::min(1., (u * v) / (nu * nv)))));
  }
  return m;
}

Mesh_info analyse(const std::vector<Point_3>& points, const std::vector<Polygon>& polygons)
{
  Mesh_info m;
  m.vertices = points.size();
  m.faces = polygons.size();
  const std::size_t V = points.size();

  std::vector<bool> used(V, false);
  for(const Polygon& p : polygons)
    for(std::size_t i : p) used[i] = true;
  m.unreferenced = std::size_t(std::count(used.begin(), used.end(), false));
  bool first = true;
  for(std::size_t i = 0; i < V; ++i) {
    const Point_3& p = points[i];
    if(!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z())) { ++m.non_finite; continue; }
    const double c[3] = { p.x(), p.y(), p.z() };
    for(int k = 0; k < 3; ++k) {
      m.lo[std::size_t(k)] = first ? c[k] : std::min(m.lo[std::size_t(k)], c[k]);
      m.hi[std::size_t(k)] = first ? c[k] : std::max(m.hi[std::size_t(k)], c[k]);
    }
    first = false;
  }
  std::vector<std::pair<Point_3, std::size_t> > by_position;
  for(std::size_t i = 0; i < V; ++i)
    if(used[i]) by_position.emplace_back(points[i], i);
  std::sort(by_position.begin(), by_position.end());
  for(std::size_t k = 1; k < by_position.size(); ++k)
    if(by_position[k].first == by_position[k - 1].first) ++m.duplicate_positions;

  // Directed edges of every polygon, as (min, max, forward, polygon, corner).
  struct Side { std::size_t a, b; bool forward; std::size_t face, corner_a, corner_b; };
  std::vector<Side> sides;
  std::vector<std::size_t> corner_start(polygons.size() + 1, 0);
  for(std::size_t f = 0; f < polygons.size(); ++f) corner_start[f + 1] = corner_start[f] + polygons[f].size();
  Union_find components(V), fans(corner_start.back());
  for(std::size_t f = 0; f < polygons.size(); ++f) {
    const Polygon& p = polygons[f];
    const std::size_t n = p.size();
    if(n == 3) ++m.triangles;
    bool repeated = false;
    for(std::size_t k = 0; k < n; ++k) {
      const std::size_t a = p[k], b = p[(k + 1) % n];
      components.unite(a, b);
      if(a == b) { repeated = true; continue; }
      sides.push_back({ std::min(a, b), std::max(a, b), a < b, f, corner_start[f] + k, corner_start[f] + (k + 1) % n });
    }
    for(std::size_t j = 0; j < n && !repeated; ++j)
      for(std::size_t k = j + 1; k < n; ++k) repeated = repeated || p[j] == p[k];
    if(repeated) { ++m.repeated_vertex_faces; continue; }
    if(n != 3) continue;
    const Point_3 &a = points[p[0]], &b = points[p[1]], &c = points[p[2]];
    if(CGAL::collinear(a, b, c)) ++m.zero_area_faces;
    m.area += std::sqrt(CGAL::squared_area(a, b, c));
    const double angle = min_angle(a, b, c) * 180 / M_PI;
    m.min_angle_degrees = std::min(m.min_angle_degrees, angle);
    if(angle < 1) ++m.faces_below_1_degree;
  }
  for(std::size_t i = 0; i < V; ++i)
    if(used[i] && components.find(i) == i) ++m.components;

  std::sort(sides.begin(), sides.end(), [](const Side& x, const Side& y) { return x.a != y.a ? x.a < y.a : x.b < y.b; });
  // Border edges, for the loops: a graph on vertices, one component per loop
  // when the border is manifold.
  Union_find border(V);
  std::vector<bool> on_border(V, false);
  for(std::size_t k = 0; k < sides.size(); ) {
    std::size_t e = k + 1;
    while(e < sides.size() && sides[e].a == sides[k].a && sides[e].b == sides[k].b) ++e;
    ++m.edges;
    const std::size_t count = e - k;
    if(count == 1) {
      ++m.border_edges;
      border.unite(sides[k].a, sides[k].b);
      on_border[sides[k].a] = on_border[sides[k].b] = true;
    } else if(count > 2) {
      ++m.non_manifold_edges;
    } else {
      if(sides[k].forward == sides[k + 1].forward) ++m.misoriented_edges;
      // The two faces are one fan at either end: join the corners there.
      const Side &s = sides[k], &t = sides[k + 1];
      const std::size_t s_at_a = s.forward ? s.corner_a : s.corner_b, s_at_b = s.forward ? s.corner_b : s.corner_a;
      const std::size_t t_at_a = t.forward ? t.corner_a : t.corner_b, t_at_b = t.forward ? t.corner_b : t.corner_a;
      fans.unite(s_at_a, t_at_a);
      fans.unite(s_at_b, t_at_b);
    }
    k = e;
  }
  for(std::size_t i = 0; i < V; ++i)
    if(on_border[i] && border.find(i) == i) ++m.border_loops;
  // A mesh cut open along seams (as exporters write it) has its seam's
  // vertices twice, both on the border: not a defect.
  for(std::size_t k = 1; k < by_position.size(); ++k)
    if(by_position[k].first == by_position[k - 1].first && on_border[by_position[k].second] &&
       on_border[by_position[k - 1].second])
      ++m.duplicate_positions_on_border;
  m.euler = long(V - m.unreferenced) - long(m.edges) + long(m.faces);

  // A vertex whose corners form more than one fan joins separate sheets.
  std::vector<std::size_t> first_fan(V, std::size_t(-1));
  std::vector<bool> counted(V, false);
  for(std::size_t f = 0; f < polygons.size(); ++f)
    for(std::size_t k = 0; k < polygons[f].size(); ++k) {
      const std::size_t v = polygons[f][k], fan = fans.find(corner_start[f] + k);
      if(first_fan[v] == std::size_t(-1)) first_fan[v] = fan;
      else if(first_fan[v] != fan && !counted[v]) { counted[v] = true; ++m.non_manifold_vertices; }
    }
  if(m.triangles == 0) m.min_angle_degrees = 0;
  return m;
}

std::string count(std::size_t n, const std::string& one, const std::string& many)
{
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

// The command that fits, or why none does.
std::string verdict(const Mesh_info& m, std::string& reason)
{
  std::vector<std::string> problems;
  if(m.triangles != m.faces) problems.push_back(count(m.faces - m.triangles, "face", "faces") + " not a triangle (triangulate)");
  if(m.unreferenced) problems.push_back(count(m.unreferenced, "unreferenced vertex", "unreferenced vertices") + " (remove them)");
  if(m.non_finite) problems.push_back(count(m.non_finite, "vertex", "vertices") + " with non-finite coordinates");
  if(m.repeated_vertex_faces) problems.push_back(count(m.repeated_vertex_faces, "face", "faces") + " repeating a vertex");
  if(!m.manifold()) problems.push_back("not manifold (repair it)");
  if(m.zero_area_faces) problems.push_back(count(m.zero_area_faces, "zero-area face", "zero-area faces") + " (the flow refuses them)");
  if(m.components != 1) problems.push_back(count(m.components, "connected component", "connected components") + " (keep one)");
  const long g = m.genus();
  // A disk, or a disk with holes (genus 0, several loops): dlf disk fills the holes.
  const bool disk = m.components == 1 && m.border_loops >= 1 && m.euler == 2 - long(m.border_loops);
  const bool sphere = m.components == 1 && m.border_loops == 0 && m.euler == 2;
  if(problems.empty() && disk) return "dlf disk";
  if(problems.empty() && sphere) return "dlf sphere";
  if(problems.empty()) {
    if(m.border_loops == 0) problems.push_back("closed surface of genus " + std::to_string(g) + " (cut it open into a disk)");
    else problems.push_back("genus " + std::to_string(g) + " with " + count(m.border_loops, "border loop", "border loops") +
                            " (cut it into a disk)");
  }
  for(std::size_t k = 0; k < problems.size(); ++k) reason += (k ? "; " : "") + problems[k];
  return "none";
}

json info_json(const std::string& path, const Mesh_info& m, const std::vector<Border_loop>& loops, const std::string& fits,
               const std::string& reason)
{
  json j;
  j["mesh"] = path;
  j["vertices"] = m.vertices;
  j["unreferenced_vertices"] = m.unreferenced;
  j["duplicate_positions"] = m.duplicate_positions;
  j["duplicate_positions_on_border"] = m.duplicate_positions_on_border;
  j["non_finite_vertices"] = m.non_finite;
  j["faces"] = m.faces;
  j["triangles"] = m.triangles;
  j["edges"] = m.edges;
  j["border_edges"] = m.border_edges;
  j["non_manifold_edges"] = m.non_manifold_edges;
  j["inconsistently_oriented_edges"] = m.misoriented_edges;
  j["connected_components"] = m.components;
  j["border_loops"] = m.border_loops;
  json list = json::array();
  for(const Border_loop& l : loops) list.push_back({ { "length", l.length }, { "vertices", l.vertices.size() } });
  j["loops"] = list; // longest first: the order of dlf disk --outer-loop
  j["euler_characteristic"] = m.euler;
  j["genus"] = m.genus() >= 0 ? json(m.genus()) : json(nullptr);
  j["non_manifold_vertices"] = m.non_manifold_vertices;
  j["faces_repeating_a_vertex"] = m.repeated_vertex_faces;
  j["zero_area_faces"] = m.zero_area_faces;
  j["min_angle_degrees"] = m.min_angle_degrees;
  j["faces_below_1_degree"] = m.faces_below_1_degree;
  j["area"] = m.area;
  j["bounding_box"] = { { "min", m.lo }, { "max", m.hi } };
  j["fits"] = fits;
  j["reason"] = reason;
  return j;
}

void print_info(std::ostream& out, const std::string& path, const Mesh_info& m, const std::vector<Border_loop>& loops,
                const std::string& fits, const std::string& reason)
{
  const double diagonal = std::sqrt((m.hi[0] - m.lo[0]) * (m.hi[0] - m.lo[0]) + (m.hi[1] - m.lo[1]) * (m.hi[1] - m.lo[1]) +
                                    (m.hi[2] - m.lo[2]) * (m.hi[2] - m.lo[2]));
  out << std::setprecision(6) << "dlf info " << path << "\n"
      << "  vertices              " << m.vertices << " (" << m.unreferenced << " unreferenced, " << m.duplicate_positions
      << " duplicate positions"
      << (m.duplicate_positions_on_border ? " (" + std::to_string(m.duplicate_positions_on_border) + " on the border: seam sides)"
                                          : std::string())
      << ", " << m.non_finite << " non-finite)\n"
      << "  faces                 " << m.faces << " (" << m.triangles << " triangles)\n"
      << "  edges                 " << m.edges << " (" << m.border_edges << " border, " << m.non_manifold_edges
      << " non-manifold, " << m.misoriented_edges << " inconsistently oriented)\n"
      << "  connected components  " << m.components << "\n"
      << "  border loops          " << m.border_loops << (m.manifold() ? "" : " (connected sets of border edges)") << "\n";
  // Longest first: dlf disk --outer-loop K counts them in this order.
  for(std::size_t k = 0; k < loops.size() && loops.size() > 1; ++k)
    out << "    loop " << k << "              length " << loops[k].length << ", " << loops[k].vertices.size() << " vertices"
        << (k == 0 ? " (the outer loop of dlf disk unless --outer-loop)" : "") << "\n";
  out      << "  Euler characteristic  " << m.euler << "\n"
      << "  genus                 " << (m.genus() >= 0 ? std::to_string(m.genus()) : std::string("n/a (not one manifold component)"))
      << "\n"
      << "  non-manifold vertices " << m.non_manifold_vertices << "\n"
      << "  degenerate faces      " << m.zero_area_faces << " zero area, " << m.repeated_vertex_faces << " repeating a vertex\n"
      << "  smallest angle        " << m.min_angle_degrees << " degrees ("
      << count(m.faces_below_1_degree, "face", "faces") << " below 1 degree)\n"
      << "  surface area          " << m.area << "\n"
      << "  bounding box          [" << m.lo[0] << ", " << m.hi[0] << "] x [" << m.lo[1] << ", " << m.hi[1] << "] x ["
      << m.lo[2] << ", " << m.hi[2] << "], diagonal " << diagonal << "\n";
  if(fits == "none") out << "  fits                  neither dlf disk nor dlf sphere: " << reason << "\n";
  else if(fits == "dlf disk" && m.border_loops > 1)
    out << "  fits                  dlf disk (a disk with " << count(m.border_loops - 1, "hole", "holes") << ": they float)\n";
  else out << "  fits                  " << fits << (fits == "dlf disk" ? " (a topological disk)" : " (closed, genus 0)") << "\n";
}

} // namespace

nlohmann::ordered_json mesh_info(const std::string& name, const std::vector<Vec3>& xyz,
                                 const std::vector<std::vector<std::size_t> >& polygons)
{
  std::vector<Point_3> points;
  for(const Vec3& p : xyz) points.emplace_back(p[0], p[1], p[2]);
  const Mesh_info m = analyse(points, polygons);
  std::string reason;
  const std::string fits = verdict(m, reason);
  std::vector<Border_loop> loops;
  if(m.usable()) {
    std::vector<Triangle> triangles;
    for(const Polygon& p : polygons) triangles.push_back({ { int(p[0]), int(p[1]), int(p[2]) } });
    loops = border_loops(xyz, triangles);
  }
  return info_json(name, m, loops, fits, reason);
}

int info_command(const std::vector<std::string>& args)
{
  std::string report;
  po::options_description visible("Options");
  visible.add_options()
    ("help,h", "show this help")
    ("report", po::value<std::string>(&report)->value_name("R.json"), "write the same as JSON")
    ("quiet,q", "print nothing (with --report)");
  const po::variables_map vm = parse_command_line("info", args, visible, "mesh");
  if(vm.count("help")) {
    std::cout << info_help << "\n" << visible;
    return EXIT_OK;
  }
  const std::vector<std::string> meshes = positional_arguments(vm, "mesh");
  if(meshes.size() != 1) throw Cli_error("dlf info needs exactly one MESH (see 'dlf info --help')");
  const std::string& path = meshes[0];
  Output_files outputs;
  if(!report.empty()) outputs.declare(report, "--report");

  if(!std::ifstream(path)) throw Cli_error("'" + path + "': cannot open (no such file, or not readable)");
  std::vector<Point_3> points;
  std::vector<Polygon> polygons;
  if(!CGAL::IO::read_polygon_soup(path, points, polygons))
    throw Cli_error("'" + path + "': cannot read as a mesh (CGAL reads .off, .obj, .ply, .stl, .ts, .vtp)");
  for(std::size_t f = 0; f < polygons.size(); ++f)
    for(std::size_t i : polygons[f])
      if(i >= points.size())
        throw Cli_error("'" + path + "': face " + std::to_string(f) + " refers to vertex " + std::to_string(i) + " of " +
                        std::to_string(points.size()));
  if(polygons.empty()) throw Cli_error("'" + path + "': the mesh has no faces");

  const Mesh_info m = analyse(points, polygons);
  std::string reason;
  const std::string fits = verdict(m, reason);
  std::vector<Border_loop> loops;
  if(m.usable()) {
    std::vector<Vec3> xyz;
    for(const Point_3& p : points) xyz.push_back({ { p.x(), p.y(), p.z() } });
    std::vector<Triangle> triangles;
    for(const Polygon& p : polygons) triangles.push_back({ { int(p[0]), int(p[1]), int(p[2]) } });
    loops = border_loops(xyz, triangles);
  }
  if(!report.empty()) {
    const json j = info_json(path, m, loops, fits, reason);
    outputs.write(report, [&](std::ostream& o) { o << j.dump(2) << '\n'; });
  }
  outputs.commit();
  if(vm.count("quiet") == 0) {
    print_info(std::cout, path, m, loops, fits, reason);
    for(const std::string& w : outputs.committed()) std::cout << "  wrote " << w << "\n";
  }
  return EXIT_OK;
}

} // namespace dlf_cli
