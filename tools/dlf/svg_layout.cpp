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

} // namespace

void write_svg_layout(std::ostream& out, const Indexed_mesh& mesh, const std::vector<Vec2>& uv,
                      const std::string& caption, const Svg_options& style, const std::vector<double>& face_density,
                      const std::vector<std::array<int, 2> >& outline, const std::string& outline_label,
                      const std::vector<int>& shaded)
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
    a3[f] = SMP::discrete_lie_flow_triangle_area(mesh.xyz[t[0]], mesh.xyz[t[1]], mesh.xyz[t[2]]) *
            (face_density.empty() ? 1. : face_density[f]);
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
  const double scale_end = colour_scale_end(log_ratio, style.fixed_scale());
  std::vector<char> in_region(F, 0);
  for(int f : shaded) in_region[std::size_t(f)] = 1;

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
  // between adjacent triangles. Beyond the face budget, the faces are
  // rasterised (svg_raster.h); the folded ones stay polygons unless they
  // too exceed it.
  const bool raster = F > style.max_faces;
  std::unique_ptr<Triangle_raster> canvas;
  if(raster) canvas.reset(new Triangle_raster(margin - 1, margin - 1, (x1 - x0) * s + 2, (y1 - y0) * s + 2, svg_raster_pixels));
  const double shade = 0.15; // the opacity of the regions' shade (as written below)
  std::vector<std::size_t> bad_faces;
  {
    Text_buffer text(out);
    auto point = [&](int v) { return std::array<double, 2>{{ margin + (uv[v][0] - x0) * s, margin + (y1 - uv[v][1]) * s }}; }; // SVG's y axis points down
    auto draw = [&](std::size_t f, const std::string& colour, bool as_pixels) {
      const Triangle& t = mesh.faces[f];
      if(as_pixels) {
        canvas->fill(point(t[0]).data(), point(t[1]).data(), point(t[2]).data(), colour, in_region[f] ? shade : 0.);
        return;
      }
      text << "<polygon points=\"";
      for(int k = 0; k < 3; ++k) {
        text.fixed2(point(t[k])[0]) << ',';
        text.fixed2(point(t[k])[1]) << (k < 2 ? " " : "");
      }
      text << "\" fill=\"" << colour << "\" stroke=\"" << colour << "\"/>\n";
    };
    // The shaded faces in a group of their own (id "region-faces"), so that
    // their colours can be told from the others'.
    text << "<g transform=\"translate(0,24)\" stroke-linejoin=\"round\">\n<g stroke-width=\"0.3\">\n";
    for(int pass = 0; pass < (shaded.empty() ? 1 : 2); ++pass) {
      if(pass == 1) text << "</g>\n<g id=\"region-faces\" stroke-width=\"0.3\">\n";
      for(std::size_t f = 0; f < F; ++f) {
        if(in_region[f] != pass) continue;
        if(!std::isfinite(log_ratio[f])) { bad_faces.push_back(f); continue; }
        draw(f, colour_of_log_ratio(log_ratio[f], scale_end), raster);
      }
    }
    text << "</g>\n";
    const std::string black = "#000000";
    if(raster) {
      if(bad_faces.size() > style.max_faces)
        for(std::size_t f : bad_faces) draw(f, black, true);
      std::ostringstream image;
      canvas->write_image(image, "faces");
      text << image.str();
    }
    text << "<g stroke-width=\"1.5\">\n";
    if(!raster || bad_faces.size() <= style.max_faces)
      for(std::size_t f : bad_faces) draw(f, black, false);
    text << "</g>\n";
    if(!shaded.empty() && !raster) {
      // One path for all the shaded triangles: filled once, without seams.
      text << "<path id=\"region-shade\" fill=\"#222\" fill-opacity=\"0.15\" stroke=\"none\" d=\"";
      for(int f : shaded) {
        const Triangle& t = mesh.faces[std::size_t(f)];
        for(int k = 0; k < 3; ++k) {
          text << (k == 0 ? 'M' : 'L');
          text.fixed2(point(t[k])[0]) << ',';
          text.fixed2(point(t[k])[1]);
        }
        text << 'Z';
      }
      text << "\"/>\n";
    }
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
  write_colour_bar(out, 2 * margin + (x1 - x0) * s + 20, margin + 24 + 20, 240, !bad_faces.empty(),
                   ratio_quantity(style.raw(), !face_density.empty()), scale_end);
  if(!outline.empty()) {
    // The key: a shaded square for regions, a line for the outlines of density pieces.
    const double kx = 2 * margin + (x1 - x0) * s + 20, ky = margin + 24 + 20 + 240 + colour_bar_legend;
    if(shaded.empty())
      out << "<line x1=\"" << kx << "\" y1=\"" << ky + 12 << "\" x2=\"" << kx + 12 << "\" y2=\"" << ky + 12
          << "\" stroke=\"#111\" stroke-width=\"1.5\"/>";
    else
      out << "<rect x=\"" << kx << "\" y=\"" << ky + 6 << "\" width=\"12\" height=\"12\" fill=\"#222\" fill-opacity=\"0.15\" "
          << "stroke=\"#111\" stroke-width=\"1.5\"/>";
    out << "<text x=\"" << kx + 18 << "\" y=\"" << ky + 16 << "\">" << xml_escape(outline_label) << "</text>\n";
  }
  out << "</svg>\n";
}

} // namespace dlf_cli
