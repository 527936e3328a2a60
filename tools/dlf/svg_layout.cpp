// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "svg_layout.h"
#include "svg_common.h"
#include "text_buffer.h"

#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/certification.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace dlf_cli {

namespace {

namespace D = CGAL::Surface_mesh_parameterization::internal::dlf;

const double layout_size = 760, margin = 20, legend_width = 150;

} // namespace

void write_svg_layout(std::ostream& out, const Indexed_mesh& mesh, const std::vector<Vec2>& uv,
                      const std::string& caption, const std::vector<double>& face_density,
                      const std::vector<std::array<int, 2> >& outline, const std::string& outline_label)
{
  const std::size_t F = mesh.faces.size();
  // Per face: surface area, domain area, exact orientation; the majority
  // orientation is "positive" (a mirrored layout is not a fold).
  std::vector<double> a3(F), a2(F);
  std::vector<int> sign(F);
  double sum3 = 0, sum2 = 0;
  long balance = 0;
  for(std::size_t f = 0; f < F; ++f) {
    const Triangle& t = mesh.faces[f];
    a3[f] = D::triangle_area_3(mesh.xyz[t[0]], mesh.xyz[t[1]], mesh.xyz[t[2]]) *
            (face_density.empty() ? 1. : face_density[f]);
    a2[f] = std::abs(D::signed_area_2(uv[t[0]], uv[t[1]], uv[t[2]]));
    sign[f] = int(D::exact_orientation_2(uv[t[0]], uv[t[1]], uv[t[2]]));
    sum3 += a3[f];
    sum2 += a2[f];
    balance += sign[f];
  }
  const int majority = balance >= 0 ? 1 : -1;
  const double scale2 = sum2 > 0 ? sum3 / sum2 : 1.;

  double x0 = uv.empty() ? 0 : uv[0][0], x1 = x0, y0 = uv.empty() ? 0 : uv[0][1], y1 = y0;
  for(const Vec2& p : uv) {
    x0 = std::min(x0, p[0]); x1 = std::max(x1, p[0]);
    y0 = std::min(y0, p[1]); y1 = std::max(y1, p[1]);
  }
  const double extent = std::max(x1 - x0, y1 - y0);
  const double s = extent > 0 ? layout_size / extent : 1.;
  const double width = 2 * margin + (x1 - x0) * s + legend_width;
  const double height = std::max(2 * margin + (y1 - y0) * s, 2 * margin + 340.) + 24;

  write_svg_header(out, width, height, caption);
  // Folded and flat triangles last, outlined: under their neighbours they
  // would be invisible, and they are what a reader looks for. A thin stroke
  // in the fill colour hides the hairline seams that anti-aliasing draws
  // between adjacent triangles.
  std::vector<std::size_t> bad_faces;
  {
    Text_buffer text(out);
    auto draw = [&](std::size_t f, const std::string& colour) {
      const Triangle& t = mesh.faces[f];
      text << "<polygon points=\"";
      for(int k = 0; k < 3; ++k) {
        text.fixed2(margin + (uv[t[k]][0] - x0) * s) << ',';
        text.fixed2(margin + (y1 - uv[t[k]][1]) * s) << (k < 2 ? " " : ""); // SVG's y axis points down
      }
      text << "\" fill=\"" << colour << "\" stroke=\"" << colour << "\"/>\n";
    };
    text << "<g transform=\"translate(0,24)\" stroke-linejoin=\"round\">\n<g stroke-width=\"0.3\">\n";
    for(std::size_t f = 0; f < F; ++f) {
      if(sign[f] != majority || !(a2[f] > 0)) { bad_faces.push_back(f); continue; }
      draw(f, colour_of_log_ratio(std::log(a2[f] * scale2 / a3[f])));
    }
    text << "</g>\n<g stroke-width=\"1.5\">\n";
    const std::string black = "#000000";
    for(std::size_t f : bad_faces) draw(f, black);
    text << "</g>\n";
    if(!outline.empty()) {
      text << "<path fill=\"none\" stroke=\"#111\" stroke-width=\"1.5\" stroke-linecap=\"round\" d=\"";
      for(const std::array<int, 2>& e : outline) {
        text << 'M';
        text.fixed2(margin + (uv[e[0]][0] - x0) * s) << ',';
        text.fixed2(margin + (y1 - uv[e[0]][1]) * s) << 'L';
        text.fixed2(margin + (uv[e[1]][0] - x0) * s) << ',';
        text.fixed2(margin + (y1 - uv[e[1]][1]) * s);
      }
      text << "\"/>\n";
    }
  }
  out << "</g>\n";
  write_colour_bar(out, 2 * margin + (x1 - x0) * s + 20, margin + 24 + 20, 240, !bad_faces.empty(), !face_density.empty());
  if(!outline.empty())
    out << "<line x1=\"" << 2 * margin + (x1 - x0) * s + 20 << "\" y1=\"" << margin + 24 + 20 + 240 + 56 << "\" x2=\""
        << 2 * margin + (x1 - x0) * s + 32 << "\" y2=\"" << margin + 24 + 20 + 240 + 56 << "\" stroke=\"#111\" stroke-width=\"1.5\"/>"
        << "<text x=\"" << 2 * margin + (x1 - x0) * s + 38 << "\" y=\"" << margin + 24 + 20 + 240 + 60 << "\">" << xml_escape(outline_label) << "</text>\n";
  out << "</svg>\n";
}

} // namespace dlf_cli
