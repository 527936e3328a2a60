// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "cli_util.h"
#include "density_input.h"
#include "cli_error.h"
#include "surface_mesh.h"

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_density.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_distortion.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <functional>
#include <map>
#include <set>
#include <sstream>
#include <utility>

namespace dlf_cli {

namespace {

namespace SMP = CGAL::Surface_mesh_parameterization;


std::string number(double x)
{
  std::ostringstream s;
  s << x;
  return s.str();
}

// All numbers of a plain-text file ('#' starts a comment), with their lines.
std::vector<std::pair<double, int> > read_numbers(const std::string& path)
{
  std::ifstream in(path);
  if(!in) throw Cli_error(quoted(path) + ": cannot open (no such file, or not readable)");
  std::vector<std::pair<double, int> > values;
  std::string line, token;
  for(int line_number = 1; std::getline(in, line); ++line_number) {
    std::istringstream words(line.substr(0, line.find('#')));
    while(words >> token) {
      char* end = nullptr;
      const double x = std::strtod(token.c_str(), &end);
      if(end != token.c_str() + token.size())
        throw Cli_error(quoted(path) + ": line " + std::to_string(line_number) + ": '" + token + "' is not a number");
      values.emplace_back(x, line_number);
    }
  }
  return values;
}

Density_setup read_density_file(const Indexed_mesh& mesh, const std::string& path)
{
  const std::vector<std::pair<double, int> > numbered = read_numbers(path);
  std::vector<double> values;
  for(const std::pair<double, int>& v : numbered) values.push_back(v.first);
  return density_of_values(mesh, values, [&](std::size_t k) {
    return quoted(path) + (k < numbered.size() ? ": line " + std::to_string(numbered[k].second) : std::string());
  });
}

std::vector<long> read_indices(std::istream& in, const std::string& path, int line_number)
{
  std::string line;
  std::getline(in, line);
  // An index too large for a long is refused by the range checks of read_selection().
  return selection_indices(line, path, line_number, "an index", false);
}

std::vector<int> ball_faces(const Surface_mesh& sm, const std::array<double, 4>& ball)
{
  std::vector<int> out;
  for(face_descriptor f : SMP::faces_in_ball(sm, Kernel::Point_3(ball[0], ball[1], ball[2]), ball[3]))
    out.push_back(int(f.idx()));
  return out;
}

} // namespace

std::vector<int> read_selection(const std::string& path, const Indexed_mesh& mesh)
{
  std::ifstream in(path);
  if(!in) throw Cli_error(quoted(path) + ": cannot open (no such file, or not readable)");
  const std::vector<long> vertex_line = read_indices(in, path, 1), face_line = read_indices(in, path, 2);
  std::set<int> faces;
  for(long f : face_line) {
    if(std::size_t(f) >= mesh.faces.size())
      throw Cli_error(quoted(path) + ": face " + std::to_string(f) + " does not exist (the mesh has " +
                      std::to_string(mesh.faces.size()) + " faces)");
    faces.insert(int(f));
  }
  if(face_line.empty()) {
    std::vector<bool> selected(mesh.xyz.size(), false);
    for(long v : vertex_line) {
      if(std::size_t(v) >= mesh.xyz.size())
        throw Cli_error(quoted(path) + ": vertex " + std::to_string(v) + " does not exist (the mesh has " +
                        std::to_string(mesh.xyz.size()) + " vertices)");
      selected[std::size_t(v)] = true;
    }
    for(std::size_t f = 0; f < mesh.faces.size(); ++f) {
      const Triangle& t = mesh.faces[f];
      if(selected[std::size_t(t[0])] && selected[std::size_t(t[1])] && selected[std::size_t(t[2])]) faces.insert(int(f));
    }
  }
  if(faces.empty())
    throw Cli_error(quoted(path) + ": selects no face (its face line is empty, and no face has its 3 vertices on its "
                    "vertex line)");
  return std::vector<int>(faces.begin(), faces.end());
}

Density_setup density_of_values(const Indexed_mesh& mesh, const std::vector<double>& values,
                                const std::function<std::string(std::size_t)>& where)
{
  const std::size_t F = mesh.faces.size(), V = mesh.xyz.size();
  Density_setup d;
  // A disk has about twice as many faces as vertices; if the counts agree, faces win.
  if(values.size() == F) d.source = "face";
  else if(values.size() == V) d.source = "vertex";
  else
    throw Cli_error(where(values.size()) + ": " + std::to_string(values.size()) + " values; expected " + std::to_string(F) +
                    " (one per face) or " + std::to_string(V) + " (one per vertex)");
  for(std::size_t k = 0; k < values.size(); ++k)
    if(!(values[k] > 0) || !std::isfinite(values[k]))
      throw Cli_error(where(k) + ": the density of " + d.source + " " + std::to_string(k) + " is " + number(values[k]) +
                      " (densities must be positive and finite)");
  d.face_density.resize(F);
  for(std::size_t f = 0; f < F; ++f) {
    const Triangle& t = mesh.faces[f];
    d.face_density[f] = d.source == "face" ? values[f]
                      : (values[std::size_t(t[0])] + values[std::size_t(t[1])] + values[std::size_t(t[2])]) / 3;
  }
  return d;
}

Density_setup make_density(const Indexed_mesh& mesh, const Disk_settings& s)
{
  if(!s.density_file.empty()) return read_density_file(mesh, s.density_file);
  Density_setup d;
  d.source = "none";
  if(s.regions.empty()) return d;
  d.source = "regions";
  Surface_mesh sm;
  build_surface_mesh(mesh, sm);
  auto rho = sm.add_property_map<face_descriptor, double>("f:dlf_density", 1.).first;
  auto rho_k = sm.add_property_map<face_descriptor, double>("f:dlf_region_density", 1.).first;
  for(const Region_option& r : s.regions) {
    Density_region region;
    region.name = r.name();
    region.factor = r.factor;
    region.faces = !r.faces.empty()                 ? r.faces
                 : r.selection_file.empty()         ? ball_faces(sm, r.ball)
                                                    : read_selection(r.selection_file, mesh);
    if(region.faces.empty())
      throw Cli_error("--" + region.name + ": no face has its centroid in this ball");
    std::vector<face_descriptor> fs;
    for(int f : region.faces) fs.push_back(face_descriptor(f));
    SMP::set_region_density(sm, fs, r.factor, rho_k, s.band);
    for(face_descriptor f : faces(sm)) put(rho, f, get(rho, f) * get(rho_k, f));
    d.regions.push_back(region);
  }
  for(face_descriptor f : faces(sm)) d.face_density.push_back(get(rho, f));
  for(Density_region& region : d.regions) {
    double in = 0, all = 0, area_in = 0, area_all = 0;
    std::vector<bool> member(mesh.faces.size(), false);
    for(int f : region.faces) member[std::size_t(f)] = true;
    for(std::size_t f = 0; f < mesh.faces.size(); ++f) {
      const Triangle& t = mesh.faces[f];
      const double area = SMP::discrete_lie_flow_triangle_area(mesh.xyz[t[0]], mesh.xyz[t[1]], mesh.xyz[t[2]]);
      all += d.face_density[f] * area;
      area_all += area;
      if(member[f]) {
        in += d.face_density[f] * area;
        area_in += area;
      }
    }
    region.prescribed = in / all;
    region.surface = area_in / area_all;
    region.mean_density = in / area_in;
  }
  return d;
}

void measure_regions(const Indexed_mesh& mesh, const std::vector<Vec2>& uv, Density_setup& setup)
{
  if(setup.regions.empty()) return;
  Surface_mesh sm;
  build_surface_mesh(mesh, sm);
  auto uvmap = sm.add_property_map<vertex_descriptor, Kernel::Point_2>("v:dlf_uv").first;
  auto rho = sm.add_property_map<face_descriptor, double>("f:dlf_density", 1.).first;
  for(vertex_descriptor v : vertices(sm)) put(uvmap, v, Kernel::Point_2(uv[v.idx()][0], uv[v.idx()][1]));
  for(face_descriptor f : faces(sm)) put(rho, f, setup.face_density[f.idx()]);
  for(Density_region& region : setup.regions) {
    std::vector<face_descriptor> fs;
    for(int f : region.faces) fs.push_back(face_descriptor(f));
    const std::pair<double, double> shares = SMP::region_area_fractions(sm, fs, uvmap, rho);
    region.achieved = shares.first;
    region.prescribed = shares.second;
  }
}

nlohmann::ordered_json regions_json(const Density_setup& d, bool measured)
{
  using json = nlohmann::ordered_json;
  json regions = json::array();
  for(const Density_region& r : d.regions) {
    json j;
    j["name"] = r.name;
    j["factor"] = r.factor;
    j["faces"] = r.faces.size();
    j["surface_fraction"] = r.surface;
    j["prescribed_fraction"] = r.prescribed;
    j["achieved_fraction"] = measured ? json(r.achieved) : json(nullptr);
    j["relative_error"] = measured ? json(r.relative_error()) : json(nullptr);
    j["reached"] = measured ? json(std::abs(r.relative_error()) <= region_share_tolerance) : json(nullptr);
    j["prescribed_magnification"] = r.mean_density;
    j["magnification"] = measured ? json(r.magnification()) : json(nullptr);
    regions.push_back(j);
  }
  return regions;
}

void print_regions(std::ostream& out, const Density_setup& d, const std::string& domain, bool measured)
{
  const std::streamsize precision = out.precision();
  for(const Density_region& r : d.regions) {
    out << std::setprecision(5) << "  region " << r.name << ": factor " << r.factor << ", " << r.faces.size()
        << " faces, " << r.surface << " of the surface; share of the " << domain << " " << r.prescribed << " prescribed";
    if(measured)
      out << ", " << r.achieved << " achieved (" << std::showpos << std::setprecision(2) << 100 * r.relative_error()
          << std::noshowpos << "%); magnification " << std::setprecision(4) << r.magnification() << " (prescribed "
          << r.mean_density << ")";
    out << "\n";
  }
  out.precision(precision);
}

std::vector<std::array<int, 2> > region_outline(const Indexed_mesh& mesh, const std::vector<int>& faces)
{
  std::map<std::pair<int, int>, int> sides;
  for(int f : faces)
    for(int k = 0; k < 3; ++k) {
      const int a = mesh.faces[std::size_t(f)][k], b = mesh.faces[std::size_t(f)][(k + 1) % 3];
      ++sides[std::make_pair((std::min)(a, b), (std::max)(a, b))];
    }
  std::vector<std::array<int, 2> > out;
  for(const auto& e : sides)
    if(e.second == 1) out.push_back({{ e.first.first, e.first.second }});
  return out;
}

} // namespace dlf_cli
