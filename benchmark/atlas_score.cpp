// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The score of atlas OBJ files (`v`, `vt`, triangles `f v/vt`), whoever made
// them, one JSON line each: charts, seam length over √area, packing
// efficiency (uv area over the uv's bounding rectangle), global D_area,
// inverted and degenerate uv triangles, overlapping uv triangle pairs (all
// exact). benchmark/atlas_vs_xatlas.sh scores `dlf atlas` and xatlas with it.
//
//   atlas_score ATLAS.obj...

#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/atlas/atlas_score.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace D = CGAL::Surface_mesh_parameterization::internal::dlf;

static bool read_atlas_obj(const std::string& path, std::vector<D::Vec3>& xyz, std::vector<D::Face>& faces,
                           std::vector<D::Vec2>& uv, std::vector<D::Face>& uv_faces, std::string& error)
{
  std::ifstream in(path);
  if(!in) { error = "cannot read"; return false; }
  std::string line;
  std::size_t number = 0;
  while(std::getline(in, line)) {
    ++number;
    std::istringstream s(line);
    std::string tag;
    s >> tag;
    if(tag == "v") { D::Vec3 p; s >> p[0] >> p[1] >> p[2]; xyz.push_back(p); }
    else if(tag == "vt") { D::Vec2 p; s >> p[0] >> p[1]; uv.push_back(p); }
    else if(tag == "f") {
      D::Face t, u;
      std::string c;
      int k = 0;
      for(; s >> c; ++k) {
        const std::size_t slash = c.find('/');
        if(k >= 3 || slash == std::string::npos) { error = "line " + std::to_string(number) + ": not a triangle with v/vt corners"; return false; }
        const long v = std::stol(c.substr(0, slash)), t_ = std::stol(c.substr(slash + 1));
        if(v < 1 || std::size_t(v) > xyz.size() || t_ < 1 || std::size_t(t_) > uv.size()) {
          error = "line " + std::to_string(number) + ": corner " + c + " out of range";
          return false;
        }
        t[k] = int(v - 1);
        u[k] = int(t_ - 1);
      }
      if(k != 3) { error = "line " + std::to_string(number) + ": not a triangle"; return false; }
      faces.push_back(t);
      uv_faces.push_back(u);
    }
  }
  if(faces.empty()) { error = "no faces"; return false; }
  return true;
}

int main(int argc, char** argv)
{
  int status = 0;
  for(int i = 1; i < argc; ++i) {
    std::vector<D::Vec3> xyz;
    std::vector<D::Face> faces, uv_faces;
    std::vector<D::Vec2> uv;
    std::string error;
    if(!read_atlas_obj(argv[i], xyz, faces, uv, uv_faces, error)) {
      std::fprintf(stderr, "atlas_score: %s: %s\n", argv[i], error.c_str());
      status = 1;
      continue;
    }
    const D::Atlas_score S = D::score_atlas(xyz, faces, uv, uv_faces);
    std::printf("{\"atlas\": \"%s\", \"faces\": %zu, \"charts\": %zu, \"seam_over_sqrt_area\": %.4f, \"packing_efficiency\": %.4f, "
                "\"d_area\": %.6f, \"inverted\": %zu, \"mirrored_charts\": %zu, \"degenerate\": %zu, \"overlapping_face_pairs\": %zu, "
                "\"overlapping_pairs_in_a_chart\": %zu, \"uv_box\": [%.6g, %.6g]}\n",
                argv[i], S.faces, S.charts, S.seam_length / std::sqrt(S.surface_area), S.packing_efficiency, S.metrics.d_area,
                S.inverted_faces, S.mirrored_charts, S.degenerate_faces, S.overlapping_face_pairs, S.overlapping_pairs_in_a_chart, S.bounding_width,
                S.bounding_height);
    std::fflush(stdout);
  }
  return status;
}
