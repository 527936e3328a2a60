// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "svg_layout.h"
#include "svg_common.h"
#include "svg_raster.h"
#include "text_buffer.h"

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_distortion.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>

namespace dlf_cli {

namespace {

namespace SMP = CGAL::Surface_mesh_parameterization;

const double layout_size = 760, margin = 20, legend_width = 150;

// Per face: the log of its domain area over its surface area (times ρ),
// in units of their totals; NaN for a folded or flat face. Exact
// orientations; the majority orientation is "positive" (a mirrored layout
// is not a fold).
std::vector<double> layout_log_ratios(const Indexed_mesh& mesh, const std::vector<Vec2>& uv, const Svg_options& style,
                                      const std::vector<double>& face_density)
{
  const std::size_t F = mesh.faces.size();
  const std::vector<double> a3 = weighted_face_areas(mesh, face_density);
  std::vector<double> a2(F);
  std::vector<int> sign(F);
  double sum3 = 0, sum2 = 0;
  long balance = 0;
  for(std::size_t f = 0; f < F; ++f) {
    const Triangle& t = mesh.faces[f];
    a2[f] = std::abs(SMP::discrete_lie_flow_signed_area_2(uv[t[0]], uv[t[1]], uv[t[2]]));
    sign[f] = int(SMP::discrete_lie_flow_orientation_2(uv[t[0]], uv[t[1]], uv[t[2]]));
    sum3 += a3[f];
    sum2 += a2[f];
    balance += sign[f];
  }
  const int majority = balance >= 0 ? 1 : -1;
  const double scale2 = sum2 > 0 ? sum3 / sum2 : 1.;
  // Raw: a3 without ρ, so that the ratio is ρ where the map reached its target.
  std::vector<double> log_ratio(F, std::numeric_limits<double>::quiet_NaN());
  for(std::size_t f = 0; f < F; ++f)
    if(sign[f] == majority && a2[f] > 0)
      log_ratio[f] = std::log(a2[f] * scale2 / a3[f]) + (style.raw() && !face_density.empty() ? std::log(face_density[f]) : 0.);
  return log_ratio;
}

// The uv bounding box and its scale to the picture.
struct Layout_frame
{
  explicit Layout_frame(const std::vector<Vec2>& uv)
  {
    x0 = x1 = uv.empty() ? 0 : uv[0][0];
    y0 = y1 = uv.empty() ? 0 : uv[0][1];
    for(const Vec2& p : uv) {
      x0 = std::min(x0, p[0]); x1 = std::max(x1, p[0]);
      y0 = std::min(y0, p[1]); y1 = std::max(y1, p[1]);
    }
    const double extent = std::max(x1 - x0, y1 - y0);
    s = extent > 0 ? layout_size / extent : 1.;
  }
  /// A uv point in the picture; SVG's y axis points down.
  std::array<double, 2> point(const Vec2& p) const { return {{ margin + (p[0] - x0) * s, margin + (y1 - p[1]) * s }}; }
  double width() const { return (x1 - x0) * s; }
  double height() const { return (y1 - y0) * s; }

  double x0, x1, y0, y1, s;
};

// Draws the layout's triangles, as polygons into `text` or as pixels into
// `canvas`, and the paths over them.
class Layout_painter
{
public:
  Layout_painter(Text_buffer& text, const Indexed_mesh& mesh, const std::vector<Vec2>& uv, const Layout_frame& frame,
                 const std::vector<char>& in_region, Triangle_raster* canvas)
    : m_text(text), m_mesh(mesh), m_uv(uv), m_frame(frame), m_in_region(in_region), m_canvas(canvas)
  {
  }

  void draw(std::size_t f, const std::string& colour, bool as_pixels)
  {
    const Triangle& t = m_mesh.faces[f];
    if(as_pixels) {
      m_canvas->fill(point(t[0]).data(), point(t[1]).data(), point(t[2]).data(), colour, m_in_region[f] ? shade : 0.);
      return;
    }
    m_text << "<polygon points=\"";
    for(int k = 0; k < 3; ++k) {
      m_text.fixed2(point(t[k])[0]) << ',';
      m_text.fixed2(point(t[k])[1]) << (k < 2 ? " " : "");
    }
    m_text << "\" fill=\"" << colour << "\" stroke=\"" << colour << "\"/>\n";
  }

  /// One path for all the shaded triangles: filled once, without seams.
  void shade_regions(const std::vector<int>& shaded)
  {
    m_text << "<path id=\"region-shade\" fill=\"#222\" fill-opacity=\"0.15\" stroke=\"none\" d=\"";
    for(int f : shaded) {
      const Triangle& t = m_mesh.faces[std::size_t(f)];
      for(int k = 0; k < 3; ++k) {
        m_text << (k == 0 ? 'M' : 'L');
        m_text.fixed2(point(t[k])[0]) << ',';
        m_text.fixed2(point(t[k])[1]);
      }
      m_text << 'Z';
    }
    m_text << "\"/>\n";
  }

  void outline(const std::vector<std::array<int, 2> >& edges)
  {
    m_text << "<path fill=\"none\" stroke=\"#111\" stroke-width=\"1.5\" stroke-linecap=\"round\" d=\"";
    for(const std::array<int, 2>& e : edges) {
      m_text << 'M';
      m_text.fixed2(point(e[0])[0]) << ',';
      m_text.fixed2(point(e[0])[1]) << 'L';
      m_text.fixed2(point(e[1])[0]) << ',';
      m_text.fixed2(point(e[1])[1]);
    }
    m_text << "\"/>\n";
  }

  static constexpr double shade = 0.15; ///< the opacity of the regions' shade (as written above)

private:
  std::array<double, 2> point(int v) const { return m_frame.point(m_uv[std::size_t(v)]); }

  Text_buffer& m_text;
  const Indexed_mesh& m_mesh;
  const std::vector<Vec2>& m_uv;
  const Layout_frame& m_frame;
  const std::vector<char>& m_in_region;
  Triangle_raster* m_canvas;
};

// Below the colour bar: a shaded square for regions, a line for the
// outlines of density pieces.
void write_layout_key(std::ostream& out, double kx, double ky, bool regions, const std::string& label)
{
  if(!regions)
    out << "<line x1=\"" << kx << "\" y1=\"" << ky + 12 << "\" x2=\"" << kx + 12 << "\" y2=\"" << ky + 12
        << "\" stroke=\"#111\" stroke-width=\"1.5\"/>";
  else
    out << "<rect x=\"" << kx << "\" y=\"" << ky + 6 << "\" width=\"12\" height=\"12\" fill=\"#222\" fill-opacity=\"0.15\" "
        << "stroke=\"#111\" stroke-width=\"1.5\"/>";
  out << "<text x=\"" << kx + 18 << "\" y=\"" << ky + 16 << "\">" << xml_escape(label) << "</text>\n";
}

} // namespace

void write_svg_layout(std::ostream& out, const Indexed_mesh& mesh, const std::vector<Vec2>& uv,
                      const std::string& caption, const Svg_options& style, const std::vector<double>& face_density,
                      const std::vector<std::array<int, 2> >& outline, const std::string& outline_label,
                      const std::vector<int>& shaded)
{
  const std::size_t F = mesh.faces.size();
  const std::vector<double> log_ratio = layout_log_ratios(mesh, uv, style, face_density);
  const double scale_end = colour_scale_end(log_ratio, style.fixed_scale());
  std::vector<char> in_region(F, 0);
  for(int f : shaded) in_region[std::size_t(f)] = 1;

  const Layout_frame frame(uv);
  const double width = 2 * margin + frame.width() + legend_width;
  const double height = std::max(2 * margin + frame.height(), 2 * margin + 340.) + 24;

  write_svg_header(out, width, height, caption);
  // Folded and flat triangles last, outlined: under their neighbours they
  // would be invisible, and they are what a reader looks for. A thin stroke
  // in the fill colour hides the hairline seams that anti-aliasing draws
  // between adjacent triangles. Beyond the face budget, the faces are
  // rasterised (svg_raster.h); the folded ones stay polygons unless they
  // too exceed it.
  const bool raster = F > style.max_faces;
  std::unique_ptr<Triangle_raster> canvas;
  if(raster) canvas.reset(new Triangle_raster(margin - 1, margin - 1, frame.width() + 2, frame.height() + 2, svg_raster_pixels));
  std::vector<std::size_t> bad_faces;
  {
    Text_buffer text(out);
    Layout_painter painter(text, mesh, uv, frame, in_region, canvas.get());
    // The shaded faces in a group of their own (id "region-faces"), so that
    // their colours can be told from the others'.
    text << "<g transform=\"translate(0,24)\" stroke-linejoin=\"round\">\n<g stroke-width=\"0.3\">\n";
    for(int pass = 0; pass < (shaded.empty() ? 1 : 2); ++pass) {
      if(pass == 1) text << "</g>\n<g id=\"region-faces\" stroke-width=\"0.3\">\n";
      for(std::size_t f = 0; f < F; ++f) {
        if(in_region[f] != pass) continue;
        if(!std::isfinite(log_ratio[f])) { bad_faces.push_back(f); continue; }
        painter.draw(f, colour_of_log_ratio(log_ratio[f], scale_end), raster);
      }
    }
    text << "</g>\n";
    const std::string black = "#000000";
    if(raster) {
      if(bad_faces.size() > style.max_faces)
        for(std::size_t f : bad_faces) painter.draw(f, black, true);
      std::ostringstream image;
      canvas->write_image(image, "faces");
      text << image.str();
    }
    text << "<g stroke-width=\"1.5\">\n";
    if(!raster || bad_faces.size() <= style.max_faces)
      for(std::size_t f : bad_faces) painter.draw(f, black, false);
    text << "</g>\n";
    if(!shaded.empty() && !raster) painter.shade_regions(shaded);
    if(!outline.empty()) painter.outline(outline);
  }
  out << "</g>\n";
  const double kx = 2 * margin + frame.width() + 20, ky = margin + 24 + 20;
  write_colour_bar(out, kx, ky, 240, !bad_faces.empty(), ratio_quantity(style.raw(), !face_density.empty()), scale_end);
  if(!outline.empty()) write_layout_key(out, kx, ky + 240 + colour_bar_legend, !shaded.empty(), outline_label);
  out << "</svg>\n";
}

} // namespace dlf_cli
