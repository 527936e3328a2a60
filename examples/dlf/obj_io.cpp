// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "obj_io.h"
#include "cli_error.h"
#include "text_buffer.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace dlf_cli {

void write_uv_obj(std::ostream& out, const std::vector<Vec3>& xyz, const std::vector<Vec2>& uv,
                  const std::vector<Triangle>& faces, const std::string& comment)
{
  Text_buffer text(out);
  if(!comment.empty()) text << "# " << comment << "\n";
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
  for(const Triangle& f : faces) {
    text << 'f';
    for(int k = 0; k < 3; ++k) text << ' ' << f[k] + 1 << '/' << f[k] + 1;
    text << '\n';
  }
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

} // namespace dlf_cli
