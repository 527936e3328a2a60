// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Tetrahedral meshes of the volumetric flow: the soup (points and tets), its
// checks (indices, exact orientation, manifoldness, a topological ball) and
// its border surface.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_VOLUME_MESH_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_VOLUME_MESH_H

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_options.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/geometry.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// A tetrahedron by its four vertex indices, positively oriented:
/// `CGAL::orientation(p0, p1, p2, p3) == POSITIVE`, i.e. det[p1 − p0, p2 − p0, p3 − p0] > 0.
typedef std::array<int, 4> Tet;

/// Six times the signed volume of (a, b, c, d), in doubles (difference form).
inline double tet_det(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d)
{
  return dot(sub(b, a), cross(sub(c, a), sub(d, a)));
}

/// The exact orientation of (a, b, c, d) (CGAL's filtered predicate on the doubles).
inline Orientation exact_tet_orientation(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d)
{
  typedef Exact_predicates_inexact_constructions_kernel::Point_3 P;
  return CGAL::orientation(P(a[0], a[1], a[2]), P(b[0], b[1], b[2]), P(c[0], c[1], c[2]), P(d[0], d[1], d[2]));
}

/// The face of a positively oriented tet opposite its corner k, oriented
/// with its normal pointing away from that corner (outwards).
inline std::array<int, 3> outward_face(const Tet& t, int k)
{
  switch(k) {
  case 0: return {{ t[1], t[2], t[3] }};
  case 1: return {{ t[0], t[3], t[2] }};
  case 2: return {{ t[0], t[1], t[3] }};
  default: return {{ t[0], t[2], t[1] }};
  }
}

/// Counts of the tets that the exact predicate finds negative or flat.
struct Tet_orientation_counts
{
  std::size_t negative = 0, flat = 0;
  int first_bad = -1; ///< the first tet that is not positive, −1 if none
  std::size_t not_positive() const { return negative + flat; }
};

inline Tet_orientation_counts count_bad_tets(const std::vector<Vec3>& x, const std::vector<Tet>& tets)
{
  Tet_orientation_counts c;
  for(std::size_t t = 0; t < tets.size(); ++t) {
    const Tet& k = tets[t];
    const Orientation o = exact_tet_orientation(x[std::size_t(k[0])], x[std::size_t(k[1])], x[std::size_t(k[2])],
                                                x[std::size_t(k[3])]);
    if(o == POSITIVE) continue;
    if(o == NEGATIVE) ++c.negative; else ++c.flat;
    if(c.first_bad < 0) c.first_bad = int(t);
  }
  return c;
}

/// The topology of a checked ball: which vertices lie on the border, and the
/// border's triangles (outward, from the tets' orientation).
struct Ball_topology
{
  std::vector<std::array<int, 3> > border_faces;
  std::vector<int> border_tet; ///< per border face, the tet it bounds
  std::vector<char> on_border; ///< per vertex
  std::vector<std::pair<int, int> > edges; ///< every edge once, (i < j)
  std::size_t border_vertices = 0;
};

/// The soup's own faults, in this order: no tets, a non-finite coordinate,
/// an index out of range or repeated in a tet, a vertex of no tet, a tet
/// not positive by the exact predicate. `OK`, or the code with `message`.
inline int check_tet_soup(const std::vector<Vec3>& x, const std::vector<Tet>& tets, std::string& message)
{
  const std::size_t V = x.size();
  if(tets.empty()) { message = "the mesh has no tetrahedra"; return ERROR_EMPTY_MESH; }
  for(std::size_t v = 0; v < V; ++v)
    for(int c = 0; c < 3; ++c)
      if(!std::isfinite(x[v][std::size_t(c)])) {
        message = "vertex " + std::to_string(v) + " has a non-finite coordinate";
        return ERROR_DEGENERATE_INPUT;
      }
  std::vector<char> used(V, 0);
  for(std::size_t t = 0; t < tets.size(); ++t) {
    const Tet& k = tets[t];
    for(int a = 0; a < 4; ++a) {
      if(k[std::size_t(a)] < 0 || std::size_t(k[std::size_t(a)]) >= V) {
        message = "tetrahedron " + std::to_string(t) + " refers to vertex " + std::to_string(k[std::size_t(a)]) +
                  ", out of range [0, " + std::to_string(V) + ")";
        return ERROR_WRONG_PARAMETER;
      }
      for(int b = 0; b < a; ++b)
        if(k[std::size_t(a)] == k[std::size_t(b)]) {
          message = "tetrahedron " + std::to_string(t) + " repeats vertex " + std::to_string(k[std::size_t(a)]);
          return ERROR_DEGENERATE_INPUT;
        }
      used[std::size_t(k[std::size_t(a)])] = 1;
    }
  }
  for(std::size_t v = 0; v < V; ++v)
    if(!used[v]) {
      message = "vertex " + std::to_string(v) + " belongs to no tetrahedron";
      return ERROR_WRONG_PARAMETER;
    }
  for(std::size_t t = 0; t < tets.size(); ++t) {
    const Tet& k = tets[t];
    const Orientation o = exact_tet_orientation(x[std::size_t(k[0])], x[std::size_t(k[1])], x[std::size_t(k[2])],
                                                x[std::size_t(k[3])]);
    if(o == COPLANAR) {
      message = "tetrahedron " + std::to_string(t) + " is degenerate (its four vertices are coplanar)";
      return ERROR_DEGENERATE_INPUT;
    }
    if(o == NEGATIVE) {
      message = "tetrahedron " + std::to_string(t) + " is inverted (negatively oriented by the exact predicate)";
      return ERROR_DEGENERATE_INPUT;
    }
  }
  return OK;
}

/// The triangles of the tets, each in one (border) or two tets: the border
/// faces (outward), their tets and vertices into `topo`, the number of
/// distinct triangles into `triangles`. `OK`, or the code with `message`.
inline int collect_ball_faces(std::size_t V, const std::vector<Tet>& tets, Ball_topology& topo,
                              std::size_t& triangles, std::string& message)
{
  struct Face_key { std::array<int, 3> v; int tet, corner; };
  std::vector<Face_key> faces;
  faces.reserve(4 * tets.size());
  for(std::size_t t = 0; t < tets.size(); ++t)
    for(int k = 0; k < 4; ++k) {
      std::array<int, 3> f = outward_face(tets[t], k);
      std::sort(f.begin(), f.end());
      faces.push_back({ f, int(t), k });
    }
  std::sort(faces.begin(), faces.end(), [](const Face_key& a, const Face_key& b) {
    return a.v != b.v ? a.v < b.v : a.tet < b.tet; });
  topo.on_border.assign(V, 0);
  triangles = 0;
  for(std::size_t i = 0; i < faces.size();) {
    std::size_t j = i + 1;
    while(j < faces.size() && faces[j].v == faces[i].v) ++j;
    if(j - i > 2) {
      message = "triangle (" + std::to_string(faces[i].v[0]) + ", " + std::to_string(faces[i].v[1]) + ", " +
                std::to_string(faces[i].v[2]) + ") is shared by " + std::to_string(j - i) +
                " tetrahedra (non-manifold; tetrahedra " + std::to_string(faces[i].tet) + " and " +
                std::to_string(faces[i + 1].tet) + " among them)";
      return ERROR_NO_TOPOLOGICAL_BALL;
    }
    if(j - i == 2 && faces[i].tet == faces[i + 1].tet) {
      message = "tetrahedron " + std::to_string(faces[i].tet) + " is duplicated";
      return ERROR_NO_TOPOLOGICAL_BALL;
    }
    if(j - i == 1) {
      const Face_key& f = faces[i];
      topo.border_faces.push_back(outward_face(tets[std::size_t(f.tet)], f.corner));
      topo.border_tet.push_back(f.tet);
      for(int v : f.v) topo.on_border[std::size_t(v)] = 1;
    }
    ++triangles;
    i = j;
  }
  return OK;
}

/// Every edge of the tets once, (i < j), sorted.
inline void collect_ball_edges(const std::vector<Tet>& tets, std::vector<std::pair<int, int> >& E)
{
  E.reserve(6 * tets.size());
  for(const Tet& k : tets)
    for(int a = 0; a < 4; ++a)
      for(int b = a + 1; b < 4; ++b)
        E.emplace_back((std::min)(k[std::size_t(a)], k[std::size_t(b)]), (std::max)(k[std::size_t(a)], k[std::size_t(b)]));
  std::sort(E.begin(), E.end());
  E.erase(std::unique(E.begin(), E.end()), E.end());
}

/// The border's directed edges (from, to, face), sorted, and the search of one.
class Ball_border_halfedges
{
public:
  explicit Ball_border_halfedges(const std::vector<std::array<int, 3> >& faces)
  {
    he.reserve(3 * faces.size());
    for(std::size_t f = 0; f < faces.size(); ++f)
      for(int k = 0; k < 3; ++k)
        he.push_back({{ faces[f][std::size_t(k)], faces[f][std::size_t((k + 1) % 3)], int(f) }});
    std::sort(he.begin(), he.end());
  }
  /// The index of the directed edge (a, b), −1 if none.
  int find(int a, int b) const
  {
    const std::array<int, 3> key = {{ a, b, -1 }};
    auto it = std::lower_bound(he.begin(), he.end(), key);
    return (it != he.end() && (*it)[0] == a && (*it)[1] == b) ? int(it - he.begin()) : -1;
  }
  std::vector<std::array<int, 3> > he;
};

/// The border surface closed and edge-manifold: every directed edge once,
/// and its twin present. `OK`, or the code with `message`.
inline int check_border_closed(const Ball_border_halfedges& H, std::string& message)
{
  const std::vector<std::array<int, 3> >& he = H.he;
  for(std::size_t i = 0; i + 1 < he.size(); ++i)
    if(he[i][0] == he[i + 1][0] && he[i][1] == he[i + 1][1]) {
      message = "the border is not a manifold surface: its edge (" + std::to_string(he[i][0]) + ", " +
                std::to_string(he[i][1]) + ") is used by more than two border triangles";
      return ERROR_NO_TOPOLOGICAL_BALL;
    }
  for(const auto& h : he)
    if(H.find(h[1], h[0]) < 0) {
      message = "the border is not closed at its edge (" + std::to_string(h[0]) + ", " + std::to_string(h[1]) + ")";
      return ERROR_NO_TOPOLOGICAL_BALL;
    }
  return OK;
}

/// Each border vertex a single fan: its outgoing border edges form one
/// cycle (walk around by the faces' next edges). `OK`, or the code with `message`.
inline int check_border_fans(std::size_t V, const std::vector<std::array<int, 3> >& faces,
                             const Ball_border_halfedges& H, std::string& message)
{
  const std::vector<std::array<int, 3> >& he = H.he;
  std::vector<int> out_degree(V, 0);
  for(const auto& h : he) ++out_degree[std::size_t(h[0])];
  std::vector<char> done(V, 0);
  for(std::size_t i = 0; i < he.size(); ++i) {
    const int v = he[i][0];
    if(done[std::size_t(v)]) continue;
    done[std::size_t(v)] = 1;
    // Walk from halfedge i around v: the next outgoing edge is the twin of
    // the face's edge entering v.
    int count = 0, h = int(i);
    do {
      ++count;
      const std::array<int, 3>& f = faces[std::size_t(he[std::size_t(h)][2])];
      int prev = -1;
      for(int k = 0; k < 3; ++k)
        if(f[std::size_t((k + 1) % 3)] == v) prev = f[std::size_t(k)];
      h = H.find(v, prev); // the twin of (prev → v)
    } while(h != int(i) && h >= 0 && count <= out_degree[std::size_t(v)]);
    if(count != out_degree[std::size_t(v)]) {
      message = "the border is not a manifold surface at vertex " + std::to_string(v) +
                " (two or more fans of border triangles meet there)";
      return ERROR_NO_TOPOLOGICAL_BALL;
    }
  }
  return OK;
}

/// The number of connected components of the border (union-find over the
/// border faces' vertices).
inline std::size_t border_components(const Ball_topology& topo)
{
  const std::size_t V = topo.on_border.size();
  std::vector<int> parent(V);
  for(std::size_t v = 0; v < V; ++v) parent[v] = int(v);
  auto root = [&parent](int v) { while(parent[std::size_t(v)] != v) v = parent[std::size_t(v)] = parent[std::size_t(parent[std::size_t(v)])]; return v; };
  for(const auto& f : topo.border_faces)
    for(int k = 0; k < 2; ++k) parent[std::size_t(root(f[std::size_t(k)]))] = root(f[std::size_t(k + 1)]);
  std::size_t components = 0;
  for(std::size_t v = 0; v < V; ++v)
    if(topo.on_border[v] && root(int(v)) == int(v)) ++components;
  return components;
}

/// The border a connected sphere and the complex a ball, by their Euler
/// characteristics. `OK`, or the code with `message`.
inline int check_ball_topology(const Ball_topology& topo, std::size_t halfedges, std::size_t triangles,
                               std::size_t tets, std::string& message)
{
  const std::size_t components = border_components(topo);
  if(components != 1) {
    message = "the border has " + std::to_string(components) +
              " connected components; a ball has one (a cavity or a second body?)";
    return ERROR_NO_TOPOLOGICAL_BALL;
  }
  const long long Eb = (long long)(halfedges / 2);
  const long long chi_border = (long long)(topo.border_vertices) - Eb + (long long)(topo.border_faces.size());
  if(chi_border != 2) {
    message = "the border is a closed surface of genus " + std::to_string((2 - chi_border) / 2) +
              " (Euler characteristic " + std::to_string(chi_border) + "); a ball's border is a sphere";
    return ERROR_NO_TOPOLOGICAL_BALL;
  }
  const long long chi = (long long)(topo.on_border.size()) - (long long)(topo.edges.size()) + (long long)(triangles) -
                        (long long)(tets);
  if(chi != 1) {
    message = "the tetrahedra's Euler characteristic V - E + F - T is " + std::to_string(chi) +
              "; a ball's is 1 (a tunnel through the interior, or disconnected pieces?)";
    return ERROR_NO_TOPOLOGICAL_BALL;
  }
  return OK;
}

/// Checks a tet soup and fills `topo`: indices in range and distinct, finite
/// coordinates, every vertex in some tet, every tet positive by the exact
/// predicate, every triangle in at most two tets, the border a closed
/// connected genus-0 surface (vertex- and edge-manifold) and the complex's
/// Euler characteristic V − E + F − T = 1. On failure `message` names the
/// first offending element (0-based indices) and the code says what it is.
inline int check_ball(const std::vector<Vec3>& x, const std::vector<Tet>& tets, Ball_topology& topo,
                      std::string& message)
{
  int code = check_tet_soup(x, tets, message);
  if(code != OK) return code;
  topo = Ball_topology();
  std::size_t triangles = 0;
  code = collect_ball_faces(x.size(), tets, topo, triangles, message);
  if(code != OK) return code;
  collect_ball_edges(tets, topo.edges);
  const Ball_border_halfedges H(topo.border_faces);
  code = check_border_closed(H, message);
  if(code != OK) return code;
  std::size_t Vb = 0;
  for(char b : topo.on_border) Vb += std::size_t(b);
  topo.border_vertices = Vb;
  code = check_border_fans(x.size(), topo.border_faces, H, message);
  if(code != OK) return code;
  return check_ball_topology(topo, H.he.size(), triangles, tets.size(), message);
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
