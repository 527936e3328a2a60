// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "svg_sphere.h"
#include "svg_common.h"
#include "svg_raster.h"
#include "text_buffer.h"

#include <cmath>
#include <memory>
#include <sstream>

namespace dlf_cli {

namespace {

const double disc_radius = 300, disc_margin = 20, disc_top = 44, disc_legend_width = 150;
const std::string fold_colour = "#000000";

} // namespace

void write_svg_sphere(std::ostream& out, const Indexed_mesh& mesh, const std::vector<Vec3>& sphere,
                      const std::string& caption, const Svg_options& style, const std::vector<double>& face_density,
                      const std::vector<int>& shaded)
{
  std::vector<double> log_ratio = face_log_area_ratios(mesh, sphere, face_density);
  if(style.raw() && !face_density.empty())
    for(std::size_t f = 0; f < log_ratio.size(); ++f) log_ratio[f] += std::log(face_density[f]);
  const double scale_end = colour_scale_end(log_ratio, style.fixed_scale());
  std::vector<char> in_region(mesh.faces.size(), 0);
  for(int f : shaded) in_region[std::size_t(f)] = 1;
  const double cy = disc_top + 20 + disc_radius;
  const double cx[2] = { disc_margin + disc_radius, 3 * disc_margin + 3 * disc_radius };
  const double width = 4 * disc_margin + 4 * disc_radius + disc_legend_width, height = cy + disc_radius + 30;
  write_svg_header(out, width, height, caption);
  const char* names[2] = { "seen from +z", "seen from −z" };
  for(int k = 0; k < 2; ++k)
    out << "<circle cx=\"" << cx[k] << "\" cy=\"" << cy << "\" r=\"" << disc_radius
        << "\" fill=\"#eee\" stroke=\"#444\"/><text x=\"" << cx[k] << "\" y=\"" << disc_top + 8
        << "\" text-anchor=\"middle\">" << names[k] << "</text>\n";

  bool has_bad_faces = false;
  {
    Text_buffer text(out);
    // The view of a triangle: the sign of the z of its normal. Seen from −z,
    // x is mirrored so that both views show the outside of the sphere.
    auto view_of = [&](const Triangle& t) {
      const Vec3 &a = sphere[t[0]], &b = sphere[t[1]], &c = sphere[t[2]];
      return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]) >= 0 ? 0 : 1;
    };
    auto points = [&](const Triangle& t, const char* separator, const char* first, const char* next) {
      const int view = view_of(t);
      const double mirror = view == 0 ? 1 : -1;
      for(int k = 0; k < 3; ++k) {
        text << (k == 0 ? first : next);
        text.fixed2(cx[view] + mirror * sphere[t[k]][0] * disc_radius) << ',';
        text.fixed2(cy - sphere[t[k]][1] * disc_radius) << (k < 2 ? separator : "");
      }
    };
    // Beyond the face budget, the faces are rasterised (svg_raster.h).
    const bool raster = mesh.faces.size() > style.max_faces;
    std::unique_ptr<Triangle_raster> canvas;
    if(raster) canvas.reset(new Triangle_raster(0, cy - disc_radius - 1, 4 * disc_margin + 4 * disc_radius, 2 * disc_radius + 2, svg_raster_pixels));
    // The shaded faces in a group of their own (id "region-faces").
    text << "<g stroke-linejoin=\"round\" stroke-width=\"0.3\">\n";
    for(int pass = 0; pass < (shaded.empty() ? 1 : 2); ++pass) {
      if(pass == 1) text << "</g>\n<g id=\"region-faces\" stroke-linejoin=\"round\" stroke-width=\"0.3\">\n";
      for(std::size_t f = 0; f < mesh.faces.size(); ++f) {
        if(in_region[f] != pass) continue;
        const bool bad = !std::isfinite(log_ratio[f]);
        has_bad_faces = has_bad_faces || bad;
        const std::string& colour = bad ? fold_colour : colour_of_log_ratio(log_ratio[f], scale_end);
        if(raster) {
          const Triangle& t = mesh.faces[f];
          const int view = view_of(t);
          const double mirror = view == 0 ? 1 : -1;
          double p[3][2];
          for(int k = 0; k < 3; ++k) {
            p[k][0] = cx[view] + mirror * sphere[t[k]][0] * disc_radius;
            p[k][1] = cy - sphere[t[k]][1] * disc_radius;
          }
          canvas->fill(p[0], p[1], p[2], colour, in_region[f] ? 0.15 : 0.);
          continue;
        }
        text << "<polygon points=\"";
        points(mesh.faces[f], " ", "", "");
        text << "\" fill=\"" << colour << "\" stroke=\"" << colour << "\"/>\n";
      }
    }
    text << "</g>\n";
    if(raster) {
      std::ostringstream image;
      canvas->write_image(image, "faces");
      text << image.str();
    }
    if(!shaded.empty() && !raster) {
      // One path for all the shaded triangles: filled once, without seams.
      text << "<path id=\"region-shade\" fill=\"#222\" fill-opacity=\"0.15\" stroke=\"none\" d=\"";
      for(int f : shaded) {
        points(mesh.faces[std::size_t(f)], "", "M", "L");
        text << 'Z';
      }
      text << "\"/>\n";
    }
  }
  write_colour_bar(out, 4 * disc_margin + 4 * disc_radius + 10, disc_top + 40, 240, has_bad_faces,
                   ratio_quantity(style.raw(), !face_density.empty()), scale_end);
  if(!shaded.empty())
    out << "<rect fill=\"#222\" fill-opacity=\"0.15\" x=\"" << 4 * disc_margin + 4 * disc_radius + 10 << "\" y=\""
        << disc_top + 40 + 240 + colour_bar_legend + 6 << "\" width=\"12\" height=\"12\"/><text x=\"" << 4 * disc_margin + 4 * disc_radius + 28
        << "\" y=\"" << disc_top + 40 + 240 + colour_bar_legend + 17 << "\">region of interest</text>\n";
  out << "</svg>\n";
}

} // namespace dlf_cli
