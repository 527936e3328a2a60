// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "svg_layout.h"

#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/disk_problem.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace dlf_cli {

namespace {

namespace D = CGAL::Surface_mesh_parameterization::internal::dlf;

const double clamp_log = std::log(4.);
const double layout_size = 760, margin = 20, bar_width = 24, legend_width = 150;

typedef std::array<double, 3> Rgb;
const Rgb blue = {{ 33, 102, 172 }}, white = {{ 247, 247, 247 }}, red = {{ 178, 24, 43 }};

std::string hex(const Rgb& c)
{
  char buffer[8];
  std::snprintf(buffer, sizeof(buffer), "#%02x%02x%02x", int(std::lround(c[0])), int(std::lround(c[1])),
                int(std::lround(c[2])));
  return buffer;
}

// Diverging scale: white at ratio 1, blue where the domain is too small,
// red where it is too large, saturated at a factor 4 either way.
std::string colour_of_log_ratio(double log_ratio)
{
  const double t = std::max(-1., std::min(1., log_ratio / clamp_log));
  const Rgb& end = t < 0 ? blue : red;
  const double a = std::abs(t);
  Rgb c;
  for(int k = 0; k < 3; ++k) c[k] = (1 - a) * white[k] + a * end[k];
  return hex(c);
}

std::string xml_escape(const std::string& s)
{
  std::string r;
  for(char ch : s) {
    switch(ch) {
    case '&': r += "&amp;"; break;
    case '<': r += "&lt;"; break;
    case '>': r += "&gt;"; break;
    case '"': r += "&quot;"; break;
    default: r += ch;
    }
  }
  return r;
}

void write_colour_bar(std::ostream& out, double x, double y, double height, bool has_bad_faces, bool weighted)
{
  out << "<defs><linearGradient id=\"ratio\" x1=\"0\" y1=\"0\" x2=\"0\" y2=\"1\">"
      << "<stop offset=\"0\" stop-color=\"" << hex(red) << "\"/>"
      << "<stop offset=\"0.5\" stop-color=\"" << hex(white) << "\"/>"
      << "<stop offset=\"1\" stop-color=\"" << hex(blue) << "\"/></linearGradient></defs>\n";
  out << "<rect x=\"" << x << "\" y=\"" << y << "\" width=\"" << bar_width << "\" height=\"" << height
      << "\" fill=\"url(#ratio)\" stroke=\"#444\" stroke-width=\"0.5\"/>\n";
  const char* labels[] = { "4", "2", "1", "1/2", "1/4" };
  for(int k = 0; k < 5; ++k) {
    const double ty = y + height * k / 4.;
    out << "<line x1=\"" << x + bar_width << "\" y1=\"" << ty << "\" x2=\"" << x + bar_width + 5 << "\" y2=\"" << ty
        << "\" stroke=\"#444\"/>"
        << "<text x=\"" << x + bar_width + 8 << "\" y=\"" << ty + 4 << "\">" << labels[k] << "</text>\n";
  }
  out << "<text x=\"" << x << "\" y=\"" << y - 8 << "\">area ratio</text>\n"
      << "<text x=\"" << x << "\" y=\"" << y + height + 18 << "\">" << (weighted ? "domain / (ρ·surface)" : "domain / surface")
      << "</text>\n";
  if(has_bad_faces)
    out << "<rect x=\"" << x << "\" y=\"" << y + height + 30 << "\" width=\"12\" height=\"12\" fill=\"#000\"/>"
        << "<text x=\"" << x + 18 << "\" y=\"" << y + height + 41 << "\">inverted or flat</text>\n";
}

} // namespace

void write_svg_layout(std::ostream& out, const Indexed_mesh& mesh, const std::vector<Vec2>& uv,
                      const std::string& caption, const std::vector<double>& face_density,
                      const std::vector<std::array<int, 2> >& outline)
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

  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << std::ceil(width) << "\" height=\"" << std::ceil(height)
      << "\" viewBox=\"0 0 " << std::ceil(width) << ' ' << std::ceil(height) << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
      << "<title>" << xml_escape(caption) << "</title>\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"#fff\"/>\n"
      << "<text x=\"" << margin << "\" y=\"16\">" << xml_escape(caption) << "</text>\n";
  out << "<g transform=\"translate(0,24)\" stroke-linejoin=\"round\">\n";
  // Folded and flat triangles last, outlined: under their neighbours they
  // would be invisible, and they are what a reader looks for.
  std::vector<std::size_t> bad_faces;
  char buffer[200];
  auto draw = [&](std::size_t f, const std::string& fill, const std::string& stroke, double stroke_width) {
    const Triangle& t = mesh.faces[f];
    double px[3], py[3];
    for(int k = 0; k < 3; ++k) {
      px[k] = margin + (uv[t[k]][0] - x0) * s;
      py[k] = margin + (y1 - uv[t[k]][1]) * s; // SVG's y axis points down
    }
    std::snprintf(buffer, sizeof(buffer),
                  "<polygon points=\"%.2f,%.2f %.2f,%.2f %.2f,%.2f\" fill=\"%s\" stroke=\"%s\" stroke-width=\"%g\"/>\n",
                  px[0], py[0], px[1], py[1], px[2], py[2], fill.c_str(), stroke.c_str(), stroke_width);
    out << buffer;
  };
  for(std::size_t f = 0; f < F; ++f) {
    if(sign[f] != majority || !(a2[f] > 0)) { bad_faces.push_back(f); continue; }
    // A thin stroke in the fill colour hides the hairline seams that
    // anti-aliasing draws between adjacent triangles.
    const std::string colour = colour_of_log_ratio(std::log(a2[f] * scale2 / a3[f]));
    draw(f, colour, colour, 0.3);
  }
  for(std::size_t f : bad_faces) draw(f, "#000000", "#000000", 1.5);
  if(!outline.empty()) {
    out << "<path fill=\"none\" stroke=\"#111\" stroke-width=\"1.5\" stroke-linecap=\"round\" d=\"";
    for(const std::array<int, 2>& e : outline) {
      std::snprintf(buffer, sizeof(buffer), "M%.2f,%.2fL%.2f,%.2f", margin + (uv[e[0]][0] - x0) * s,
                    margin + (y1 - uv[e[0]][1]) * s, margin + (uv[e[1]][0] - x0) * s, margin + (y1 - uv[e[1]][1]) * s);
      out << buffer;
    }
    out << "\"/>\n";
  }
  out << "</g>\n";
  write_colour_bar(out, 2 * margin + (x1 - x0) * s + 20, margin + 24 + 20, 240, !bad_faces.empty(), !face_density.empty());
  if(!outline.empty())
    out << "<line x1=\"" << 2 * margin + (x1 - x0) * s + 20 << "\" y1=\"" << margin + 24 + 20 + 240 + 56 << "\" x2=\""
        << 2 * margin + (x1 - x0) * s + 32 << "\" y2=\"" << margin + 24 + 20 + 240 + 56 << "\" stroke=\"#111\" stroke-width=\"1.5\"/>"
        << "<text x=\"" << 2 * margin + (x1 - x0) * s + 38 << "\" y=\"" << margin + 24 + 20 + 240 + 60 << "\">region of interest</text>\n";
  out << "</svg>\n";
}

} // namespace dlf_cli
