// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "svg_common.h"

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_distortion.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>

namespace dlf_cli {

namespace {

namespace SMP = CGAL::Surface_mesh_parameterization;

typedef std::array<double, 3> Rgb;
const Rgb blue = {{ 33, 102, 172 }}, white = {{ 247, 247, 247 }}, red = {{ 178, 24, 43 }};

std::string hex(const Rgb& c)
{
  char buffer[8];
  std::snprintf(buffer, sizeof(buffer), "#%02x%02x%02x", int(std::lround(c[0])), int(std::lround(c[1])),
                int(std::lround(c[2])));
  return buffer;
}

// Signed double area of a domain triangle: in the plane, or against the
// centre of the sphere (the orientation the sphere flow certifies).
double signed_area(const Vec2& a, const Vec2& b, const Vec2& c)
{
  return 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
}
double signed_area(const Vec3& a, const Vec3& b, const Vec3& c)
{
  const double area = SMP::discrete_lie_flow_triangle_area(a, b, c);
  // det[a, b, c] = a · (b × c)
  const double det = a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
  return det < 0 ? -area : area;
}

} // namespace

std::vector<double> weighted_face_areas(const Indexed_mesh& mesh, const std::vector<double>& face_density)
{
  std::vector<double> area(mesh.faces.size());
  for(std::size_t f = 0; f < area.size(); ++f) {
    const Triangle& t = mesh.faces[f];
    area[f] = SMP::discrete_lie_flow_triangle_area(mesh.xyz[t[0]], mesh.xyz[t[1]], mesh.xyz[t[2]]) *
              (face_density.empty() ? 1. : face_density[f]);
  }
  return area;
}

namespace {

template <class Point>
std::vector<double> log_ratios(const Indexed_mesh& mesh, const std::vector<Point>& domain,
                               const std::vector<double>& face_density)
{
  const std::size_t F = mesh.faces.size();
  const std::vector<double> a3 = weighted_face_areas(mesh, face_density);
  std::vector<double> a2(F), out(F, std::numeric_limits<double>::quiet_NaN());
  double sum3 = 0, sum2 = 0;
  long balance = 0;
  for(std::size_t f = 0; f < F; ++f) {
    const Triangle& t = mesh.faces[f];
    a2[f] = signed_area(domain[t[0]], domain[t[1]], domain[t[2]]);
    balance += a2[f] > 0 ? 1 : a2[f] < 0 ? -1 : 0;
    sum3 += a3[f];
    sum2 += std::abs(a2[f]);
  }
  const double majority = balance >= 0 ? 1. : -1.;
  const double scale2 = sum2 > 0 ? sum3 / sum2 : 1.;
  for(std::size_t f = 0; f < F; ++f)
    if(majority * a2[f] > 0 && a3[f] > 0) out[f] = std::log(majority * a2[f] * scale2 / a3[f]);
  return out;
}

// A label of the scale: 3 significant digits, "1/x" below 1.
std::string scale_label(double ratio)
{
  const double x = ratio < 1 ? 1 / ratio : ratio;
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), x < 1000 ? "%.3g" : "%.0f", x);
  return (ratio < 1 ? "1/" : "") + std::string(buffer);
}
const double svg_bar_width = 24;

} // namespace

double colour_scale_end(const std::vector<double>& log_ratios, bool fixed)
{
  if(fixed) return 4;
  double largest = 0;
  for(double l : log_ratios)
    if(std::isfinite(l)) largest = (std::max)(largest, std::abs(l));
  const double end = std::exp(largest);
  // Two significant digits, rounded up (the tolerance keeps 40.0000001 at 40).
  const double unit = std::pow(10., std::floor(std::log10(end)) - 1);
  return (std::max)(1.1, std::ceil(end / unit - 1e-9) * unit);
}

const std::string& colour_of_log_ratio(double log_ratio, double scale_end)
{
  // A table of the scale in 2·512 steps (adjacent entries differ by at most
  // one unit of a channel): a lookup per face instead of formatting.
  static const std::vector<std::string> table = [] {
    std::vector<std::string> t(1025);
    for(int k = 0; k <= 1024; ++k) {
      const double x = (k - 512) / 512.;
      const Rgb& end = x < 0 ? blue : red;
      const double a = std::abs(x);
      Rgb c;
      for(int i = 0; i < 3; ++i) c[std::size_t(i)] = (1 - a) * white[std::size_t(i)] + a * end[std::size_t(i)];
      t[std::size_t(k)] = hex(c);
    }
    return t;
  }();
  const double t = std::max(-1., std::min(1., log_ratio / std::log(scale_end)));
  return table[std::size_t(std::lround(512 * (t + 1)))];
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

void write_svg_header(std::ostream& out, double width, double height, const std::string& caption)
{
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:xlink=\"http://www.w3.org/1999/xlink\" width=\"" << std::ceil(width) << "\" height=\"" << std::ceil(height)
      << "\" viewBox=\"0 0 " << std::ceil(width) << ' ' << std::ceil(height)
      << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
      << "<title>" << xml_escape(caption) << "</title>\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"#fff\"/>\n"
      << "<text x=\"20\" y=\"16\">" << xml_escape(caption) << "</text>\n";
}

void write_colour_bar(std::ostream& out, double x, double y, double height, bool has_bad_faces,
                      const std::string& quantity, double scale_end)
{
  char scale[96];
  std::snprintf(scale, sizeof(scale), "data-scale-min=\"%.17g\" data-scale-max=\"%.17g\"", 1 / scale_end, scale_end);
  out << "<g id=\"colour-bar\" " << scale << ">\n";
  out << "<defs><linearGradient id=\"ratio\" x1=\"0\" y1=\"0\" x2=\"0\" y2=\"1\">"
      << "<stop offset=\"0\" stop-color=\"" << hex(red) << "\"/>"
      << "<stop offset=\"0.5\" stop-color=\"" << hex(white) << "\"/>"
      << "<stop offset=\"1\" stop-color=\"" << hex(blue) << "\"/></linearGradient></defs>\n";
  out << "<rect x=\"" << x << "\" y=\"" << y << "\" width=\"" << svg_bar_width << "\" height=\"" << height
      << "\" fill=\"url(#ratio)\" stroke=\"#444\" stroke-width=\"0.5\"/>\n";
  // Ticks at E, √E, 1, 1/√E, 1/E: even steps of the log scale.
  for(int k = 0; k < 5; ++k) {
    const double ty = y + height * k / 4.;
    out << "<line x1=\"" << x + svg_bar_width << "\" y1=\"" << ty << "\" x2=\"" << x + svg_bar_width + 5 << "\" y2=\""
        << ty << "\" stroke=\"#444\"/>"
        << "<text x=\"" << x + svg_bar_width + 8 << "\" y=\"" << ty + 4 << "\">"
        << scale_label(std::pow(scale_end, (2 - k) / 2.)) << "</text>\n";
  }
  out << "<text x=\"" << x << "\" y=\"" << y - 8 << "\">area ratio</text>\n"
      << "<text x=\"" << x << "\" y=\"" << y + height + 18 << "\">";
  // A second line after '\n' (the legend is narrow).
  const std::size_t cut = quantity.find('\n');
  out << xml_escape(quantity.substr(0, cut));
  if(cut != std::string::npos)
    out << "<tspan x=\"" << x << "\" dy=\"14\">" << xml_escape(quantity.substr(cut + 1)) << "</tspan>";
  out << "</text>\n";
  if(has_bad_faces)
    out << "<rect x=\"" << x << "\" y=\"" << y + height + 42 << "\" width=\"12\" height=\"12\" fill=\"#000\"/>"
        << "<text x=\"" << x + 18 << "\" y=\"" << y + height + 53 << "\">inverted or flat</text>\n";
  out << "</g>\n";
}

void write_colour_bar(std::ostream& out, double x, double y, double height, bool has_bad_faces, bool weighted)
{
  write_colour_bar(out, x, y, height, has_bad_faces, ratio_quantity(false, weighted), 4);
}

std::string ratio_quantity(bool raw, bool has_density)
{
  if(!has_density) return "domain / surface";
  return raw ? "domain / surface\n(ρ = 1: area kept)" : "domain / (ρ·surface)";
}

std::vector<double> face_log_area_ratios(const Indexed_mesh& mesh, const std::vector<Vec2>& domain,
                                         const std::vector<double>& face_density)
{
  return log_ratios(mesh, domain, face_density);
}

std::vector<double> face_log_area_ratios(const Indexed_mesh& mesh, const std::vector<Vec3>& domain,
                                         const std::vector<double>& face_density)
{
  return log_ratios(mesh, domain, face_density);
}

} // namespace dlf_cli
