// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The planar flow's input in index form (independent of the mesh type), the
// outcome it reports, and the lumped area elements A_Ω and A_M.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_DISK_PROBLEM_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_DISK_PROBLEM_H

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_options.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/area_barrier_energy.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/distortion.h>

#include <CGAL/enum.h>

#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// A disk-topology triangle mesh, its targets, and its boundary loop.
struct Disk_problem
{
  std::vector<Vec3> xyz;       ///< input positions
  std::vector<Face> faces;     ///< input triangles, positively oriented in the initial map
  std::vector<double> target;  ///< per face: ρ_f · area_M(f) > 0 (any common scale)
  std::vector<int> boundary;   ///< the boundary loop, counter-clockwise in the domain
};

/// What a flow run reports besides the positions.
struct Flow_outcome
{
  Discrete_lie_flow_stop_reason stop_reason = Discrete_lie_flow_stop_reason::NOT_RUN;
  std::size_t iterations = 0;
  double initial_d_area = 0;  ///< on the certified triangulation
  double final_d_area = 0;
  double final_residual = 0;
  std::size_t flips = 0;      ///< paper mode: edge flips in total
  std::size_t rejected_by_exact_check = 0; ///< trial steps the doubles accepted and the exact predicate refused
  std::size_t factorizations = 0, symbolic_analyses = 0;
  bool solver_failed = false;
  /// Time split of the iterations (seconds): assembly, factorisation + solve, step search.
  double seconds_assembly = 0, seconds_solve = 0, seconds_step = 0;
  std::vector<Discrete_lie_flow_iteration> history;
};

/// One iteration's record for the history and the callback of every flow.
/// The residual (a pass over the faces) is computed only when someone reads
/// it. False when the callback asks to stop; the stop reason is then set.
template <class Residual>
bool record_iteration(const Discrete_lie_flow_options& opt, std::size_t iteration, double step, double critical_step,
                      int limiting_face, double d_area, std::size_t backtracks, std::size_t flips, double seconds,
                      const Residual& residual, Flow_outcome& out)
{
  Discrete_lie_flow_iteration info;
  info.iteration = iteration;
  info.step = step;
  info.critical_step = critical_step;
  info.limiting_face = limiting_face;
  info.d_area = d_area;
  info.backtracks = backtracks;
  info.flips = flips;
  info.seconds = seconds;
  if(opt.record_history || opt.callback) info.residual = residual();
  if(opt.record_history) out.history.push_back(info);
  if(opt.callback && !opt.callback(info)) { out.stop_reason = Discrete_lie_flow_stop_reason::INTERRUPTED; return false; }
  return true;
}

/// Faces around each vertex, with the corner the vertex occupies.
struct Vertex_faces
{
  std::vector<std::size_t> first;              ///< CSR offsets, size n + 1
  std::vector<std::pair<std::size_t, int> > of; ///< (face, corner)

  Vertex_faces(std::size_t n, const std::vector<Face>& faces) : first(n + 1, 0)
  {
    for(const Face& t : faces) for(int k = 0; k < 3; ++k) ++first[std::size_t(t[k]) + 1];
    for(std::size_t v = 0; v < n; ++v) first[v + 1] += first[v];
    of.resize(first[n]);
    std::vector<std::size_t> fill(first.begin(), first.end() - 1);
    for(std::size_t f = 0; f < faces.size(); ++f)
      for(int k = 0; k < 3; ++k) of[fill[std::size_t(faces[f][k])]++] = std::make_pair(f, k);
  }
};

/// The 2 × 2 Gauss–Newton model of one vertex's move in a relaxation sweep
/// (planar_relaxation.h, sphere_relaxation.h): gradient g and matrix
/// Σ w ∇u ∇uᵀ, accumulated face by face in the vertex's own frame.
struct Vertex_model
{
  double g0 = 0, g1 = 0, h00 = 0, h01 = 0, h11 = 0;

  /// A face with ∂E/∂u = dE, curvature w and ∂u/∂(vertex) = (x, y).
  void add(double dE, double w, double x, double y)
  {
    g0 += dE * x; g1 += dE * y;
    h00 += w * x * x; h01 += w * x * y; h11 += w * y * y;
  }

  /// The (slightly regularised) Newton step x and its slope gᵀx; false
  /// unless it is a descent direction.
  bool step(double& x0, double& x1, double& slope) const
  {
    const double reg = 1e-9 * (h00 + h11), a = h00 + reg, c = h11 + reg;
    const double det = a * c - h01 * h01;
    if(!(det > 0)) return false;
    x0 = -(c * g0 - h01 * g1) / det;
    x1 = -(a * g1 - h01 * g0) / det;
    slope = g0 * x0 + g1 * x1;
    return slope < 0;
  }
};

/// What a relaxation sweep did (planar_relaxation.h, sphere_relaxation.h).
struct Relaxation_outcome
{
  std::size_t moved = 0, refused_by_exact_check = 0;
};

/// The line search of one vertex's relaxation move, shared by the plane and
/// the sphere: `at(λ)` is the vertex's trial position, `energy(x)` the total
/// energy with the vertex at x (+∞ when one of its faces is not positive;
/// the caller keeps what it needs to commit the move), `certified(x)` the
/// exact orientation check of its faces. From `lambda`, at most 8 halvings
/// until the energy passes Armijo against `E` and the exact predicate
/// agrees; then true, with the position in `moved`.
template <class Point, class Position, class Energy, class Certified>
bool relaxation_line_search(double E, double lambda, double slope, const Position& at, const Energy& energy,
                            const Certified& certified, Point& moved, Relaxation_outcome& out)
{
  for(int halvings = 0; halvings < 8; ++halvings, lambda *= 0.5) {
    moved = at(lambda);
    if(!(energy(moved) <= E + 1e-4 * lambda * slope)) continue;
    if(!certified(moved)) { ++out.refused_by_exact_check; continue; }
    ++out.moved;
    return true;
  }
  return false;
}

/// Whether `orientation(x, r, s)` is positive for every face (x, r, s) of the
/// vertex at `around.of[begin, end)` moved to x (r, s: its other corners in
/// `p`, in the face's order): the exact check of a relaxation move.
template <class Point, class Orientation>
bool moved_vertex_is_positive(const Vertex_faces& around, std::size_t begin, std::size_t end,
                              const std::vector<Face>& faces, const std::vector<Point>& p, const Point& x,
                              const Orientation& orientation)
{
  for(std::size_t i = begin; i < end; ++i) {
    const Face& t = faces[around.of[i].first];
    const int k = around.of[i].second;
    if(orientation(x, p[std::size_t(t[(k + 1) % 3])], p[std::size_t(t[(k + 2) % 3])]) != CGAL::POSITIVE) return false;
  }
  return true;
}

/// Lumped vertex areas: out[i] = (1/3) Σ_{f ∋ i} value[f].
inline void lump_on_vertices(std::size_t n, const std::vector<Face>& faces, const std::vector<double>& value,
                             std::vector<double>& out)
{
  out.assign(n, 0.);
  for(std::size_t f = 0; f < faces.size(); ++f)
    for(int k = 0; k < 3; ++k) out[faces[f][k]] += value[f] / 3;
}

inline double signed_area_2(const Vec2& a, const Vec2& b, const Vec2& c)
{
  return 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
}

inline void signed_areas_2(const std::vector<Vec2>& uv, const std::vector<Face>& faces, std::vector<double>& out)
{
  out.resize(faces.size());
  for(std::size_t f = 0; f < faces.size(); ++f)
    out[f] = signed_area_2(uv[faces[f][0]], uv[faces[f][1]], uv[faces[f][2]]);
}

/// Normalised squared mismatch Σ_i (A_Ω(i) − A_M(i))² / (Σ A_Ω)², with A_M
/// scaled to the domain's total area.
inline double area_residual(std::size_t n, const std::vector<Face>& faces, const std::vector<double>& dom_area,
                            const std::vector<double>& target)
{
  std::vector<double> ao, am;
  lump_on_vertices(n, faces, dom_area, ao);
  lump_on_vertices(n, faces, target, am);
  double so = 0, sm = 0;
  for(std::size_t i = 0; i < n; ++i) { so += ao[i]; sm += am[i]; }
  double r = 0;
  for(std::size_t i = 0; i < n; ++i) { const double d = ao[i] - am[i] * so / sm; r += d * d; }
  return r / (so * so);
}

/// D_area of domain areas `u` against targets (both per face; u > 0):
/// exactly the metric `d_area` of DESIGN.md. +∞ if some u ≤ 0.
inline double d_area_of(const std::vector<double>& u, const std::vector<double>& target)
{
  double U = 0, T = 0;
  for(std::size_t f = 0; f < u.size(); ++f) {
    if(!(u[f] > 0)) return std::numeric_limits<double>::infinity();
    U += u[f]; T += target[f];
  }
  double e = 0;
  for(std::size_t f = 0; f < u.size(); ++f) {
    const double r = (u[f] / U) / (target[f] / T);
    e += (target[f] / T) * (r + 1 / r);
  }
  return e;
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
