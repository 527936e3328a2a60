// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "svg_raster.h"
#include "cli_error.h"

#include <png.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace dlf_cli {

namespace {

void append_to_string(png_structp png, png_bytep data, png_size_t length)
{
  static_cast<std::string*>(png_get_io_ptr(png))->append(reinterpret_cast<const char*>(data), length);
}

void no_flush(png_structp) {}

// libpng reports errors by longjmp to png_jmpbuf: nothing with a destructor
// may live in this frame, hence the rows are made by the caller.
bool encode_rgba(png_structp png, png_infop info, std::string* out, int columns, int rows, png_byte** row_pointers)
{
  if(setjmp(png_jmpbuf(png))) return false;
  png_set_write_fn(png, out, &append_to_string, &no_flush);
  png_set_IHDR(png, info, png_uint_32(columns), png_uint_32(rows), 8, PNG_COLOR_TYPE_RGB_ALPHA, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_compression_level(png, 6);
  png_write_info(png, info);
  png_write_image(png, row_pointers);
  png_write_end(png, nullptr);
  return true;
}

std::string base64(const std::string& bytes)
{
  static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve(4 * ((bytes.size() + 2) / 3));
  for(std::size_t k = 0; k < bytes.size(); k += 3) {
    const std::size_t n = std::min<std::size_t>(3, bytes.size() - k);
    std::uint32_t v = 0;
    for(std::size_t j = 0; j < 3; ++j) v = v << 8 | (j < n ? std::uint8_t(bytes[k + j]) : 0u);
    for(std::size_t j = 0; j < 4; ++j) out += j <= n ? digits[(v >> (18 - 6 * j)) & 63] : '=';
  }
  return out;
}

} // namespace

Triangle_raster::Triangle_raster(double x, double y, double width, double height, double pixels_per_unit)
  : m_x(x), m_y(y), m_width(width), m_height(height), m_scale(pixels_per_unit),
    m_columns((std::max)(1, int(std::ceil(width * pixels_per_unit)))),
    m_rows((std::max)(1, int(std::ceil(height * pixels_per_unit)))),
    m_rgba(4 * std::size_t(m_columns) * std::size_t(m_rows), 0)
{}

void Triangle_raster::fill(const double a[2], const double b[2], const double c[2], const std::string& colour, double shade)
{
  const long rgb = std::strtol(colour.c_str() + 1, nullptr, 16);
  std::uint8_t pixel[4] = { std::uint8_t(rgb >> 16), std::uint8_t(rgb >> 8), std::uint8_t(rgb), 255 };
  for(int i = 0; i < 3; ++i) pixel[i] = std::uint8_t(std::lround((1 - shade) * pixel[i] + shade * 0x22));
  // In pixel units; a pixel (i, j) is sampled at its centre (i + ½, j + ½).
  const double px[3] = { (a[0] - m_x) * m_scale, (b[0] - m_x) * m_scale, (c[0] - m_x) * m_scale };
  const double py[3] = { (a[1] - m_y) * m_scale, (b[1] - m_y) * m_scale, (c[1] - m_y) * m_scale };
  const double area = (px[1] - px[0]) * (py[2] - py[0]) - (py[1] - py[0]) * (px[2] - px[0]);
  if(area == 0 || !std::isfinite(area)) return;
  const double sign = area > 0 ? 1 : -1;
  const int i0 = (std::max)(0, int(std::floor(*std::min_element(px, px + 3))));
  const int i1 = (std::min)(m_columns - 1, int(std::ceil(*std::max_element(px, px + 3))));
  const int j0 = (std::max)(0, int(std::floor(*std::min_element(py, py + 3))));
  const int j1 = (std::min)(m_rows - 1, int(std::ceil(*std::max_element(py, py + 3))));
  for(int j = j0; j <= j1; ++j)
    for(int i = i0; i <= i1; ++i) {
      const double x = i + 0.5, y = j + 0.5;
      bool inside = true;
      for(int k = 0; k < 3 && inside; ++k) {
        const int l = (k + 1) % 3;
        inside = sign * ((px[l] - px[k]) * (y - py[k]) - (py[l] - py[k]) * (x - px[k])) >= 0;
      }
      if(inside) std::copy(pixel, pixel + 4, &m_rgba[4 * (std::size_t(j) * std::size_t(m_columns) + std::size_t(i))]);
    }
}

void Triangle_raster::write_image(std::ostream& out, const std::string& id) const
{
  std::vector<png_byte*> rows(static_cast<std::size_t>(m_rows));
  std::vector<std::uint8_t> pixels = m_rgba; // libpng takes non-const rows
  for(int j = 0; j < m_rows; ++j) rows[std::size_t(j)] = &pixels[4 * std::size_t(j) * std::size_t(m_columns)];
  std::string png_bytes;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  const bool ok = info && encode_rgba(png, info, &png_bytes, m_columns, m_rows, rows.data());
  png_destroy_write_struct(&png, &info);
  if(!ok) throw Cli_error("cannot encode the PNG of the SVG's triangles (libpng failed)");
  out << "<image" << (id.empty() ? "" : " id=\"" + id + "\"") << " x=\"" << m_x << "\" y=\"" << m_y << "\" width=\""
      << m_width << "\" height=\"" << m_height << "\" preserveAspectRatio=\"none\" xlink:href=\"data:image/png;base64,"
      << base64(png_bytes) << "\"/>\n";
}

} // namespace dlf_cli
