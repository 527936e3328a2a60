// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Medit `.mesh` format of tetrahedral meshes (what CGAL's Mesh_3 writes
// with `CGAL::IO::output_to_medit`), read with errors that name the line, and
// written back with the border triangles.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_VOLUME_MEDIT_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_VOLUME_MEDIT_H

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_tet_mesh.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/volume/volume_mesh.h>

#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <istream>
#include <map>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// A tetrahedral mesh as a Medit file holds it (0-based indices here).
typedef Discrete_lie_flow_tet_mesh Medit_tet_mesh;

/// The reading of a Medit file: its tokens with their line numbers ('#'
/// starts a comment), read in order; each fault sets `error` to "line N: ...".
class Medit_reader
{
public:
  Medit_reader(std::istream& in, Medit_tet_mesh& mesh, std::string& error) : m_mesh(mesh), m_error(error)
  {
    std::string line;
    while(std::getline(in, line)) {
      ++m_line_no;
      const std::size_t hash = line.find('#');
      if(hash != std::string::npos) line.resize(hash);
      std::istringstream ls(line);
      std::string tok;
      while(ls >> tok) m_tokens.emplace_back(tok, m_line_no);
    }
  }

  bool read()
  {
    bool have_version = false, have_vertices = false, have_tets = false, ended = false;
    while(m_p < m_tokens.size() && !ended) {
      const std::string key = m_tokens[m_p].first;
      const std::size_t kp = m_p++;
      long long n = 0;
      if(key == "MeshVersionFormatted") {
        if(!read_int(n, "the format version")) return false;
        if(n != 1 && n != 2) return fail(kp, "MeshVersionFormatted " + std::to_string(n) + " is not supported (1 or 2)");
        have_version = true;
      } else if(key == "Dimension") {
        if(!read_int(n, "the dimension")) return false;
        if(n != 3) return fail(kp, "Dimension " + std::to_string(n) + ": a tetrahedral mesh needs 3");
      } else if(key == "Vertices") {
        if(have_vertices) return fail(kp, "a second Vertices section");
        if(!read_vertices(kp)) return false;
        have_vertices = true;
      } else if(key == "Tetrahedra") {
        if(have_tets) return fail(kp, "a second Tetrahedra section");
        if(!have_vertices) return fail(kp, "Tetrahedra before Vertices");
        if(!read_tets(kp)) return false;
        have_tets = true;
      } else if(key == "End") {
        ended = true;
      } else if(!skip_section(kp, key)) {
        return false;
      }
    }
    if(!have_version) return fail(0, "not a Medit mesh: no MeshVersionFormatted");
    if(!have_vertices) return fail(m_p, "no Vertices section");
    if(!have_tets) return fail(m_p, "no Tetrahedra section (a surface mesh? a volume map needs tetrahedra)");
    return true;
  }

private:
  bool fail(std::size_t i, const std::string& what)
  {
    m_error = "line " + std::to_string(i < m_tokens.size() ? m_tokens[i].second : m_line_no) + ": " + what;
    return false;
  }

  bool read_int(long long& v, const std::string& what)
  {
    if(m_p >= m_tokens.size()) return fail(m_p, "unexpected end of file, expected " + what);
    const std::string& s = m_tokens[m_p].first;
    char* end = nullptr;
    v = std::strtoll(s.c_str(), &end, 10);
    if(end == s.c_str() || *end != '\0') return fail(m_p, "expected " + what + ", found '" + s + "'");
    ++m_p;
    return true;
  }

  bool read_double(double& v, const std::string& what)
  {
    if(m_p >= m_tokens.size()) return fail(m_p, "unexpected end of file, expected " + what);
    const std::string& s = m_tokens[m_p].first;
    char* end = nullptr;
    v = std::strtod(s.c_str(), &end);
    if(end == s.c_str() || *end != '\0') return fail(m_p, "expected " + what + ", found '" + s + "'");
    if(!std::isfinite(v)) return fail(m_p, what + " is not finite ('" + s + "')");
    ++m_p;
    return true;
  }

  // A section's count is checked against the numbers left in the file
  // before anything is allocated (a short file announcing 10^9 vertices
  // would otherwise take gigabytes: a finding of the fuzzing target).
  bool fits(std::size_t kp, long long n, long long per_record, const std::string& what)
  {
    const long long left = (long long)(m_tokens.size() - m_p);
    if(n <= left / per_record) return true;
    return fail(kp, "the file announces " + std::to_string(n) + " " + what + ", more than the " +
                      std::to_string(left) + " numbers left in it can hold");
  }

  bool read_vertices(std::size_t kp)
  {
    long long n = 0;
    if(!read_int(n, "the number of vertices")) return false;
    if(n < 0 || n > 2000000000LL) return fail(kp, "bad number of vertices " + std::to_string(n));
    if(!fits(kp, n, 4, "vertices")) return false;
    m_mesh.points.resize(std::size_t(n));
    m_mesh.point_refs.resize(std::size_t(n));
    for(long long i = 0; i < n; ++i) {
      const std::string what = "vertex " + std::to_string(i + 1) + " of " + std::to_string(n);
      for(int c = 0; c < 3; ++c)
        if(!read_double(m_mesh.points[std::size_t(i)][std::size_t(c)], "coordinate " + std::to_string(c + 1) + " of " + what))
          return false;
      long long r = 0;
      if(!read_int(r, "the reference of " + what)) return false;
      m_mesh.point_refs[std::size_t(i)] = int(r);
    }
    return true;
  }

  bool read_tets(std::size_t kp)
  {
    long long n = 0;
    if(!read_int(n, "the number of tetrahedra")) return false;
    if(n < 0 || n > 2000000000LL) return fail(kp, "bad number of tetrahedra " + std::to_string(n));
    if(!fits(kp, n, 5, "tetrahedra")) return false;
    m_mesh.tets.resize(std::size_t(n));
    m_mesh.tet_refs.resize(std::size_t(n));
    for(long long i = 0; i < n; ++i) {
      const std::string what = "tetrahedron " + std::to_string(i + 1) + " of " + std::to_string(n);
      for(int c = 0; c < 4; ++c) {
        long long v = 0;
        const std::size_t vp = m_p;
        if(!read_int(v, "vertex index " + std::to_string(c + 1) + " of " + what)) return false;
        if(v < 1 || v > (long long)m_mesh.points.size())
          return fail(vp, what + " refers to vertex " + std::to_string(v) + ", out of range 1.." +
                            std::to_string(m_mesh.points.size()));
        m_mesh.tets[std::size_t(i)][std::size_t(c)] = int(v - 1);
      }
      long long r = 0;
      if(!read_int(r, "the reference of " + what)) return false;
      m_mesh.tet_refs[std::size_t(i)] = int(r);
    }
    return true;
  }

  // A section of known record size, read and ignored.
  bool skip_section(std::size_t kp, const std::string& key)
  {
    static const std::map<std::string, int> skipped = {
      { "Edges", 3 }, { "Triangles", 4 }, { "Quadrilaterals", 5 }, { "Hexahedra", 9 }, { "Prisms", 7 },
      { "Corners", 1 }, { "RequiredVertices", 1 }, { "Ridges", 1 }, { "RequiredEdges", 1 },
      { "RequiredTriangles", 1 }, { "Normals", 3 }, { "NormalAtVertices", 2 }, { "Tangents", 3 },
      { "TangentAtVertices", 2 } };
    const auto it = skipped.find(key);
    if(it == skipped.end()) return fail(kp, "unknown section '" + key + "'");
    long long n = 0;
    if(!read_int(n, "the number of " + key)) return false;
    if(n < 0) return fail(kp, "bad number of " + key);
    if(!fits(kp, n, it->second, key)) return false;
    for(long long i = 0; i < n * it->second; ++i) {
      double ignored;
      if(!read_double(ignored, "entry " + std::to_string(i / it->second + 1) + " of " + key)) return false;
    }
    return true;
  }

  Medit_tet_mesh& m_mesh;
  std::string& m_error;
  std::vector<std::pair<std::string, std::size_t> > m_tokens;
  std::size_t m_line_no = 0;
  std::size_t m_p = 0;
};

/// Reads a Medit `.mesh` file (ASCII). Sections other than Vertices and
/// Tetrahedra are read and ignored when their record size is known
/// (Triangles, Edges, Corners, ...). Returns false and sets `error` to
/// "line N: ..." on the first problem.
inline bool read_medit(std::istream& in, Medit_tet_mesh& mesh, std::string& error)
{
  mesh = Medit_tet_mesh();
  return Medit_reader(in, mesh, error).read();
}

/// Keeps only the vertices that some tet uses (CGAL's writer also lists the
/// triangulation's vertices outside the complex), in their order; returns
/// how many were dropped. `kept[i]` is the input index of output vertex i.
inline std::size_t drop_unused_vertices(Medit_tet_mesh& mesh, std::vector<int>& kept)
{
  std::vector<int> renum(mesh.points.size(), -1);
  for(const Tet& t : mesh.tets)
    for(int v : t) renum[std::size_t(v)] = 0;
  kept.clear();
  for(std::size_t v = 0; v < renum.size(); ++v)
    if(renum[v] == 0) { renum[v] = int(kept.size()); kept.push_back(int(v)); }
  const std::size_t dropped = mesh.points.size() - kept.size();
  if(dropped == 0) return 0;
  std::vector<Vec3> points(kept.size());
  std::vector<int> refs(kept.size());
  for(std::size_t i = 0; i < kept.size(); ++i) {
    points[i] = mesh.points[std::size_t(kept[i])];
    refs[i] = mesh.point_refs[std::size_t(kept[i])];
  }
  mesh.points.swap(points);
  mesh.point_refs.swap(refs);
  for(Tet& t : mesh.tets)
    for(int& v : t) v = renum[std::size_t(v)];
  return dropped;
}

/// Writes a tetrahedral mesh as Medit (17 significant digits, so that the
/// exact orientations survive a round trip), with its border triangles.
inline void write_medit(std::ostream& out, const std::vector<Vec3>& points, const std::vector<Tet>& tets,
                        const std::vector<int>& tet_refs, const std::vector<std::array<int, 3> >& border_faces)
{
  char buf[96];
  out << "MeshVersionFormatted 1\nDimension 3\nVertices\n" << points.size() << '\n';
  for(const Vec3& p : points) {
    std::snprintf(buf, sizeof buf, "%.17g %.17g %.17g 1\n", p[0], p[1], p[2]);
    out << buf;
  }
  out << "Triangles\n" << border_faces.size() << '\n';
  for(const auto& f : border_faces) out << f[0] + 1 << ' ' << f[1] + 1 << ' ' << f[2] + 1 << " 1\n";
  out << "Tetrahedra\n" << tets.size() << '\n';
  for(std::size_t t = 0; t < tets.size(); ++t)
    out << tets[t][0] + 1 << ' ' << tets[t][1] + 1 << ' ' << tets[t][2] + 1 << ' ' << tets[t][3] + 1 << ' '
        << (t < tet_refs.size() ? tet_refs[t] : 1) << '\n';
  out << "End\n";
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
