// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "obj_io.h"
#include "cli_error.h"
#include "text_buffer.h"

#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace dlf_cli {

void write_obj_vertices(Text_buffer& text, const std::vector<Vec3>& xyz, const std::vector<Vec2>& uv)
{
  for(const Vec3& p : xyz) {
    text << "v ";
    text.exact(p[0]) << ' ';
    text.exact(p[1]) << ' ';
    text.exact(p[2]) << '\n';
  }
  for(const Vec2& t : uv) {
    text << "vt ";
    text.exact(t[0]) << ' ';
    text.exact(t[1]) << '\n';
  }
}

void write_obj_faces(Text_buffer& text, const std::vector<Triangle>& faces, const std::vector<Triangle>& uv_faces)
{
  for(std::size_t f = 0; f < faces.size(); ++f) {
    text << 'f';
    for(int k = 0; k < 3; ++k) text << ' ' << faces[f][k] + 1 << '/' << uv_faces[f][k] + 1;
    text << '\n';
  }
}

void write_uv_obj(std::ostream& out, const std::vector<Vec3>& xyz, const std::vector<Vec2>& uv,
                  const std::vector<Triangle>& faces, const std::vector<Triangle>& uv_faces, const std::string& comment)
{
  Text_buffer text(out);
  if(!comment.empty()) text << "# " << comment << "\n";
  write_obj_vertices(text, xyz, uv);
  write_obj_faces(text, faces, uv_faces);
}

void write_uv_obj(std::ostream& out, const std::vector<Vec3>& xyz, const std::vector<Vec2>& uv,
                  const std::vector<Triangle>& faces, const std::string& comment)
{
  write_uv_obj(out, xyz, uv, faces, faces, comment);
}

std::vector<Vec2> read_uv_obj(const std::string& path, std::size_t vertices)
{
  std::ifstream in(path);
  if(!in) throw Cli_error("'" + path + "': cannot open (no such file, or not readable)");
  std::vector<Vec2> vt, vxy;
  bool flat = true;
  std::string line;
  std::size_t line_number = 0;
  while(std::getline(in, line)) {
    ++line_number;
    std::istringstream s(line);
    std::string tag;
    if(!(s >> tag)) continue;
    if(tag != "v" && tag != "vt") continue;
    double x = 0, y = 0, z = 0;
    if(!(s >> x >> y) || !std::isfinite(x) || !std::isfinite(y))
      throw Cli_error("'" + path + "', line " + std::to_string(line_number) + ": expected two finite numbers after '" +
                      tag + "'");
    if(tag == "vt") { vt.push_back({{ x, y }}); continue; }
    if(!(s >> z) || z != 0) flat = false;
    vxy.push_back({{ x, y }});
  }
  if(vt.empty() && vxy.empty()) throw Cli_error("'" + path + "': no 'vt' or 'v' lines (not an OBJ?)");
  if(vt.empty() && !flat)
    throw Cli_error("'" + path + "': has no 'vt' lines and its 'v' are not flat (z != 0): no uv to read");
  const std::vector<Vec2>& uv = vt.empty() ? vxy : vt;
  if(uv.size() != vertices)
    throw Cli_error("'" + path + "': has " + std::to_string(uv.size()) + (vt.empty() ? " flat 'v'" : " 'vt'") +
                    " lines for " + std::to_string(vertices) + " mesh vertices (expected one uv per vertex, in order)");
  return uv;
}

Obj_map read_map_obj(const std::string& path, const Indexed_mesh& mesh)
{
  std::ifstream in(path);
  if(!in) throw Cli_error("'" + path + "': cannot open (no such file, or not readable)");
  // The faces' vertex and texture indices, 0-based; -1 where a corner has no vt.
  std::vector<Triangle> faces, uv_faces;
  std::vector<std::size_t> face_lines;
  std::size_t v_count = 0, vt_count = 0, line_number = 0;
  bool per_corner = false;
  std::string line;
  while(std::getline(in, line)) {
    ++line_number;
    std::istringstream s(line);
    std::string tag;
    if(!(s >> tag)) continue;
    if(tag == "v") ++v_count;
    if(tag == "vt") ++vt_count;
    if(tag != "f") continue;
    const std::string where = "'" + path + "', line " + std::to_string(line_number) + ": ";
    Triangle t, u;
    int k = 0;
    for(std::string corner; s >> corner; ++k) {
      if(k == 3) throw Cli_error(where + "a face with more than 3 corners");
      // v, v/vt, v//vn or v/vt/vn; negative indices count back from the last line read.
      long a = 0, p = 0;
      char* end = nullptr;
      a = std::strtol(corner.c_str(), &end, 10);
      if(end == corner.c_str() || (*end != '\0' && *end != '/') || a == 0)
        throw Cli_error(where + "'" + corner + "' is not a face corner (v, v/vt or v/vt/vn)");
      bool has_vt = false;
      if(*end == '/' && end[1] != '/' && end[1] != '\0') {
        const char* start = end + 1;
        p = std::strtol(start, &end, 10);
        if(end == start || (*end != '\0' && *end != '/') || p == 0)
          throw Cli_error(where + "'" + corner + "' is not a face corner (v, v/vt or v/vt/vn)");
        has_vt = true;
      }
      a = a > 0 ? a - 1 : long(v_count) + a;
      p = has_vt ? (p > 0 ? p - 1 : long(vt_count) + p) : -1;
      if(a < 0 || std::size_t(a) >= v_count || (has_vt && (p < 0 || std::size_t(p) >= vt_count)))
        throw Cli_error(where + "'" + corner + "' refers to a 'v' or 'vt' line that is not there (" +
                        std::to_string(v_count) + " 'v', " + std::to_string(vt_count) + " 'vt' so far)");
      t[std::size_t(k)] = int(a);
      u[std::size_t(k)] = int(p);
      if(has_vt && p != a) per_corner = true;
    }
    if(k != 3) throw Cli_error(where + "a face with " + std::to_string(k) + " corners (triangles expected)");
    faces.push_back(t);
    uv_faces.push_back(u);
    face_lines.push_back(line_number);
  }

  Obj_map map;
  if(!per_corner) {
    map.surface = mesh;
    map.uv = read_uv_obj(path, mesh.xyz.size());
    return map;
  }
  if(faces.size() != mesh.faces.size())
    throw Cli_error("'" + path + "': has " + std::to_string(faces.size()) + " faces for " + std::to_string(mesh.faces.size()) +
                    " mesh faces (per-corner uv: its faces must be the mesh's, in order)");
  std::vector<Vec2> vt;
  {
    std::ifstream again(path);
    while(std::getline(again, line)) {
      std::istringstream s(line);
      std::string tag;
      double x = 0, y = 0;
      if((s >> tag) && tag == "vt") {
        if(!(s >> x >> y) || !std::isfinite(x) || !std::isfinite(y))
          throw Cli_error("'" + path + "': a 'vt' line without two finite numbers");
        vt.push_back({{ x, y }});
      }
    }
  }
  std::vector<int> vertex_of(vt.size(), -1);
  for(std::size_t f = 0; f < faces.size(); ++f) {
    const std::string where = "'" + path + "', line " + std::to_string(face_lines[f]) + ": ";
    if(faces[f] != mesh.faces[f])
      throw Cli_error(where + "face " + std::to_string(f) + " joins vertices " + std::to_string(faces[f][0]) + " " +
                      std::to_string(faces[f][1]) + " " + std::to_string(faces[f][2]) + ", the mesh's " +
                      std::to_string(mesh.faces[f][0]) + " " + std::to_string(mesh.faces[f][1]) + " " +
                      std::to_string(mesh.faces[f][2]) + " (per-corner uv: the faces must be the mesh's, in order)");
    for(int k = 0; k < 3; ++k) {
      const int p = uv_faces[f][std::size_t(k)], a = faces[f][std::size_t(k)];
      if(p < 0) throw Cli_error(where + "a corner without 'vt' in a map with per-corner uv");
      int& v = vertex_of[std::size_t(p)];
      if(v >= 0 && v != a)
        throw Cli_error(where + "'vt' " + std::to_string(p + 1) + " is used at vertices " + std::to_string(v + 1) + " and " +
                        std::to_string(a + 1) + " (a 'vt' is one side of one vertex)");
      v = a;
    }
  }
  map.per_corner = true;
  map.uv = vt;
  map.surface.faces = uv_faces;
  map.surface.xyz.resize(vt.size(), Vec3{{ 0, 0, 0 }});
  for(std::size_t p = 0; p < vt.size(); ++p)
    if(vertex_of[p] >= 0) map.surface.xyz[p] = mesh.xyz[std::size_t(vertex_of[p])];
  return map;
}

} // namespace dlf_cli
