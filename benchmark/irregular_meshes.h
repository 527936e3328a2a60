// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Irregular closed meshes made reproducibly from CGAL's data set, for the
// spherical flow's "large irregular meshes" benchmark: scanned models come
// with slivers, triangle strips and face areas spanning decades, which
// subdivided data-set meshes do not have. Each operation keeps the mesh a
// closed, oriented, genus-0 triangle mesh with the same surface (up to the
// decimation's approximation), and is deterministic (its own random stream,
// fixed seed):
//  - jitterK: every vertex moved in its tangent plane by up to K% of its
//    distance to the opposite edges of its star (never past them: every face
//    keeps its orientation), in random directions; K = 90 gives min angles
//    near 1° and face areas spanning three decades;
//  - decimateK: random-order edge collapses down to K% of the faces
//    (CGAL::Surface_mesh_simplification, edge-length cost, so the collapses
//    are where the edges are short, midpoint placement): uneven sizes;
//  - needlesK: a maximal matching of edges, each matched edge split at K
//    points spaced geometrically (segments spanning a factor 10), both
//    adjacent triangles split into fans of needles at them (as triangle
//    strips converted to triangles are); with jitter, min angles near 1°.
// Spec syntax, after the file and its subdivision: MESH+loop1+jitter90+needles4.

#ifndef DLF_BENCHMARK_IRREGULAR_MESHES_H
#define DLF_BENCHMARK_IRREGULAR_MESHES_H

#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_ratio_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Edge_length_cost.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Midpoint_placement.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace dlf_benchmark {

/// Uniform double in [0, 1) from the 32-bit Mersenne twister (whose output
/// sequence the standard fixes, unlike its distributions').
inline double unit_random(std::mt19937& rng) { return double(rng()) / 4294967296.0; }

/// One irregularising operation of a spec: "jitter", "decimate" or "needles" and its K.
struct Irregular_step
{
  std::string what;
  int k = 0;
};

/// Splits "MESH+loop1+jitter90+needles4" into the spec of the mesh and its
/// subdivision ("MESH+loop1") and the irregularising steps after it; false,
/// with `why`, for an unknown step.
inline bool split_irregular_spec(const std::string& spec, std::string& base, std::vector<Irregular_step>& steps,
                                 std::string& why)
{
  steps.clear();
  base.clear();
  std::size_t begin = 0;
  bool first = true;
  while(begin <= spec.size()) {
    const std::size_t plus = spec.find('+', begin);
    const std::string part = spec.substr(begin, plus == std::string::npos ? std::string::npos : plus - begin);
    bool irregular = false;
    for(const char* name : { "jitter", "decimate", "needles" })
      if(!first && part.rfind(name, 0) == 0) {
        const std::string digits = part.substr(std::string(name).size());
        if(digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos) {
          why = "'" + part + "': " + name + " needs a number";
          return false;
        }
        steps.push_back(Irregular_step{ name, std::atoi(digits.c_str()) });
        irregular = true;
      }
    if(!irregular) {
      if(!steps.empty()) { why = "'" + part + "' after an irregularising step"; return false; }
      base += (first ? "" : "+") + part;
    }
    first = false;
    if(plus == std::string::npos) break;
    begin = plus + 1;
  }
  for(const Irregular_step& s : steps)
    if((s.what == "jitter" && (s.k <= 0 || s.k >= 100)) || (s.what == "decimate" && (s.k <= 0 || s.k >= 100)) ||
       (s.what == "needles" && (s.k <= 0 || s.k > 64))) {
      why = s.what + std::to_string(s.k) + " out of range";
      return false;
    }
  return true;
}

namespace irregular_detail {

template <class P> typename CGAL::Kernel_traits<P>::Kernel::Vector_3 face_normal(const P& a, const P& b, const P& c)
{
  return CGAL::cross_product(b - a, c - a);
}

} // namespace irregular_detail

/// jitterK (see the top of this file).
template <class Point>
void jitter_vertices(CGAL::Surface_mesh<Point>& mesh, int percent, unsigned seed = 1)
{
  typedef CGAL::Surface_mesh<Point> Mesh;
  typedef typename CGAL::Kernel_traits<Point>::Kernel::Vector_3 Vector;
  typedef typename Mesh::Vertex_index Vertex;
  std::mt19937 rng(seed);
  const double s = percent / 100.;
  for(Vertex v : vertices(mesh)) {
    const Point p = mesh.point(v);
    // Normal of the star (area-weighted) and the distance to the link's edges.
    Vector n(0, 0, 0);
    double h = std::numeric_limits<double>::infinity();
    for(auto he : CGAL::halfedges_around_target(mesh.halfedge(v), mesh)) {
      if(mesh.is_border(he)) continue;
      const Point& a = mesh.point(mesh.source(he));
      const Point& b = mesh.point(mesh.target(mesh.next(he)));
      n = n + irregular_detail::face_normal(a, p, b); // face (a, p, b) in mesh order
      // Distance from p to the line ab.
      const Vector ab = b - a;
      const double l2 = ab.squared_length();
      if(l2 > 0) h = (std::min)(h, std::sqrt(CGAL::cross_product(p - a, ab).squared_length() / l2));
    }
    const double nl = std::sqrt(n.squared_length());
    if(!(nl > 0) || !std::isfinite(h)) continue;
    n = n / nl;
    // A random tangent direction.
    Vector t = std::abs(n.x()) < 0.9 ? CGAL::cross_product(n, Vector(1, 0, 0)) : CGAL::cross_product(n, Vector(0, 1, 0));
    t = t / std::sqrt(t.squared_length());
    const Vector u = CGAL::cross_product(n, t);
    const double angle = 2 * CGAL_PI * unit_random(rng), r = s * h * std::sqrt(unit_random(rng));
    const Vector d = t * (r * std::cos(angle)) + u * (r * std::sin(angle));
    // Keep the move only if every face of the star keeps its orientation
    // (its normal within 90° of the old one).
    const Point q = p + d;
    bool ok = true;
    for(auto he : CGAL::halfedges_around_target(mesh.halfedge(v), mesh)) {
      const Point& a = mesh.point(mesh.source(he));
      const Point& b = mesh.point(mesh.target(mesh.next(he)));
      if(!(irregular_detail::face_normal(a, q, b) * irregular_detail::face_normal(a, p, b) > 0)) { ok = false; break; }
    }
    if(ok) mesh.point(v) = q;
  }
}

/// decimateK (see the top of this file).
template <class Point>
void decimate_edges(CGAL::Surface_mesh<Point>& mesh, int percent)
{
  namespace SMS = CGAL::Surface_mesh_simplification;
  SMS::Count_ratio_stop_predicate<CGAL::Surface_mesh<Point> > stop(percent / 100.);
  SMS::edge_collapse(mesh, stop, CGAL::parameters::get_cost(SMS::Edge_length_cost<CGAL::Surface_mesh<Point> >())
                                     .get_placement(SMS::Midpoint_placement<CGAL::Surface_mesh<Point> >()));
  mesh.collect_garbage();
}

/// needlesK (see the top of this file).
template <class Point>
void needle_strips(CGAL::Surface_mesh<Point>& mesh, int k, unsigned seed = 2)
{
  typedef CGAL::Surface_mesh<Point> Mesh;
  typedef typename Mesh::Vertex_index Vertex;
  typedef typename Mesh::Halfedge_index Halfedge;
  std::mt19937 rng(seed);
  // A maximal matching of edges in random order: no face gets two split edges.
  std::vector<typename Mesh::Edge_index> order(edges(mesh).begin(), edges(mesh).end());
  for(std::size_t i = order.size(); i > 1; --i) std::swap(order[i - 1], order[std::size_t(rng() % i)]);
  std::vector<char> face_used(num_faces(mesh), 0);
  std::map<typename Mesh::Face_index, Halfedge> split_of; // face -> its split halfedge
  for(auto e : order) {
    const Halfedge h = mesh.halfedge(e), o = mesh.opposite(h);
    const auto f = mesh.face(h), g = mesh.face(o);
    if(face_used[std::size_t(f)] || face_used[std::size_t(g)]) continue;
    face_used[std::size_t(f)] = face_used[std::size_t(g)] = 1;
    split_of[f] = h;
    split_of[g] = o;
  }
  // Split points: geometric segment lengths spanning a factor 10, the small
  // end at a random side.
  std::vector<double> t(std::size_t(k) + 2);
  Mesh out;
  for(Vertex v : vertices(mesh)) out.add_vertex(mesh.point(v)); // same indices
  std::map<std::pair<Vertex, Vertex>, std::vector<Vertex> > points_of; // (source, target) -> interior points
  for(const auto& fh : split_of) {
    const Halfedge h = fh.second;
    const Vertex a = mesh.source(h), b = mesh.target(h);
    if(points_of.count(std::make_pair(b, a))) continue;
    const double ratio = std::pow(10., 1. / (std::max)(k, 1));
    double sum = 0, len = 1;
    std::vector<double> seg(std::size_t(k) + 1);
    for(double& x : seg) { x = len; sum += len; len *= ratio; }
    if(rng() % 2) std::reverse(seg.begin(), seg.end());
    std::vector<Vertex>& pts = points_of[std::make_pair(a, b)];
    double acc = 0;
    for(int i = 0; i < k; ++i) {
      acc += seg[std::size_t(i)] / sum;
      pts.push_back(out.add_vertex(mesh.point(a) + (mesh.point(b) - mesh.point(a)) * acc));
    }
  }
  for(auto f : faces(mesh)) {
    const auto it = split_of.find(f);
    if(it == split_of.end()) {
      std::vector<Vertex> vs;
      for(Vertex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) vs.push_back(v);
      out.add_face(vs);
      continue;
    }
    const Halfedge h = it->second;
    const Vertex a = mesh.source(h), b = mesh.target(h), c = mesh.target(mesh.next(h));
    std::vector<Vertex> chain{ a };
    const auto ab = points_of.find(std::make_pair(a, b));
    if(ab != points_of.end()) chain.insert(chain.end(), ab->second.begin(), ab->second.end());
    else {
      const std::vector<Vertex>& ba = points_of.at(std::make_pair(b, a));
      chain.insert(chain.end(), ba.rbegin(), ba.rend());
    }
    chain.push_back(b);
    for(std::size_t i = 0; i + 1 < chain.size(); ++i) out.add_face(chain[i], chain[i + 1], c);
  }
  mesh = std::move(out);
}

/// Applies `steps` in order.
template <class Point>
void make_irregular(CGAL::Surface_mesh<Point>& mesh, const std::vector<Irregular_step>& steps)
{
  for(const Irregular_step& s : steps) {
    if(s.what == "jitter") jitter_vertices(mesh, s.k);
    else if(s.what == "decimate") decimate_edges(mesh, s.k);
    else if(s.what == "needles") needle_strips(mesh, s.k);
  }
}

} // namespace dlf_benchmark

#endif
