// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The atlas's surface in index form: triangles, their halfedges and twins,
// connected components, opening along a seam (one vertex per wedge), and
// the topology (border loops, Euler characteristic, genus) of a piece.
// Halfedge 3f + k runs from corner k of face f to corner k + 1.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_ATLAS_MESH_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_ATLAS_MESH_H

#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/geometry.h>

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// A triangle mesh in index form with, per face, the caller's face (its
/// index among all faces) and, per corner, the caller's corner 3·f + k.
struct Atlas_piece
{
  std::vector<Vec3> xyz;
  std::vector<Face> faces;
  std::vector<std::size_t> caller_face; ///< per face
  std::vector<double> density;          ///< per face ρ (> 0), empty for ρ ≡ 1
};

inline std::size_t next_in_face(std::size_t h) { return h - h % 3 + (h % 3 + 1) % 3; }
inline std::size_t prev_in_face(std::size_t h) { return h - h % 3 + (h % 3 + 2) % 3; }

/// The twin of every halfedge, −1 on a border. A directed edge met twice
/// (inconsistent orientation) or an edge of more than two faces is left
/// without twin: the surface is opened there rather than misread.
inline std::vector<long> halfedge_twins(const std::vector<Face>& faces)
{
  // Halfedges bucketed by their source vertex (counting sort): each lookup
  // scans one vertex's few outgoing halfedges, where a hash table of all
  // directed edges cost a fifth of a million-face atlas.
  const std::size_t H = 3 * faces.size();
  std::vector<long> twin(H, -1);
  std::size_t n = 0;
  for(const Face& t : faces)
    for(int v : t) n = (std::max)(n, std::size_t(v) + 1);
  std::vector<std::size_t> first(n + 1, 0);
  for(const Face& t : faces)
    for(int v : t) ++first[std::size_t(v) + 1];
  for(std::size_t v = 0; v < n; ++v) first[v + 1] += first[v];
  std::vector<std::size_t> out(H), fill(first.begin(), first.end() - 1);
  for(std::size_t h = 0; h < H; ++h) out[fill[std::size_t(faces[h / 3][h % 3])]++] = h;
  auto head = [&faces](std::size_t h) { return faces[h / 3][(h % 3 + 1) % 3]; };
  // The halfedges a → b: the one there is, or −2 when repeated, −1 when none.
  auto find = [&](int a, int b) {
    long found = -1;
    for(std::size_t i = first[std::size_t(a)]; i < first[std::size_t(a) + 1]; ++i)
      if(head(out[i]) == b) found = found == -1 ? long(out[i]) : -2;
    return found;
  };
  for(std::size_t h = 0; h < H; ++h) {
    if(twin[h] != -1) continue;
    const int a = faces[h / 3][h % 3], b = head(h);
    if(find(a, b) < 0) continue; // a → b repeated
    const long o = find(b, a);
    if(o >= 0) { twin[h] = o; twin[std::size_t(o)] = long(h); }
  }
  return twin;
}

/// Connected components of the faces across twinned halfedges: a component
/// index per face, and the number of components.
inline std::size_t face_components(const std::vector<Face>& faces, const std::vector<long>& twin,
                                   std::vector<int>& component)
{
  component.assign(faces.size(), -1);
  std::size_t count = 0;
  std::vector<std::size_t> stack;
  for(std::size_t f0 = 0; f0 < faces.size(); ++f0) {
    if(component[f0] >= 0) continue;
    component[f0] = int(count);
    stack.assign(1, f0);
    while(!stack.empty()) {
      const std::size_t f = stack.back();
      stack.pop_back();
      for(std::size_t k = 0; k < 3; ++k) {
        const long o = twin[3 * f + k];
        if(o >= 0 && component[std::size_t(o) / 3] < 0) {
          component[std::size_t(o) / 3] = int(count);
          stack.push_back(std::size_t(o) / 3);
        }
      }
    }
    ++count;
  }
  return count;
}

/// Opens `P` along the halfedges with `seam[h]` set (both halves of an
/// edge): the corners of a vertex that can reach one another across
/// uncut edges share one new vertex, so a vertex on k seam edges becomes
/// k vertices, and a non-manifold vertex one vertex per wedge. Returns the
/// new vertex of every corner; `P.xyz` and `P.faces` are replaced.
inline std::vector<int> open_along(Atlas_piece& P, const std::vector<long>& twin, const std::vector<char>& seam)
{
  const std::size_t H = 3 * P.faces.size();
  std::vector<int> wedge(H, -1);
  std::vector<Vec3> xyz;
  std::vector<std::size_t> stack;
  for(std::size_t c0 = 0; c0 < H; ++c0) {
    if(wedge[c0] >= 0) continue;
    const int id = int(xyz.size());
    xyz.push_back(P.xyz[std::size_t(P.faces[c0 / 3][c0 % 3])]);
    wedge[c0] = id;
    stack.assign(1, c0);
    while(!stack.empty()) {
      // Corner c of a vertex v: its outgoing halfedge is c, its incoming one prev(c).
      const std::size_t c = stack.back();
      stack.pop_back();
      const std::size_t out = c, in = prev_in_face(c);
      if(twin[in] >= 0 && !seam[in]) { // across v's incoming edge: the twin leaves v
        const std::size_t d = std::size_t(twin[in]);
        if(wedge[d] < 0) { wedge[d] = id; stack.push_back(d); }
      }
      if(twin[out] >= 0 && !seam[out]) { // across v's outgoing edge: the twin enters v
        const std::size_t d = next_in_face(std::size_t(twin[out]));
        if(wedge[d] < 0) { wedge[d] = id; stack.push_back(d); }
      }
    }
  }
  for(std::size_t f = 0; f < P.faces.size(); ++f)
    for(std::size_t k = 0; k < 3; ++k) P.faces[f][k] = wedge[3 * f + k];
  P.xyz.swap(xyz);
  return wedge;
}

/// The topology of a connected manifold piece (every vertex one wedge,
/// as `open_along` leaves it): its border loops, as halfedge lists in
/// order, and its Euler characteristic χ = V − E + F = 2 − 2g − loops.
struct Piece_topology
{
  std::vector<std::vector<std::size_t> > loops; ///< border halfedges of each loop, in order
  long euler = 0;
  long genus() const { return (2 - euler - long(loops.size())) / 2; }
  bool disk() const { return loops.size() == 1 && euler == 1; }
};

inline Piece_topology piece_topology(const Atlas_piece& P, const std::vector<long>& twin)
{
  Piece_topology T;
  const std::size_t H = 3 * P.faces.size();
  std::size_t border = 0;
  // On a manifold piece a border vertex starts exactly one border halfedge.
  std::vector<long> border_from(P.xyz.size(), -1);
  for(std::size_t h = 0; h < H; ++h)
    if(twin[h] < 0) { ++border; border_from[std::size_t(P.faces[h / 3][h % 3])] = long(h); }
  std::vector<char> used(H, 0);
  for(std::size_t h0 = 0; h0 < H; ++h0) {
    if(twin[h0] >= 0 || used[h0]) continue;
    T.loops.emplace_back();
    for(long h = long(h0); h >= 0 && !used[std::size_t(h)];) {
      used[std::size_t(h)] = 1;
      T.loops.back().push_back(std::size_t(h));
      h = border_from[std::size_t(P.faces[std::size_t(h) / 3][(std::size_t(h) % 3 + 1) % 3])];
    }
  }
  std::vector<char> seen(P.xyz.size(), 0);
  long V = 0;
  for(const Face& t : P.faces)
    for(int v : t)
      if(!seen[std::size_t(v)]) { seen[std::size_t(v)] = 1; ++V; }
  const long E = long((H + border) / 2);
  T.euler = V - E + long(P.faces.size());
  return T;
}

/// The faces of `P` with all three corners on its border (the flow's floor:
/// such a triangle cannot take its target shape and area together).
inline std::size_t three_border_corner_faces(const Atlas_piece& P, const std::vector<long>& twin)
{
  std::vector<char> on_border(P.xyz.size(), 0);
  for(std::size_t h = 0; h < twin.size(); ++h)
    if(twin[h] < 0) {
      on_border[std::size_t(P.faces[h / 3][h % 3])] = 1;
      on_border[std::size_t(P.faces[h / 3][(h % 3 + 1) % 3])] = 1;
    }
  std::size_t n = 0;
  for(const Face& t : P.faces)
    if(on_border[std::size_t(t[0])] && on_border[std::size_t(t[1])] && on_border[std::size_t(t[2])]) ++n;
  return n;
}

/// The sub-piece of the faces `keep` (indices into `P.faces`), its vertices
/// renumbered in order of first use.
inline Atlas_piece sub_piece(const Atlas_piece& P, const std::vector<std::size_t>& keep)
{
  Atlas_piece S;
  std::vector<int> index(P.xyz.size(), -1);
  for(std::size_t f : keep) {
    Face t = P.faces[f];
    for(int& v : t) {
      if(index[std::size_t(v)] < 0) { index[std::size_t(v)] = int(S.xyz.size()); S.xyz.push_back(P.xyz[std::size_t(v)]); }
      v = index[std::size_t(v)];
    }
    S.faces.push_back(t);
    S.caller_face.push_back(P.caller_face[f]);
    if(!P.density.empty()) S.density.push_back(P.density[f]);
  }
  return S;
}

/// The pieces of `P`, one per connected component, each opened at its
/// non-manifold vertices.
inline std::vector<Atlas_piece> split_components(const Atlas_piece& P)
{
  const std::vector<long> twin = halfedge_twins(P.faces);
  std::vector<int> component;
  const std::size_t n = face_components(P.faces, twin, component);
  std::vector<std::vector<std::size_t> > members(n);
  for(std::size_t f = 0; f < P.faces.size(); ++f) members[std::size_t(component[f])].push_back(f);
  std::vector<Atlas_piece> out;
  for(const std::vector<std::size_t>& m : members) {
    out.push_back(sub_piece(P, m));
    const std::vector<long> t = halfedge_twins(out.back().faces);
    open_along(out.back(), t, std::vector<char>(t.size(), 0));
  }
  return out;
}

/// Σ ρ·area over the faces of `P`.
inline double piece_area(const Atlas_piece& P)
{
  double a = 0;
  for(std::size_t f = 0; f < P.faces.size(); ++f)
    a += (P.density.empty() ? 1. : P.density[f]) *
         triangle_area_3(P.xyz[std::size_t(P.faces[f][0])], P.xyz[std::size_t(P.faces[f][1])], P.xyz[std::size_t(P.faces[f][2])]);
  return a;
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
