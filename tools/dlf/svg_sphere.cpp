// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "svg_sphere.h"
#include "svg_common.h"
#include "text_buffer.h"

#include <cmath>

namespace dlf_cli {

namespace {

const double disc_radius = 300, disc_margin = 20, disc_top = 44, disc_legend_width = 150;
const std::string fold_colour = "#000000";

} // namespace

void write_svg_sphere(std::ostream& out, const Indexed_mesh& mesh, const std::vector<Vec3>& sphere,
                      const std::string& caption)
{
  const std::vector<double> log_ratio = face_log_area_ratios(mesh, sphere, std::vector<double>());
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
    text << "<g stroke-linejoin=\"round\" stroke-width=\"0.3\">\n";
    for(std::size_t f = 0; f < mesh.faces.size(); ++f) {
      const Triangle& t = mesh.faces[f];
      const Vec3 &a = sphere[t[0]], &b = sphere[t[1]], &c = sphere[t[2]];
      // The view a triangle faces: the sign of the z of its normal. Seen from
      // −z, x is mirrored so that both views show the outside of the sphere.
      const double nz = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
      const int view = nz >= 0 ? 0 : 1;
      const double mirror = view == 0 ? 1 : -1;
      const bool bad = !std::isfinite(log_ratio[f]);
      has_bad_faces = has_bad_faces || bad;
      const std::string& colour = bad ? fold_colour : colour_of_log_ratio(log_ratio[f]);
      text << "<polygon points=\"";
      for(int k = 0; k < 3; ++k) {
        text.fixed2(cx[view] + mirror * sphere[t[k]][0] * disc_radius) << ',';
        text.fixed2(cy - sphere[t[k]][1] * disc_radius) << (k < 2 ? " " : "");
      }
      text << "\" fill=\"" << colour << "\" stroke=\"" << colour << "\"/>\n";
    }
    text << "</g>\n";
  }
  write_colour_bar(out, 4 * disc_margin + 4 * disc_radius + 10, disc_top + 40, 240, has_bad_faces, false);
  out << "</svg>\n";
}

} // namespace dlf_cli
