// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "texture_output.h"
#include "cli_error.h"
#include "obj_io.h"
#include "text_buffer.h"

#include <png.h>

#include <algorithm>
#include <filesystem>

namespace dlf_cli {

namespace {

void write_to_stream(png_structp png, png_bytep data, png_size_t length)
{
  static_cast<std::ostream*>(png_get_io_ptr(png))->write(reinterpret_cast<const char*>(data), std::streamsize(length));
}

void flush_stream(png_structp png) { static_cast<std::ostream*>(png_get_io_ptr(png))->flush(); }

// libpng reports errors by longjmp to png_jmpbuf: nothing with a destructor
// may live in this frame, hence the rows are made by the caller.
bool encode_png(png_structp png, png_infop info, std::ostream* out, int size, int squares, png_byte** rows)
{
  if(setjmp(png_jmpbuf(png))) return false;
  png_set_write_fn(png, out, &write_to_stream, &flush_stream);
  png_set_IHDR(png, info, png_uint_32(size), png_uint_32(size), 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  // Flat colours compress well with the "up" filter and a fast level.
  png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_UP);
  png_set_compression_level(png, 3);
  png_write_info(png, info);
  for(int y = 0; y < size; ++y) png_write_row(png, rows[long(y) * squares / size]);
  png_write_end(png, nullptr);
  return true;
}

} // namespace

Texture_paths texture_paths(const std::string& obj_path)
{
  std::filesystem::path p(obj_path);
  if(p.extension() != ".obj" || p.stem().empty())
    throw Cli_error("--texture expects a file name ending in .obj (it also writes .mtl and .png beside it), got '" +
                    obj_path + "'");
  Texture_paths t;
  t.obj = obj_path;
  t.mtl = p.replace_extension(".mtl").string();
  t.png = p.replace_extension(".png").string();
  return t;
}

std::vector<Vec2> unit_square_uv(const std::vector<Vec2>& uv)
{
  if(uv.empty()) return uv;
  double x0 = uv[0][0], x1 = x0, y0 = uv[0][1], y1 = y0;
  for(const Vec2& p : uv) {
    x0 = std::min(x0, p[0]); x1 = std::max(x1, p[0]);
    y0 = std::min(y0, p[1]); y1 = std::max(y1, p[1]);
  }
  const double extent = std::max(x1 - x0, y1 - y0);
  const double s = extent > 0 ? 1. / extent : 1.;
  std::vector<Vec2> out(uv.size());
  for(std::size_t i = 0; i < uv.size(); ++i) out[i] = {{ (uv[i][0] - x0) * s, (uv[i][1] - y0) * s }};
  return out;
}

void write_textured_obj(std::ostream& out, const std::vector<Vec3>& xyz, const std::vector<Vec2>& uv,
                        const std::vector<Triangle>& faces, const std::string& mtl_file, const std::string& comment,
                        const std::vector<Triangle>& uv_faces)
{
  Text_buffer text(out);
  if(!comment.empty()) text << "# " << comment << "\n";
  text << "mtllib " << mtl_file << "\n";
  write_obj_vertices(text, xyz, uv);
  text << "usemtl dlf_checker\n";
  write_obj_faces(text, faces, uv_faces.empty() ? faces : uv_faces);
}

void write_checker_mtl(std::ostream& out, const std::string& png_file)
{
  // Ambient and diffuse white, no specular: the texture's colours as they are.
  out << "newmtl dlf_checker\n"
         "Ka 1 1 1\n"
         "Kd 1 1 1\n"
         "Ks 0 0 0\n"
         "d 1\n"
         "illum 1\n"
         "map_Kd " << png_file << "\n";
}

void write_checker_png(std::ostream& out, int size, int squares)
{
  // One row per square row is enough: rows within a square are equal.
  std::vector<std::vector<png_byte> > rows(std::size_t(squares), std::vector<png_byte>(3 * std::size_t(size)));
  for(int j = 0; j < squares; ++j)
    for(int x = 0; x < size; ++x) {
      const int i = int(long(x) * squares / size);
      png_byte* p = &rows[std::size_t(j)][3 * std::size_t(x)];
      if((i + j) % 2 == 0) { p[0] = p[1] = p[2] = 245; continue; }
      // Red grows with u, green with v (texture row 0 is v = 1).
      p[0] = png_byte(40 + 180 * i / std::max(1, squares - 1));
      p[1] = png_byte(40 + 180 * (squares - 1 - j) / std::max(1, squares - 1));
      p[2] = 150;
    }

  std::vector<png_byte*> row_pointers;
  for(std::vector<png_byte>& r : rows) row_pointers.push_back(r.data());
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  const bool ok = info && encode_png(png, info, &out, size, squares, row_pointers.data());
  png_destroy_write_struct(&png, &info);
  if(!ok) throw Cli_error("cannot write the texture PNG (out of memory?)");
}

} // namespace dlf_cli
