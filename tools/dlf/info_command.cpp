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
  "connected components (each with its faces, border loops, Euler characteristic,\n"
  "genus and area, largest first), border loops (each with its length and vertex\n"
  "count, longest first: the order of 'dlf disk --outer-loop'), Euler\n"
  "characteristic and genus, non-manifold vertices, degenerate and zero-area\n"
  "faces, the smallest angle, the surface area (polygons too: angles about each\n"
  "polygon's normal), the bounding box; and which command fits: 'dlf disk' (a\n"
  "topological disk, or a genus-0 mesh with holes), 'dlf sphere' (closed,\n"
  "genus 0), or neither, and why; and whether 'dlf atlas' takes it (any mesh\n"
  "with finite coordinates: several components, any genus, polygons).\n"
  "\n"
  "Exit status: 0 when MESH was read (whatever it is), 1 otherwise.\n"
  "\n"
  "Examples:\n"
  "  dlf info face.off\n"
  "  dlf info scan.ply --report scan_info.json\n";


/// One connected component: its counts, and its topology where defined.
struct Component_info
{
  std::size_t vertices = 0, edges = 0, faces = 0, border_loops = 0;
  bool manifold = true, orientable = true;
  double area = 0;
  long euler() const { return long(vertices) - long(edges) + long(faces); }
  /// χ = 2 − 2g − b for a connected orientable manifold; −1 otherwise.
  long genus() const
  {
    if(!manifold || !orientable) return -1;
    const long twice = 2 - euler() - long(border_loops);
    return twice >= 0 && twice % 2 == 0 ? twice / 2 : -1;
  }
};

struct Mesh_info
{
  std::size_t vertices = 0, faces = 0, triangles = 0, unreferenced = 0, duplicate_positions = 0, non_finite = 0;
  std::size_t duplicate_positions_on_border = 0; ///< both copies on the border: the sides of a seam, legal
  std::size_t edges = 0, border_edges = 0, non_manifold_edges = 0, misoriented_edges = 0;
  std::size_t components = 0, border_loops = 0, non_manifold_vertices = 0;
  std::size_t repeated_vertex_faces = 0, zero_area_faces = 0, faces_below_1_degree = 0;
  long euler = 0;
  std::size_t measured_faces = 0; ///< faces with an area and angles (no repeated vertex)
  double min_angle_degrees = 360, area = 0;
  std::vector<Component_info> parts; ///< largest first (faces), then by smallest vertex
  std::array<double, 3> lo{ { 0, 0, 0 } }, hi{ { 0, 0, 0 } };
  bool manifold() const { return non_manifold_edges == 0 && non_manifold_vertices == 0; }
  bool orientable() const { return misoriented_edges == 0; }
  bool usable() const
  {
    return triangles == faces && unreferenced == 0 && non_finite == 0 && repeated_vertex_faces == 0 && manifold();
  }
  /// Genus of a connected orientable manifold (polygons too): χ = 2 − 2g − b; −1 if undefined.
  long genus() const { return parts.size() == 1 ? parts[0].genus() : -1; }
  /// Why the genus is undefined, for the text.
  std::string no_genus() const
  {
    if(parts.size() != 1) return "n/a (" + std::to_string(parts.size()) + " components: each below)";
    if(!parts[0].manifold) return "n/a (not manifold)";
    if(!parts[0].orientable) return "n/a (not orientable)";
    return "n/a (Euler characteristic and border loops disagree with any genus)";
  }
  bool has_angles() const { return measured_faces > 0; }
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

// Area, smallest interior angle (degrees) and zero area of a polygon
// without a repeated vertex. The area is the norm of the vector area (the
// area of a planar polygon, convex or not); each corner's angle is measured
// around that normal, so a reflex corner counts as more than 180 degrees.
// Triangles use the exact collinearity test and the plain angles.
struct Polygon_measure { double area = 0, min_angle = 360; bool zero_area = false; };

Polygon_measure measure_polygon(const std::vector<Point_3>& points, const Polygon& p)
{
  Polygon_measure r;
  const std::size_t n = p.size();
  const Point_3& o = points[p[0]];
  if(n == 3) {
    const Point_3 &a = points[p[0]], &b = points[p[1]], &c = points[p[2]];
    r.zero_area = CGAL::collinear(a, b, c);
    r.area = std::sqrt(CGAL::squared_area(a, b, c));
    r.min_angle = min_angle(a, b, c) * 180 / M_PI;
    return r;
  }
  Epick::Vector_3 normal(0, 0, 0);
  r.zero_area = true;
  for(std::size_t k = 1; k + 1 < n; ++k) {
    normal = normal + CGAL::cross_product(points[p[k]] - o, points[p[k + 1]] - o);
    r.zero_area = r.zero_area && CGAL::collinear(o, points[p[k]], points[p[k + 1]]);
  }
  const double twice = std::sqrt(normal.squared_length());
  r.area = twice / 2;
  for(std::size_t k = 0; k < n; ++k) {
    const Point_3& at = points[p[k]];
    const Epick::Vector_3 next = points[p[(k + 1) % n]] - at, previous = points[p[(k + n - 1) % n]] - at;
    double angle;
    if(twice > 0) { // from the next edge to the previous one, counterclockwise about the normal
      angle = std::atan2(CGAL::cross_product(next, previous) * normal / twice, next * previous);
      if(angle < 0) angle += 2 * M_PI;
    } else {
      const double nn = std::sqrt(next.squared_length()), np = std::sqrt(previous.squared_length());
      angle = nn == 0 || np == 0 ? 0 : std::acos(std::max(-1., std::min(1., (next * previous) / (nn * np))));
    }
    r.min_angle = std::min(r.min_angle, angle * 180 / M_PI);
  }
  return r;
}

// Directed edges of every polygon, as (min, max, forward, polygon, corner).
struct Side { std::size_t a, b; bool forward; std::size_t face, corner_a, corner_b; };

// Orientability: two faces across a manifold edge that run it the same
// way must be flipped relative to each other; a cycle with an odd number
// of flips (a Möbius strip) makes the component non-orientable. A
// union-find of faces that keeps each face's flip against its parent.
class Face_orientation
{
public:
  explicit Face_orientation(std::size_t faces) : m_parent(faces), m_flip(faces, 0), m_non_orientable(faces, false)
  {
    std::iota(m_parent.begin(), m_parent.end(), std::size_t(0));
  }

  /// Faces `s` and `t` across a manifold edge; `flip`: they run it the same way.
  void join(std::size_t s, std::size_t t, char flip)
  {
    char fs, ft;
    const std::size_t rs = root(s, fs), rt = root(t, ft);
    if(rs != rt) {
      m_parent[rs] = rt;
      m_flip[rs] = char(fs ^ ft ^ flip);
      if(m_non_orientable[rs]) m_non_orientable[rt] = true;
    } else if((fs ^ ft) != flip) {
      m_non_orientable[rs] = true;
    }
  }

  bool orientable(std::size_t f)
  {
    char flip;
    return !m_non_orientable[root(f, flip)];
  }

private:
  std::size_t root(std::size_t f, char& flip) // with path compression, the flips kept
  {
    std::size_t r = f;
    flip = 0;
    while(m_parent[r] != r) { flip ^= m_flip[r]; r = m_parent[r]; }
    char to_root = flip;
    while(m_parent[f] != r && f != r) {
      const std::size_t up = m_parent[f];
      const char next = char(to_root ^ m_flip[f]);
      m_parent[f] = r;
      m_flip[f] = to_root;
      f = up;
      to_root = next;
    }
    return r;
  }

  std::vector<std::size_t> m_parent;
  std::vector<char> m_flip;
  std::vector<bool> m_non_orientable; ///< per root
};

// What the passes of analyse() over vertices, faces and edges hand on.
struct Mesh_survey
{
  Mesh_survey(std::size_t vertices, const std::vector<Polygon>& polygons)
    : used(vertices, false), corner_start(polygons.size() + 1, 0), face_area(polygons.size(), 0),
      components(vertices), fans(corners(polygons)), border(vertices), on_border(vertices, false),
      non_manifold_vertex(vertices, false), orientation(polygons.size())
  {
    for(std::size_t f = 0; f < polygons.size(); ++f) corner_start[f + 1] = corner_start[f] + polygons[f].size();
  }
  static std::size_t corners(const std::vector<Polygon>& polygons)
  {
    std::size_t n = 0;
    for(const Polygon& p : polygons) n += p.size();
    return n;
  }

  std::vector<bool> used;                                  ///< per vertex: a face refers to it
  std::vector<std::pair<Point_3, std::size_t> > by_position; ///< the used vertices, sorted by position
  std::vector<Side> sides;                                 ///< sorted by (a, b)
  std::vector<std::size_t> corner_start;                   ///< face f's corners from corner_start[f]
  std::vector<double> face_area;
  Union_find components;                                   ///< vertices joined along the polygons' edges
  Union_find fans;                                         ///< corners joined across manifold edges
  // Border edges, for the loops: a graph on vertices, one component per
  // loop when the border is manifold.
  Union_find border;
  std::vector<bool> on_border, non_manifold_vertex;
  Face_orientation orientation;
};

// Unreferenced and non-finite vertices, the bounding box, duplicate positions.
void survey_vertices(const std::vector<Point_3>& points, const std::vector<Polygon>& polygons, Mesh_survey& survey,
                     Mesh_info& m)
{
  const std::size_t V = points.size();
  for(const Polygon& p : polygons)
    for(std::size_t i : p) survey.used[i] = true;
  m.unreferenced = std::size_t(std::count(survey.used.begin(), survey.used.end(), false));
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
  std::vector<std::pair<Point_3, std::size_t> >& by_position = survey.by_position;
  for(std::size_t i = 0; i < V; ++i)
    if(survey.used[i]) by_position.emplace_back(points[i], i);
  std::sort(by_position.begin(), by_position.end());
  for(std::size_t k = 1; k < by_position.size(); ++k)
    if(by_position[k].first == by_position[k - 1].first) ++m.duplicate_positions;
}

// Triangles, faces repeating a vertex, areas and angles, connected
// components; the polygons' sides, sorted.
void survey_faces(const std::vector<Point_3>& points, const std::vector<Polygon>& polygons, Mesh_survey& survey,
                  Mesh_info& m)
{
  for(std::size_t f = 0; f < polygons.size(); ++f) {
    const Polygon& p = polygons[f];
    const std::size_t n = p.size(), first = survey.corner_start[f];
    if(n == 3) ++m.triangles;
    bool repeated = false;
    for(std::size_t k = 0; k < n; ++k) {
      const std::size_t a = p[k], b = p[(k + 1) % n];
      survey.components.unite(a, b);
      if(a == b) { repeated = true; continue; }
      survey.sides.push_back({ std::min(a, b), std::max(a, b), a < b, f, first + k, first + (k + 1) % n });
    }
    for(std::size_t j = 0; j < n && !repeated; ++j)
      for(std::size_t k = j + 1; k < n; ++k) repeated = repeated || p[j] == p[k];
    if(repeated) { ++m.repeated_vertex_faces; continue; }
    if(n < 3) continue;
    const Polygon_measure q = measure_polygon(points, p);
    ++m.measured_faces;
    if(q.zero_area) ++m.zero_area_faces;
    survey.face_area[f] = q.area;
    m.area += q.area;
    m.min_angle_degrees = std::min(m.min_angle_degrees, q.min_angle);
    if(q.min_angle < 1) ++m.faces_below_1_degree;
  }
  for(std::size_t i = 0; i < points.size(); ++i)
    if(survey.used[i] && survey.components.find(i) == i) ++m.components;
  std::sort(survey.sides.begin(), survey.sides.end(),
            [](const Side& x, const Side& y) { return x.a != y.a ? x.a < y.a : x.b < y.b; });
}

// The end of the run of sides from `k` that are one edge.
std::size_t edge_end(const std::vector<Side>& sides, std::size_t k)
{
  std::size_t e = k + 1;
  while(e < sides.size() && sides[e].a == sides[k].a && sides[e].b == sides[k].b) ++e;
  return e;
}

// Edges (border, non-manifold, inconsistently oriented), border loops, the
// faces' orientation and the fans of corners around each vertex; the
// duplicate positions on the border, the Euler characteristic.
void survey_edges(std::size_t V, Mesh_survey& survey, Mesh_info& m)
{
  const std::vector<Side>& sides = survey.sides;
  for(std::size_t k = 0; k < sides.size(); ) {
    const std::size_t e = edge_end(sides, k);
    ++m.edges;
    const std::size_t count = e - k;
    if(count == 1) {
      ++m.border_edges;
      survey.border.unite(sides[k].a, sides[k].b);
      survey.on_border[sides[k].a] = survey.on_border[sides[k].b] = true;
    } else if(count > 2) {
      ++m.non_manifold_edges;
      survey.non_manifold_vertex[sides[k].a] = survey.non_manifold_vertex[sides[k].b] = true;
    } else {
      const Side &s = sides[k], &t = sides[k + 1];
      if(s.forward == t.forward) ++m.misoriented_edges;
      survey.orientation.join(s.face, t.face, s.forward == t.forward ? 1 : 0);
      // The two faces are one fan at either end: join the corners there.
      const std::size_t s_at_a = s.forward ? s.corner_a : s.corner_b, s_at_b = s.forward ? s.corner_b : s.corner_a;
      const std::size_t t_at_a = t.forward ? t.corner_a : t.corner_b, t_at_b = t.forward ? t.corner_b : t.corner_a;
      survey.fans.unite(s_at_a, t_at_a);
      survey.fans.unite(s_at_b, t_at_b);
    }
    k = e;
  }
  for(std::size_t i = 0; i < V; ++i)
    if(survey.on_border[i] && survey.border.find(i) == i) ++m.border_loops;
  // A mesh cut open along seams (as exporters write it) has its seam's
  // vertices twice, both on the border: not a defect.
  const std::vector<std::pair<Point_3, std::size_t> >& by_position = survey.by_position;
  for(std::size_t k = 1; k < by_position.size(); ++k)
    if(by_position[k].first == by_position[k - 1].first && survey.on_border[by_position[k].second] &&
       survey.on_border[by_position[k - 1].second])
      ++m.duplicate_positions_on_border;
  m.euler = long(V - m.unreferenced) - long(m.edges) + long(m.faces);
}

// A vertex whose corners form more than one fan joins separate sheets.
void count_non_manifold_vertices(const std::vector<Polygon>& polygons, Mesh_survey& survey, Mesh_info& m)
{
  const std::size_t V = survey.used.size();
  std::vector<std::size_t> first_fan(V, std::size_t(-1));
  std::vector<bool> counted(V, false);
  for(std::size_t f = 0; f < polygons.size(); ++f)
    for(std::size_t k = 0; k < polygons[f].size(); ++k) {
      const std::size_t v = polygons[f][k], fan = survey.fans.find(survey.corner_start[f] + k);
      if(first_fan[v] == std::size_t(-1)) first_fan[v] = fan;
      else if(first_fan[v] != fan && !counted[v]) { counted[v] = true; ++m.non_manifold_vertices; }
    }
  for(std::size_t v = 0; v < V; ++v)
    if(counted[v]) survey.non_manifold_vertex[v] = true;
}

// Per component (by the union-find of its vertices): counts, border
// loops, manifold and orientable; largest first, then by smallest vertex.
void list_components(const std::vector<Polygon>& polygons, Mesh_survey& survey, Mesh_info& m)
{
  const std::size_t V = survey.used.size();
  std::vector<std::size_t> part_of(V, std::size_t(-1));
  for(std::size_t i = 0; i < V; ++i)
    if(survey.used[i] && survey.components.find(i) == i) { part_of[i] = m.parts.size(); m.parts.emplace_back(); }
  auto part = [&](std::size_t v) -> Component_info& { return m.parts[part_of[survey.components.find(v)]]; };
  std::vector<std::size_t> smallest_vertex(m.parts.size(), V);
  for(std::size_t i = 0; i < V; ++i) {
    if(!survey.used[i]) continue;
    const std::size_t c = part_of[survey.components.find(i)];
    Component_info& component = m.parts[c];
    ++component.vertices;
    smallest_vertex[c] = std::min(smallest_vertex[c], i);
    if(survey.non_manifold_vertex[i]) component.manifold = false;
    if(survey.on_border[i] && survey.border.find(i) == i) ++component.border_loops;
  }
  for(std::size_t k = 0; k < survey.sides.size(); k = edge_end(survey.sides, k)) ++part(survey.sides[k].a).edges;
  for(std::size_t f = 0; f < polygons.size(); ++f) {
    if(polygons[f].empty()) continue;
    Component_info& component = part(polygons[f][0]);
    ++component.faces;
    component.area += survey.face_area[f];
    if(!survey.orientation.orientable(f)) component.orientable = false;
  }
  // A stable order for text and JSON.
  std::vector<std::size_t> order(m.parts.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) {
    return m.parts[x].faces != m.parts[y].faces ? m.parts[x].faces > m.parts[y].faces : smallest_vertex[x] < smallest_vertex[y];
  });
  std::vector<Component_info> sorted;
  for(std::size_t c : order) sorted.push_back(m.parts[c]);
  m.parts.swap(sorted);
}

Mesh_info analyse(const std::vector<Point_3>& points, const std::vector<Polygon>& polygons)
{
  Mesh_info m;
  m.vertices = points.size();
  m.faces = polygons.size();
  Mesh_survey survey(points.size(), polygons);
  survey_vertices(points, polygons, survey, m);
  survey_faces(points, polygons, survey, m);
  survey_edges(points.size(), survey, m);
  count_non_manifold_vertices(polygons, survey, m);
  list_components(polygons, survey, m);
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
    const std::string genus = g >= 0 ? "genus " + std::to_string(g) : "Euler characteristic " + std::to_string(m.euler);
    if(m.border_loops == 0) problems.push_back("closed surface of " + genus + " (cut it open into a disk)");
    else problems.push_back(genus + " with " + count(m.border_loops, "border loop", "border loops") + " (cut it into a disk)");
  }
  for(std::size_t k = 0; k < problems.size(); ++k) reason += (k ? "; " : "") + problems[k];
  return "none";
}

// Whether `dlf atlas` takes the mesh, and what it does to it first: it
// triangulates polygons, splits non-manifold vertices, drops zero-area and
// repeated-vertex faces, cuts closed and higher-genus components into disks.
bool atlas_fits(const Mesh_info& m, std::string& note)
{
  if(m.non_finite) { note = count(m.non_finite, "vertex", "vertices") + " with non-finite coordinates"; return false; }
  if(m.measured_faces == m.zero_area_faces) { note = "every face has zero area"; return false; }
  std::vector<std::string> what;
  if(m.components > 1) what.push_back("each of the " + std::to_string(m.components) + " components");
  if(m.triangles != m.faces) what.push_back("polygons triangulated");
  if(!m.manifold()) what.push_back("non-manifold vertices split");
  if(m.zero_area_faces + m.repeated_vertex_faces) what.push_back("degenerate faces dropped");
  bool cut = false;
  for(const Component_info& c : m.parts) cut = cut || c.genus() > 0 || c.border_loops == 0;
  if(cut) what.push_back("closed or higher-genus parts cut into disks");
  for(std::size_t k = 0; k < what.size(); ++k) note += (k ? ", " : "") + what[k];
  if(note.empty()) note = "as it is";
  return true;
}

json genus_json(long g) { return g >= 0 ? json(g) : json(nullptr); }

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
  json parts = json::array(); // largest first
  for(const Component_info& c : m.parts)
    parts.push_back({ { "faces", c.faces }, { "vertices", c.vertices }, { "edges", c.edges },
                      { "border_loops", c.border_loops }, { "euler_characteristic", c.euler() },
                      { "genus", genus_json(c.genus()) }, { "manifold", c.manifold }, { "orientable", c.orientable },
                      { "area", c.area } });
  j["components"] = parts;
  j["border_loops"] = m.border_loops;
  json list = json::array();
  for(const Border_loop& l : loops) list.push_back({ { "length", l.length }, { "vertices", l.vertices.size() } });
  j["loops"] = list; // longest first: the order of dlf disk --outer-loop
  j["euler_characteristic"] = m.euler;
  j["genus"] = genus_json(m.genus());
  j["non_manifold_vertices"] = m.non_manifold_vertices;
  j["faces_repeating_a_vertex"] = m.repeated_vertex_faces;
  j["zero_area_faces"] = m.zero_area_faces;
  // Polygons too: interior angles about each polygon's normal.
  j["min_angle_degrees"] = m.has_angles() ? json(m.min_angle_degrees) : json(nullptr);
  j["faces_below_1_degree"] = m.faces_below_1_degree;
  j["area"] = m.area;
  j["bounding_box"] = { { "min", m.lo }, { "max", m.hi } };
  j["fits"] = fits;
  j["reason"] = reason;
  std::string note;
  j["atlas_fits"] = atlas_fits(m, note);
  j["atlas_note"] = note;
  return j;
}

/// Components listed one per line in the text (the report lists all).
constexpr std::size_t listed_components = 10;

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
      << "  connected components  " << m.components << "\n";
  // Largest first; the genus where the component is an orientable manifold.
  for(std::size_t k = 0; k < m.parts.size() && m.parts.size() > 1 && k < listed_components; ++k) {
    const Component_info& c = m.parts[k];
    out << "    component " << std::left << std::setw(8) << k << std::right << " " << count(c.faces, "face", "faces") << ", "
        << count(c.vertices, "vertex", "vertices") << ", " << count(c.border_loops, "border loop", "border loops") << ", Euler characteristic " << c.euler() << ", genus "
        << (c.genus() >= 0 ? std::to_string(c.genus()) : std::string(!c.manifold ? "n/a (not manifold)"
                                                                     : !c.orientable ? "n/a (not orientable)" : "n/a"))
        << ", area " << c.area << "\n";
  }
  if(m.parts.size() > listed_components)
    out << "    ... and " << m.parts.size() - listed_components << " more (--report lists every component)\n";
  out << "  border loops          " << m.border_loops << (m.manifold() ? "" : " (connected sets of border edges)") << "\n";
  // Longest first: dlf disk --outer-loop K counts them in this order.
  for(std::size_t k = 0; k < loops.size() && loops.size() > 1; ++k)
    out << "    loop " << k << "              length " << loops[k].length << ", " << loops[k].vertices.size() << " vertices"
        << (k == 0 ? " (the outer loop of dlf disk unless --outer-loop)" : "") << "\n";
  out << "  Euler characteristic  " << m.euler << "\n"
      << "  genus                 " << (m.genus() >= 0 ? std::to_string(m.genus()) : m.no_genus()) << "\n"
      << "  non-manifold vertices " << m.non_manifold_vertices << "\n"
      << "  degenerate faces      " << m.zero_area_faces << " zero area, " << m.repeated_vertex_faces << " repeating a vertex\n"
      << "  smallest angle        ";
  if(m.has_angles())
    out << m.min_angle_degrees << " degrees (" << count(m.faces_below_1_degree, "face", "faces") << " below 1 degree)\n";
  else
    out << "n/a (every face repeats a vertex)\n";
  out << "  surface area          " << m.area << "\n"
      << "  bounding box          [" << m.lo[0] << ", " << m.hi[0] << "] x [" << m.lo[1] << ", " << m.hi[1] << "] x ["
      << m.lo[2] << ", " << m.hi[2] << "], diagonal " << diagonal << "\n";
  if(fits == "none") out << "  fits                  neither dlf disk nor dlf sphere: " << reason << "\n";
  else if(fits == "dlf disk" && m.border_loops > 1)
    out << "  fits                  dlf disk (a disk with " << count(m.border_loops - 1, "hole", "holes") << ": they float)\n";
  else out << "  fits                  " << fits << (fits == "dlf disk" ? " (a topological disk)" : " (closed, genus 0)") << "\n";
  std::string note;
  const bool atlas = atlas_fits(m, note);
  out << "  dlf atlas             " << (atlas ? "fits (" + note + ")" : "does not fit: " + note) << "\n";
}
// What the command says of a mesh: the analysis, the command that fits (or
// why none does) and, for a mesh the flows take, its border loops.
struct Mesh_description
{
  Mesh_info info;
  std::string fits, reason;
  std::vector<Border_loop> loops;
};

Mesh_description describe(const std::vector<Point_3>& points, const std::vector<Polygon>& polygons)
{
  Mesh_description d;
  d.info = analyse(points, polygons);
  d.fits = verdict(d.info, d.reason);
  if(d.info.usable()) {
    std::vector<Vec3> xyz;
    for(const Point_3& p : points) xyz.push_back({ { p.x(), p.y(), p.z() } });
    std::vector<Triangle> triangles;
    for(const Polygon& p : polygons) triangles.push_back({ { int(p[0]), int(p[1]), int(p[2]) } });
    d.loops = border_loops(xyz, triangles);
  }
  return d;
}

} // namespace

nlohmann::ordered_json mesh_info(const std::string& name, const std::vector<Vec3>& xyz,
                                 const std::vector<std::vector<std::size_t> >& polygons)
{
  std::vector<Point_3> points;
  for(const Vec3& p : xyz) points.emplace_back(p[0], p[1], p[2]);
  const Mesh_description d = describe(points, polygons);
  return info_json(name, d.info, d.loops, d.fits, d.reason);
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

  std::vector<Vec3> xyz;
  std::vector<Polygon> polygons;
  if(!read_polygon_soup(path, xyz, polygons))
    throw Cli_error("'" + path + "': cannot read as a mesh (CGAL reads .off, .obj, .ply, .stl, .ts, .vtp)");
  std::vector<Point_3> points;
  points.reserve(xyz.size());
  for(const Vec3& p : xyz) points.emplace_back(p[0], p[1], p[2]);
  for(std::size_t f = 0; f < polygons.size(); ++f)
    for(std::size_t i : polygons[f])
      if(i >= points.size())
        throw Cli_error("'" + path + "': face " + std::to_string(f) + " refers to vertex " + std::to_string(i) + " of " +
                        std::to_string(points.size()));
  if(polygons.empty()) throw Cli_error("'" + path + "': the mesh has no faces");

  const Mesh_description d = describe(points, polygons);
  if(!report.empty()) write_report_files(outputs, report, "", info_json(path, d.info, d.loops, d.fits, d.reason));
  outputs.commit();
  if(vm.count("quiet") == 0) {
    print_info(std::cout, path, d.info, d.loops, d.fits, d.reason);
    for(const std::string& w : outputs.committed()) std::cout << "  wrote " << w << "\n";
  }
  return EXIT_OK;
}

} // namespace dlf_cli
