// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The spherical flow's input in index form (independent of the mesh type),
// its validation (closed, connected, genus 0, non-degenerate), and the flat
// triangles between sphere points that the flow measures.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_SPHERE_PROBLEM_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_SPHERE_PROBLEM_H

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_options.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/area_elements.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/geometry.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/distortion.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// A closed genus-0 triangle mesh and its targets.
struct Sphere_problem
{
  std::vector<Vec3> xyz;       ///< input positions
  std::vector<Face> faces;     ///< input triangles (consistently oriented)
  std::vector<double> target;  ///< per face: ρ_f · area_M(f) > 0 (any common scale)
};

/// The verdict of a validation: `OK`, or a code and one line naming what was found.
struct Validation
{
  int code = OK;
  std::string message;
  bool ok() const { return code == OK; }
};

/// Checks that `faces` over `n` vertices form one closed, connected,
/// orientable surface of genus 0: every edge shared by exactly two faces
/// with opposite directions, one component, no isolated vertex, and Euler
/// characteristic V − E + F = 2.
inline Validation validate_sphere_topology(std::size_t n, const std::vector<Face>& faces)
{
  Validation r;
  if(faces.empty() || n == 0) { r.code = ERROR_EMPTY_MESH; r.message = "the mesh has no faces"; return r; }
  // Directed edges: a closed oriented surface has each directed edge once and
  // its opposite once.
  std::map<std::pair<int, int>, int> directed;
  std::size_t bad_face = faces.size();
  for(std::size_t f = 0; f < faces.size(); ++f) {
    const Face& t = faces[f];
    if(t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) { bad_face = (std::min)(bad_face, f); continue; }
    for(int k = 0; k < 3; ++k) ++directed[std::make_pair(t[k], t[(k + 1) % 3])];
  }
  if(bad_face < faces.size()) {
    r.code = ERROR_DEGENERATE_INPUT;
    r.message = "face " + std::to_string(bad_face) + " repeats a vertex";
    return r;
  }
  std::size_t border = 0, non_manifold = 0, undirected = 0;
  for(const auto& e : directed) {
    if(e.second > 1) ++non_manifold;
    const auto o = directed.find(std::make_pair(e.first.second, e.first.first));
    if(o == directed.end()) ++border;
    else if(e.first.first < e.first.second) ++undirected;
  }
  undirected += border;
  // Components over faces (union-find on vertices), and isolated vertices.
  std::vector<int> parent(n);
  for(std::size_t i = 0; i < n; ++i) parent[i] = int(i);
  auto find = [&parent](int x) {
    while(parent[std::size_t(x)] != x) { parent[std::size_t(x)] = parent[std::size_t(parent[std::size_t(x)])]; x = parent[std::size_t(x)]; }
    return x;
  };
  std::vector<bool> used(n, false);
  for(const Face& t : faces)
    for(int k = 0; k < 3; ++k) {
      used[std::size_t(t[k])] = true;
      parent[std::size_t(find(t[k]))] = find(t[(k + 1) % 3]);
    }
  std::size_t components = 0, isolated = 0;
  for(std::size_t i = 0; i < n; ++i) {
    if(!used[i]) { ++isolated; continue; }
    if(find(int(i)) == int(i)) ++components;
  }
  const long chi = long(n - isolated) - long(undirected) + long(faces.size());
  if(border != 0 || non_manifold != 0 || components != 1 || isolated != 0 || chi != 2) {
    // The reason first: what the mesh has that a sphere has not; the Euler
    // characteristic is the reason only for one closed manifold component.
    std::vector<std::string> reasons;
    if(components != 1) reasons.push_back(std::to_string(components) + (components == 1 ? " component" : " components"));
    if(border) reasons.push_back(std::to_string(border) + (border == 1 ? " border edge" : " border edges"));
    if(non_manifold) reasons.push_back(std::to_string(non_manifold) + " non-manifold or inconsistently oriented edges");
    if(isolated) reasons.push_back(std::to_string(isolated) + " isolated vertices");
    std::ostringstream s;
    s << "not a closed genus-0 surface: ";
    if(reasons.empty()) {
      if(chi < 2 && chi % 2 == 0) s << "a closed surface of genus " << (2 - chi) / 2 << " (Euler characteristic " << chi << ")";
      else s << "Euler characteristic " << chi;
      s << "; a sphere has genus 0, Euler characteristic 2";
    } else {
      for(std::size_t k = 0; k < reasons.size(); ++k) s << (k == 0 ? "" : k + 1 == reasons.size() ? " and " : ", ") << reasons[k];
      s << "; a spherical map needs one closed, manifold component (this mesh: Euler characteristic " << chi << ")";
    }
    r.code = ERROR_NOT_GENUS_0;
    r.message = s.str();
  }
  return r;
}

/// Checks the geometry: finite coordinates, positive 3D areas, positive
/// finite densities; fills `P.target`. `density` is per face, empty for ρ ≡ 1.
inline Validation validate_sphere_geometry(Sphere_problem& P, const std::vector<double>& density)
{
  Validation r;
  for(std::size_t i = 0; i < P.xyz.size(); ++i)
    if(!std::isfinite(P.xyz[i][0]) || !std::isfinite(P.xyz[i][1]) || !std::isfinite(P.xyz[i][2])) {
      r.code = ERROR_DEGENERATE_INPUT;
      r.message = "vertex " + std::to_string(i) + " has a non-finite coordinate";
      return r;
    }
  if(!density.empty() && density.size() != P.faces.size()) {
    r.code = ERROR_INVALID_DENSITY;
    r.message = "the density has " + std::to_string(density.size()) + " values for " + std::to_string(P.faces.size()) + " faces";
    return r;
  }
  P.target.resize(P.faces.size());
  for(std::size_t f = 0; f < P.faces.size(); ++f) {
    const Face& t = P.faces[f];
    const double a = triangle_area_3(P.xyz[std::size_t(t[0])], P.xyz[std::size_t(t[1])], P.xyz[std::size_t(t[2])]);
    if(!(a > 0) || !std::isfinite(a)) {
      r.code = ERROR_DEGENERATE_INPUT;
      r.message = "face " + std::to_string(f) + " (vertices " + std::to_string(t[0]) + ", " + std::to_string(t[1]) +
                  ", " + std::to_string(t[2]) + ") has zero area";
      return r;
    }
    const double rho = density.empty() ? 1. : density[f];
    if(!(rho > 0) || !std::isfinite(rho)) {
      r.code = ERROR_INVALID_DENSITY;
      r.message = "the density of face " + std::to_string(f) + " is " + std::to_string(rho);
      return r;
    }
    P.target[f] = rho * a;
  }
  return r;
}

/// Signed area of the flat triangle between sphere points: half the length
/// of N = (b − a) × (c − a), with the sign of a · N = det[a, b, c] (in the
/// difference form, whose rounding error scales with the triangle).
inline double signed_area_sphere(const Vec3& a, const Vec3& b, const Vec3& c)
{
  const Vec3 N = cross(sub(b, a), sub(c, a));
  const double l = 0.5 * std::sqrt(dot(N, N));
  const double s = dot(a, N);
  return s > 0 ? l : (s < 0 ? -l : 0.);
}

/// Half the orientation determinant, ½ det[a, b, c] = ½ a · ((b − a) × (c − a)):
/// the flat area times the distance of the triangle's plane from the centre.
/// The flow's area element: it vanishes exactly where the orientation
/// predicate does (a triangle whose plane passes through the centre keeps a
/// large flat area), so the energy is a barrier for the certified property.
inline double cone_area_sphere(const Vec3& a, const Vec3& b, const Vec3& c)
{
  return 0.5 * dot(a, cross(sub(b, a), sub(c, a)));
}

/// ∂/∂a of the two area elements of the face (a, b, c) at its corner a (any
/// corner: rotate the face). With N = (b − a) × (c − a) and e = c − b: the
/// flat area ½|N| has ½ n̂ × e, the cone area ½ det[a, b, c] has ½ b × c,
/// evaluated as ½ (N + a × e), which keeps its relative accuracy on tiny faces.
inline void corner_area_gradients(const Vec3& a, const Vec3& b, const Vec3& c, Vec3& flat, Vec3& cone)
{
  const Vec3 N = cross(sub(b, a), sub(c, a));
  const double l = std::sqrt(dot(N, N));
  const Vec3 e = sub(c, b);
  const Vec3 de = cross(N, e), ae = cross(a, e);
  for(std::size_t j = 0; j < 3; ++j) {
    flat[j] = 0.5 * de[j] / l;
    cone[j] = 0.5 * (N[j] + ae[j]);
  }
}

inline void cone_areas_sphere(const std::vector<Vec3>& p, const std::vector<Face>& faces, std::vector<double>& out)
{
  out.resize(faces.size());
  for(std::size_t f = 0; f < faces.size(); ++f)
    out[f] = cone_area_sphere(p[std::size_t(faces[f][0])], p[std::size_t(faces[f][1])], p[std::size_t(faces[f][2])]);
}

inline void signed_areas_sphere(const std::vector<Vec3>& p, const std::vector<Face>& faces, std::vector<double>& out)
{
  out.resize(faces.size());
  for(std::size_t f = 0; f < faces.size(); ++f)
    out[f] = signed_area_sphere(p[std::size_t(faces[f][0])], p[std::size_t(faces[f][1])], p[std::size_t(faces[f][2])]);
}

/// D_area of the flat triangles between the sphere points (the metric of doc/design.md).
inline double flat_d_area(const std::vector<Vec3>& p, const std::vector<Face>& faces, const std::vector<double>& target)
{
  std::vector<double> a;
  signed_areas_sphere(p, faces, a);
  return d_area_of(a, target);
}

/// Mean |log area ratio| of the flat triangles (both totals normalised; the
/// metric's `log_area_mean_abs`), +∞ when a face is not positive.
inline double flat_mean_abs_log_ratio(const std::vector<Vec3>& p, const std::vector<Face>& faces,
                                      const std::vector<double>& target)
{
  std::vector<double> a;
  signed_areas_sphere(p, faces, a);
  double U = 0, T = 0;
  for(std::size_t f = 0; f < a.size(); ++f) {
    if(!(a[f] > 0)) return std::numeric_limits<double>::infinity();
    U += a[f]; T += target[f];
  }
  double s = 0;
  for(std::size_t f = 0; f < a.size(); ++f) s += std::abs(std::log((a[f] / U) / (target[f] / T)));
  return a.empty() ? 0. : s / double(a.size());
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
