// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The triangles of a large mesh as one picture: an SVG of a polygon per face
// grows by about 90 bytes a face, so beyond a face budget (`--svg-max-faces`)
// the pictures rasterise their triangles into a PNG (libpng) embedded as an
// `<image>`; the colour bar, outlines and text stay vector.

#ifndef DLF_CLI_SVG_RASTER_H
#define DLF_CLI_SVG_RASTER_H

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace dlf_cli {

/// Pixels a unit of the pictures' rasterised faces: 1520 a side of the layout,
/// 1200 a sphere's disc; sharp when zoomed in twice.
constexpr double svg_raster_pixels = 2;

class Triangle_raster
{
public:
  /// A transparent canvas covering [x, x + width] × [y, y + height] of the
  /// picture's coordinates at `pixels_per_unit` pixels a unit.
  Triangle_raster(double x, double y, double width, double height, double pixels_per_unit);

  /// Fills the pixels whose centre lies in the triangle (a, b, c) with
  /// `colour` ("#rrggbb"), darkened by `shade` (0: none, 1: black) mixed in.
  void fill(const double a[2], const double b[2], const double c[2], const std::string& colour, double shade = 0);

  /// The `<image>` element, its PNG inline (base64), drawn at the canvas's
  /// place; with `id` when not empty.
  void write_image(std::ostream& out, const std::string& id = std::string()) const;

private:
  double m_x, m_y, m_width, m_height, m_scale;
  int m_columns, m_rows;
  std::vector<std::uint8_t> m_rgba;
};

} // namespace dlf_cli

#endif
