// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "cli_util.h"
#include "mesh_input.h"
#include "cli_error.h"

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <locale>
#include <map>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace dlf_cli {

namespace {

typedef CGAL::Simple_cartesian<double>::Point_3 Soup_point;
typedef std::vector<std::size_t> Polygon;


void check_triangles(const std::vector<Polygon>& polygons, const std::string& name)
{
  std::size_t bad = 0, first = 0;
  for(std::size_t f = 0; f < polygons.size(); ++f)
    if(polygons[f].size() != 3 && bad++ == 0) first = f;
  if(bad == 0) {
    for(std::size_t f = 0; f < polygons.size(); ++f) {
      const Polygon& p = polygons[f];
      if(p[0] == p[1] || p[1] == p[2] || p[2] == p[0])
        throw Cli_error(name + ": face " + std::to_string(f) + " uses vertex " +
                        std::to_string(p[0] == p[1] || p[0] == p[2] ? p[0] : p[1]) + " twice");
    }
    return;
  }
  std::ostringstream s;
  s << name << ": " << bad << " of " << polygons.size() << " faces are not triangles (first: face " << first
    << " with " << polygons[first].size() << " vertices); triangulate the mesh first, or 'dlf atlas' triangulates it";
  throw Cli_error(s.str());
}

// Unreferenced vertices would have no uv; rather than invent one (and break
// "vt i is the uv of input vertex i"), refuse them.
void check_referenced(std::size_t n, const std::vector<Polygon>& polygons, const std::string& name)
{
  std::vector<bool> used(n, false);
  for(const Polygon& p : polygons)
    for(std::size_t i : p) used[i] = true;
  const std::size_t unused = std::size_t(std::count(used.begin(), used.end(), false));
  if(unused == 0) return;
  std::ostringstream s;
  s << name << ": " << unused << (unused == 1 ? " vertex is" : " vertices are") << " not used by any face (first: vertex "
    << std::size_t(std::find(used.begin(), used.end(), false) - used.begin()) << "); remove them first";
  throw Cli_error(s.str());
}

bool has_off_extension(const std::string& path)
{
  if(path.size() < 4) return false;
  std::string ext = path.substr(path.size() - 4);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext == ".off";
}

bool has_ply_extension(const std::string& path)
{
  if(path.size() < 4) return false;
  std::string ext = path.substr(path.size() - 4);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext == ".ply";
}

// A header word as a message shows it: at most 32 characters, a byte that
// is not printable ASCII as \xNN.
std::string shown(const std::string& word)
{
  static const char hex[] = "0123456789abcdef";
  std::string out;
  for(std::size_t i = 0; i < word.size() && i < 32; ++i) {
    const unsigned char c = static_cast<unsigned char>(word[i]);
    if(c >= 0x20 && c < 0x7f) out += char(c);
    else out += std::string("\\x") + hex[c >> 4] + hex[c & 15];
  }
  return word.size() > 32 ? out + "..." : out;
}

bool is_ply_scalar_type(const std::string& type)
{
  static const char* const types[] = { "char", "uchar", "short", "ushort", "int", "uint", "float", "double",
                                       "int8", "uint8", "int16", "uint16", "int32", "uint32", "float32", "float64" };
  return std::find(std::begin(types), std::end(types), type) != std::end(types);
}

struct Ply_element
{
  std::string name, where;
  std::uint64_t count = 0;
  std::uint64_t properties = 0;
};

void check_ply_counts(const std::vector<Ply_element>& elements, std::uint64_t bytes_left)
{
  std::uint64_t needed = 0;
  for(const Ply_element& e : elements) {
    const std::uint64_t per_item = std::max<std::uint64_t>(1, e.properties);
    if(e.count > bytes_left / per_item || needed > bytes_left - e.count * per_item)
      throw Cli_error(e.where + "element '" + shown(e.name) + "' announces " + std::to_string(e.count) +
                      " items, more than the " + std::to_string(bytes_left) +
                      " bytes after the header can hold (at least a byte per property of an item)");
    needed += e.count * per_item;
  }
}

// CGAL 5.5's PLY reader misbehaves on some headers (findings of
// fuzz/dlf_fuzz.cpp), which are refused here first:
//  - a property before any element: it takes the last element of an empty
//    list (undefined behaviour);
//  - a vertex coordinate (x, y, z) that is not a float or a double, or a list:
//    it casts the property to a float and dereferences the null result;
//  - a halfedge's source or target that is not a uint (same cast);
//  - a property of a type PLY does not have: it is skipped, and each item of
//    its element is then read from nothing, so an element's count is all
//    that bounds the loop (a 180-byte file announcing 21,474,836,476
//    vertices pushed default points until memory ran out). Every item takes
//    at least a byte per property, so the counts must fit in the file;
//  - no end_header line: the reader goes on regardless (a garbled
//    'property' keyword left a vertex element with none, read the same way).
void check_ply_header(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::string line;
  std::vector<Ply_element> elements;
  for(std::size_t number = 1; std::getline(in, line); ++number) {
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    const std::string where = quoted(path) + ", line " + std::to_string(number) + ": ";
    if(keyword == "end_header") {
      const std::streamoff header = in.tellg();
      in.seekg(0, std::ios::end);
      const std::streamoff size = in.tellg();
      check_ply_counts(elements, header >= 0 && size >= header ? std::uint64_t(size - header) : 0);
      return;
    }
    if(keyword == "element") {
      Ply_element e;
      std::string count;
      words >> e.name >> count;
      e.where = where;
      const char* end = count.data() + count.size();
      if(count.empty() || std::from_chars(count.data(), end, e.count).ptr != end)
        throw Cli_error(where + "element '" + shown(e.name) + "' has the count '" + shown(count) +
                        "' (a PLY element's count is a whole number)");
      elements.push_back(e);
    }
    if(keyword != "property") continue;
    if(elements.empty())
      throw Cli_error(where + "a PLY 'property' before any 'element' (not a valid PLY header)");
    const std::string& element_name = elements.back().name;
    ++elements.back().properties;
    std::string type, name;
    words >> type;
    if(type == "list") {
      std::string size_type, item_type;
      words >> size_type >> item_type;
      if(!is_ply_scalar_type(size_type) || !is_ply_scalar_type(item_type))
        throw Cli_error(where + "a list of '" + shown(item_type) + "' counted by '" + shown(size_type) +
                        "' (not PLY types: char, uchar, short, ushort, int, uint, float, double and their sized names)");
    } else if(!is_ply_scalar_type(type)) {
      throw Cli_error(where + "a property of type '" + shown(type) +
                      "' (not a PLY type: char, uchar, short, ushort, int, uint, float, double and their sized names)");
    }
    words >> name;
    const bool vertex = element_name == "vertex" || element_name == "vertices";
    if(vertex && (name == "x" || name == "y" || name == "z") &&
       type != "float" && type != "float32" && type != "double" && type != "float64")
      throw Cli_error(where + "vertex coordinate '" + name + "' declared as '" + type +
                      "' (a PLY vertex coordinate must be a float or a double)");
    if(element_name == "halfedge" && (name == "source" || name == "target") &&
       type != "uint" && type != "uint32")
      throw Cli_error(where + "halfedge '" + name + "' declared as '" + type +
                      "' (a PLY halfedge's source and target must be uint)");
  }
  throw Cli_error(quoted(path) + ": the PLY header has no 'end_header' line (not a valid PLY header)");
}

// OFF files are read here rather than by CGAL's reader, which a small
// malformed file makes misbehave (findings of fuzz/dlf_fuzz.cpp, CGAL 5.5):
//  - it resizes its arrays to the header's counts, and a face to the count
//    at the start of its line, before reading them, so "OFF 2000000000
//    2000000000 0" asks for ~100 GB; a negative face size is converted from
//    double to std::size_t (UB, then std::length_error);
//  - it reads colours, texture coordinates and normals past the values of a
//    line that has fewer numbers than the header announces (heap reads out
//    of bounds, an uninitialised index for textures), and converts
//    out-of-range colours to unsigned char (UB).
// The text format is parsed with CGAL's conventions (header keyword
// [ST][C][N][4][n]OFF, '#' comments, one vertex or face per line, extra
// numbers on a line ignored: the tool needs no colours, normals or texture
// coordinates). Binary OFF is read here too (CGAL's binary header overflowed
// an int on a large edge count, and a face size of 10⁹ made it allocate
// gigabytes: fuzz findings); its variants with colours, normals or texture
// coordinates are refused with a message. Returns false when the file is not
// valid OFF.
class Off_text_reader
{
public:
  explicit Off_text_reader(const std::string& text) : m_text(text) {}

  bool read(const std::string& path, std::vector<Soup_point>& points, std::vector<Polygon>& polygons)
  {
    skip_blanks_and_comments();
    const std::string keyword = word();
    std::size_t j = 0;
    if(keyword.compare(0, 2, "ST") == 0) j += 2;
    if(j < keyword.size() && keyword[j] == 'C') ++j;
    if(j < keyword.size() && keyword[j] == 'N') ++j;
    const bool homogeneous = j < keyword.size() && keyword[j] == '4';
    if(homogeneous) ++j;
    const bool dimensional = j < keyword.size() && keyword[j] == 'n';
    if(dimensional) ++j;
    if(keyword.compare(j, std::string::npos, "OFF") != 0) return false;
    skip_blanks_and_comments();
    if(m_text.compare(m_pos, 6, "BINARY") == 0) {
      if(j != 0)
        throw Cli_error(quoted(path) + ": binary " + keyword + " (with colours, normals, texture coordinates or other "
                        "dimensions) is not read; plain binary OFF and every text OFF are");
      return read_binary(path, points, polygons);
    }

    long long dimension = 3, nv = -1, nf = -1, ne = -1;
    if(dimensional && !integer(dimension)) return false;
    if(dimension != 3 || !integer(nv) || !integer(nf) || !integer(ne) || nv < 0 || nf < 0) return false;
    // A vertex line takes at least 6 bytes ("0 0 0\n"), a face line 2.
    check_counts(path, nv, nf, 6. * double(nv) + 2. * double(nf));

    points.reserve(std::size_t(nv));
    std::vector<double> values;
    for(long long i = 0; i < nv; ++i) {
      if(!line(values) || values.size() < (homogeneous ? 4u : 3u)) return false;
      const double w = homogeneous ? values[3] : 1.;
      if(w == 0) return false;
      points.push_back(Soup_point(values[0] / w, values[1] / w, values[2] / w));
    }
    polygons.reserve(std::size_t(nf));
    for(long long f = 0; f < nf; ++f) {
      if(!line(values) || values.empty()) return false;
      // The size, then as many vertex indices; what follows (a colour) is ignored.
      const double k = values[0];
      if(!(k >= 0 && k < double(values.size())) || k != std::floor(k)) return false;
      Polygon polygon(static_cast<std::size_t>(k));
      for(std::size_t c = 0; c < polygon.size(); ++c) {
        const double i = values[c + 1];
        if(!(i >= 0 && i < double(nv)) || i != std::floor(i)) return false;
        polygon[c] = static_cast<std::size_t>(i);
      }
      polygons.push_back(polygon);
    }
    return true;
  }

private:
  void skip_blanks_and_comments()
  {
    for(;;) {
      while(m_pos < m_text.size() && std::isspace(static_cast<unsigned char>(m_text[m_pos]))) ++m_pos;
      if(m_pos >= m_text.size() || m_text[m_pos] != '#') return;
      m_pos = (std::min)(m_text.find('\n', m_pos), m_text.size());
    }
  }

  std::string word()
  {
    const std::size_t start = m_pos;
    while(m_pos < m_text.size() && std::isalnum(static_cast<unsigned char>(m_text[m_pos]))) ++m_pos;
    return m_text.substr(start, m_pos - start);
  }

  bool integer(long long& n)
  {
    skip_blanks_and_comments();
    std::size_t end = m_pos;
    if(end < m_text.size() && (m_text[end] == '-' || m_text[end] == '+')) ++end;
    const std::size_t digits = end;
    while(end < m_text.size() && std::isdigit(static_cast<unsigned char>(m_text[end]))) ++end;
    if(end == digits) return false;
    // More than 18 digits cannot be a count that fits in memory: saturate.
    n = end - digits > 18 ? 999999999999999999LL : std::stoll(m_text.substr(digits, end - digits));
    if(m_text[m_pos] == '-') n = -n;
    m_pos = end;
    return true;
  }

  // The numbers of the next line that is neither blank nor a comment, up to
  // a '#' or the first token that is not a number (as `istream >> double`
  // reads them: an optional sign, no "inf" or "nan"; a number out of the
  // range of double ends the line too).
  bool line(std::vector<double>& values)
  {
    skip_blanks_and_comments();
    if(m_pos >= m_text.size()) return false;
    const std::size_t end = (std::min)(m_text.find('\n', m_pos), m_text.size());
    const char* p = m_text.data() + m_pos;
    const char* const stop = m_text.data() + end;
    m_pos = end;
    values.clear();
    for(;;) {
      while(p < stop && (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\v' || *p == '\f')) ++p;
      if(p == stop || *p == '#') return true;
      const char* q = p;
      if(*q == '+' || *q == '-') ++q;
      // Only digits or a point may start the magnitude: from_chars would take "inf" and "nan".
      if(q == stop || !(std::isdigit(static_cast<unsigned char>(*q)) || *q == '.')) return true;
      double x = 0;
      const std::from_chars_result r = std::from_chars(q, stop, x);
      if(r.ec != std::errc()) return true;
      values.push_back(*p == '-' ? -x : x);
      p = r.ptr;
    }
  }

  // Plain binary OFF (Geomview's layout): after the header line, big-endian
  // 32-bit counts (vertices, faces, edges), three floats per vertex, and per
  // face its size, its indices and a colour count followed by that many
  // floats (ignored). Every count is checked against the bytes left before
  // anything is allocated.
  bool read_binary(const std::string& path, std::vector<Soup_point>& points, std::vector<Polygon>& polygons)
  {
    std::size_t at = m_text.find('\n', m_pos);
    if(at == std::string::npos) return false;
    ++at;
    auto left = [&]() { return m_text.size() - at; };
    auto word32 = [&](std::uint32_t& u) {
      if(left() < 4) return false;
      u = 0;
      for(int b = 0; b < 4; ++b) u = (u << 8) | static_cast<unsigned char>(m_text[at++]);
      return true;
    };
    auto integer32 = [&](long long& n) {
      std::uint32_t u = 0;
      if(!word32(u)) return false;
      n = static_cast<std::int32_t>(u);
      return true;
    };
    long long nv = 0, nf = 0, ne = 0;
    if(!integer32(nv) || !integer32(nf) || !integer32(ne) || nv < 0 || nf < 0) return false;
    // A vertex takes 12 bytes (three floats), a face at least 8 (its size and colour count).
    check_counts(path, nv, nf, 12. * double(nv) + 8. * double(nf));
    points.reserve(std::size_t(nv));
    for(long long i = 0; i < nv; ++i) {
      float c[3];
      for(float& x : c) {
        std::uint32_t u = 0;
        if(!word32(u)) return false;
        std::memcpy(&x, &u, sizeof x);
      }
      points.push_back(Soup_point(c[0], c[1], c[2]));
    }
    polygons.reserve(std::size_t(nf));
    for(long long f = 0; f < nf; ++f) {
      long long k = 0, colours = 0;
      if(!integer32(k) || k < 0 || double(k) * 4 > double(left())) return false;
      Polygon polygon(static_cast<std::size_t>(k));
      for(std::size_t& i : polygon) {
        long long v = 0;
        if(!integer32(v) || v < 0 || v >= nv) return false;
        i = static_cast<std::size_t>(v);
      }
      if(!integer32(colours) || colours < 0 || double(colours) * 4 > double(left())) return false;
      at += 4 * static_cast<std::size_t>(colours);
      polygons.push_back(std::move(polygon));
    }
    return true;
  }

  void check_counts(const std::string& path, long long nv, long long nf, double bytes) const
  {
    if(bytes > double(m_text.size()))
      throw Cli_error(quoted(path) + ": the header announces " + std::to_string(nv) + " vertices and " +
                      std::to_string(nf) + " faces, more than the file's " + std::to_string(m_text.size()) +
                      " bytes can hold");
  }

  const std::string& m_text;
  std::size_t m_pos = 0;
};

bool read_off_soup(const std::string& path, std::vector<Soup_point>& points, std::vector<Polygon>& polygons)
{
  std::ifstream in(path, std::ios::binary);
  std::string text;
  // One read of the whole file when its size is known (a regular file),
  // else character by character (a pipe).
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  in.seekg(0, std::ios::beg);
  if(size > 0 && in) {
    text.resize(std::size_t(size));
    in.read(&text[0], std::streamsize(size));
    text.resize(std::size_t(in.gcount()));
  } else {
    in.clear();
    in.seekg(0, std::ios::beg);
    text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  return Off_text_reader(text).read(path, points, polygons);
}

// Whether a soup of triangles (each of 3 distinct vertices) is a
// consistently oriented manifold mesh: no directed edge used twice, and the
// faces around each vertex form one fan. The same test as CGAL's
// is_polygon_soup_a_polygon_mesh(), by sorting instead of trees of pairs
// (a few seconds at millions of faces); false sends the soup to CGAL's
// orientation, which decides.
bool is_oriented_manifold(std::size_t n, const std::vector<Polygon>& triangles)
{
  std::vector<std::uint64_t> directed;
  directed.reserve(3 * triangles.size());
  for(const Polygon& t : triangles)
    for(int k = 0; k < 3; ++k) directed.push_back((std::uint64_t(t[std::size_t(k)]) << 32) | std::uint64_t(t[std::size_t((k + 1) % 3)]));
  std::sort(directed.begin(), directed.end());
  if(std::adjacent_find(directed.begin(), directed.end()) != directed.end()) return false;
  std::vector<std::uint64_t>().swap(directed);
  // Around vertex v, face (v, a, b) links a to b; with no directed edge
  // twice, the links form paths and cycles, and one fan is one of them.
  std::vector<std::size_t> first(n + 1, 0);
  for(const Polygon& t : triangles)
    for(std::size_t v : t) ++first[v + 1];
  for(std::size_t v = 0; v < n; ++v) first[v + 1] += first[v];
  std::vector<std::pair<std::size_t, std::size_t> > link(first[n]);
  std::vector<std::size_t> fill(first.begin(), first.end() - 1);
  for(const Polygon& t : triangles)
    for(std::size_t k = 0; k < 3; ++k) link[fill[t[k]]++] = { t[(k + 1) % 3], t[(k + 2) % 3] };
  std::vector<char> seen;
  for(std::size_t v = 0; v < n; ++v) {
    const std::size_t b = first[v], e = first[v + 1];
    if(e - b < 2) continue;
    // Start at the link whose start no other link ends at (a border fan), else anywhere (a closed one).
    std::size_t start = b;
    for(std::size_t i = b; i < e; ++i) {
      bool continues = false;
      for(std::size_t j = b; j < e && !continues; ++j) continues = link[j].second == link[i].first;
      if(!continues) { start = i; break; }
    }
    seen.assign(e - b, 0);
    std::size_t walked = 0;
    for(std::size_t i = start; i != e && !seen[i - b]; ) {
      seen[i - b] = 1;
      ++walked;
      std::size_t next = e;
      for(std::size_t j = b; j < e; ++j)
        if(link[j].first == link[i].second) { next = j; break; }
      i = next;
    }
    if(walked != e - b) return false;
  }
  return true;
}


// Every command reads a mesh file through here: OFF by the tool's own
// reader, a PLY header checked first, the rest by CGAL's; whatever a reader
// throws is the file's fault (CGAL 5.5's PLY reader resizes a list to the
// count it reads, so a negative or huge count throws: a fuzzing finding).
bool read_soup(const std::string& path, std::vector<Soup_point>& points, std::vector<Polygon>& polygons)
{
  if(!std::ifstream(path))
    throw Cli_error(quoted(path) + ": cannot open (no such file, or not readable)");
  if(has_ply_extension(path)) check_ply_header(path);
  try {
    return has_off_extension(path) ? read_off_soup(path, points, polygons)
                                   : CGAL::IO::read_polygon_soup(path, points, polygons);
  } catch(const std::exception& e) {
    throw Cli_error(quoted(path) + ": cannot read as a mesh (the reader failed: " + e.what() + ")");
  }
}

} // namespace

bool read_polygon_soup(const std::string& path, std::vector<Vec3>& xyz, std::vector<std::vector<std::size_t> >& polygons)
{
  std::vector<Soup_point> points;
  const bool ok = read_soup(path, points, polygons);
  xyz.clear();
  xyz.reserve(points.size());
  for(const Soup_point& p : points) xyz.push_back({{ p.x(), p.y(), p.z() }});
  return ok;
}

bool is_oriented_manifold_soup(std::size_t n, const std::vector<std::vector<std::size_t> >& triangles)
{
  return is_oriented_manifold(n, triangles);
}

Indexed_mesh read_triangle_mesh(const std::string& path)
{
  std::vector<Soup_point> points;
  std::vector<Polygon> polygons;
  // The soup reader, not PMP::IO::read_polygon_mesh(): the latter's repair
  // step merges duplicate points and drops isolated ones, which renumbers
  // vertices, and every output of the tool must keep the input's numbering.
  if(!read_soup(path, points, polygons))
    throw Cli_error(quoted(path) + ": cannot read as a mesh (CGAL reads .off, .obj, .ply, .stl, .ts, .vtp)");
  std::vector<Vec3> xyz;
  xyz.reserve(points.size());
  for(const Soup_point& p : points) xyz.push_back({{ p.x(), p.y(), p.z() }});
  return checked_triangle_mesh(std::move(xyz), std::move(polygons), quoted(path));
}

Indexed_mesh checked_triangle_mesh(std::vector<Vec3> xyz, std::vector<std::vector<std::size_t> > polygons,
                                   const std::string& name)
{
  if(polygons.empty())
    throw Cli_error(name + ": the mesh has no faces");
  for(std::size_t i = 0; i < xyz.size(); ++i)
    if(!std::isfinite(xyz[i][0]) || !std::isfinite(xyz[i][1]) || !std::isfinite(xyz[i][2]))
      throw Cli_error(name + ": vertex " + std::to_string(i) + " has a non-finite coordinate");
  for(std::size_t f = 0; f < polygons.size(); ++f)
    for(std::size_t i : polygons[f])
      if(i >= xyz.size())
        throw Cli_error(name + ": face " + std::to_string(f) + " refers to vertex " + std::to_string(i) +
                        " of " + std::to_string(xyz.size()));
  check_triangles(polygons, name);
  check_referenced(xyz.size(), polygons, name);

  if(!is_oriented_manifold(xyz.size(), polygons)) {
    // Only an inconsistently oriented mesh gets here; orienting flips some
    // faces but keeps the order, unless it must duplicate non-manifold
    // vertices, which would renumber.
    std::vector<Soup_point> points;
    points.reserve(xyz.size());
    for(const Vec3& p : xyz) points.emplace_back(p[0], p[1], p[2]);
    const std::size_t n = points.size(), mesh_faces = polygons.size();
    CGAL::Polygon_mesh_processing::orient_polygon_soup(points, polygons);
    if(points.size() != n || polygons.size() != mesh_faces || !CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(polygons))
      throw Cli_error(name + ": the mesh is not manifold (an edge has more than two faces, or a vertex "
                      "joins separate fans); 'dlf atlas' splits its non-manifold vertices");
  }

  Indexed_mesh mesh;
  mesh.xyz = std::move(xyz);
  mesh.faces.reserve(polygons.size());
  for(const Polygon& p : polygons) mesh.faces.push_back({{ int(p[0]), int(p[1]), int(p[2]) }});
  return mesh;
}

namespace {

// An edge as one sortable key: `a` in the high half, `b` in the low one.
std::uint64_t edge_key(int a, int b) { return (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b); }
int key_first(std::uint64_t k) { return int(k >> 32); }
int key_second(std::uint64_t k) { return int(k & 0xffffffffu); }

} // namespace

std::vector<Border_loop> border_loops(const std::vector<Vec3>& xyz, const std::vector<Triangle>& faces)
{
  // Undirected edges used by one face (sorted keys rather than a tree of
  // pairs: millions of faces); on a manifold border every border vertex has
  // two border neighbours, and the loops are walked from their smallest
  // vertex index.
  std::vector<std::uint64_t> undirected;
  undirected.reserve(3 * faces.size());
  for(const Triangle& t : faces)
    for(int k = 0; k < 3; ++k) {
      const std::pair<int, int> e = std::minmax(t[k], t[(k + 1) % 3]);
      undirected.push_back(edge_key(e.first, e.second));
    }
  std::sort(undirected.begin(), undirected.end());
  // Both directions of each border edge, grouped by vertex (stable: the
  // neighbours of a vertex keep the order of the sorted edges).
  std::vector<std::pair<int, int> > around;
  for(std::size_t i = 0; i < undirected.size(); ) {
    std::size_t j = i;
    while(j < undirected.size() && undirected[j] == undirected[i]) ++j;
    if(j - i == 1) {
      around.emplace_back(key_first(undirected[i]), key_second(undirected[i]));
      around.emplace_back(key_second(undirected[i]), key_first(undirected[i]));
    }
    i = j;
  }
  std::vector<std::uint64_t>().swap(undirected);
  std::stable_sort(around.begin(), around.end(),
                   [](const std::pair<int, int>& x, const std::pair<int, int>& y) { return x.first < y.first; });
  std::vector<std::size_t> first(xyz.size() + 1, 0); // around[first[v] .. first[v + 1]) are v's
  for(const auto& e : around) ++first[std::size_t(e.first) + 1];
  for(std::size_t v = 0; v < xyz.size(); ++v) first[v + 1] += first[v];
  std::vector<Border_loop> loops;
  std::vector<char> walked(xyz.size(), 0);
  for(std::size_t e0 = 0; e0 < around.size(); e0 = first[std::size_t(around[e0].first) + 1]) {
    const int start = around[e0].first;
    if(walked[std::size_t(start)]) continue;
    Border_loop loop;
    for(int previous = -1, v = start; v >= 0 && !walked[std::size_t(v)]; ) {
      walked[std::size_t(v)] = 1;
      loop.vertices.push_back(v);
      int next = -1;
      for(std::size_t e = first[std::size_t(v)]; e < first[std::size_t(v) + 1]; ++e) {
        const int w = around[e].second;
        if(w != previous && !walked[std::size_t(w)]) { next = w; break; }
      }
      previous = v;
      v = next;
    }
    const std::size_t n = loop.vertices.size();
    for(std::size_t k = 0; k < n; ++k) {
      const Vec3 &a = xyz[std::size_t(loop.vertices[k])], &b = xyz[std::size_t(loop.vertices[(k + 1) % n])];
      loop.length += std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
    }
    loops.push_back(loop);
  }
  std::stable_sort(loops.begin(), loops.end(), [](const Border_loop& x, const Border_loop& y) { return x.length > y.length; });
  return loops;
}

std::vector<Border_loop> check_disk_topology(const Indexed_mesh& mesh, const std::string& path)
{
  const std::size_t V = mesh.xyz.size(), F = mesh.faces.size();
  // Directed edges; a border edge is one whose reverse is absent.
  std::vector<std::uint64_t> directed;
  directed.reserve(3 * F);
  for(const Triangle& t : mesh.faces)
    for(int k = 0; k < 3; ++k) directed.push_back(edge_key(t[k], t[(k + 1) % 3]));
  std::sort(directed.begin(), directed.end());
  directed.erase(std::unique(directed.begin(), directed.end()), directed.end());
  std::size_t E = 0;
  for(std::uint64_t e : directed) {
    const int a = key_first(e), b = key_second(e);
    if(a < b || !std::binary_search(directed.begin(), directed.end(), edge_key(b, a))) ++E;
  }
  std::vector<std::uint64_t>().swap(directed);
  std::vector<Border_loop> loops = border_loops(mesh.xyz, mesh.faces);
  Union_find uf(V);
  for(const Triangle& t : mesh.faces) { uf.unite(std::size_t(t[0]), std::size_t(t[1])); uf.unite(std::size_t(t[1]), std::size_t(t[2])); }
  std::size_t components = 0;
  for(std::size_t i = 0; i < V; ++i)
    if(uf.find(i) == i) ++components;
  const long euler = long(V) - long(E) + long(F);
  // χ = 2 − 2g − b for a connected orientable surface with b border loops:
  // a disk (b = 1, χ = 1) or a disk with holes (χ = 2 − b).
  if(components == 1 && !loops.empty() && euler == 2 - long(loops.size())) return loops;

  // The reason first, then what fits instead.
  std::ostringstream s;
  s << quoted(path) << ": not a disk: ";
  const long twice_genus = 2 - long(loops.size()) - euler;
  const bool has_genus = twice_genus >= 0 && twice_genus % 2 == 0;
  if(components != 1) {
    s << components << " connected components (dlf disk maps one), " << loops.size() << " border loop"
      << (loops.size() == 1 ? "" : "s") << " in all, Euler characteristic " << euler
      << "; 'dlf atlas' maps every component";
  } else if(loops.empty()) {
    s << "a closed surface (no border loop) of ";
    if(has_genus) s << "genus " << twice_genus / 2 << " (Euler characteristic " << euler << ")";
    else s << "Euler characteristic " << euler;
    s << "; dlf disk needs a border: "
      << (twice_genus == 0 ? "'dlf sphere' maps it onto the sphere, 'dlf atlas' cuts it into disks"
                           : "cut it open, or 'dlf atlas' cuts it into disks");
  } else {
    if(has_genus) s << "genus " << twice_genus / 2 << " with ";
    else s << "Euler characteristic " << euler << " with ";
    s << loops.size() << " border loop" << (loops.size() == 1 ? "" : "s");
    if(has_genus) s << " (Euler characteristic " << euler << ")";
    s << "; dlf disk takes genus 0 (the loops past the first are holes), 'dlf atlas' cuts it into disks";
  }
  throw Cli_error(s.str());
}

} // namespace dlf_cli
