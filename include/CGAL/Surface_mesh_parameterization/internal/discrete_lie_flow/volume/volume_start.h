// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The volumetric flow's start: the border onto the unit sphere by the
// spherical flow (bijective, exact-certified), the interior by Tutte's
// barycentric embedding in 3D, then the exact check of every tet and, when
// the embedding folds some (it can in 3D), untangling (volume_untangle.h).

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_VOLUME_START_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DLF_VOLUME_START_H

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_report.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/volume/volume_flow.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/volume/volume_untangle.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <Eigen/Sparse>

#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// What the start did.
struct Volume_start_info
{
  std::size_t tutte_negative_tets = 0, tutte_flat_tets = 0; ///< by the exact predicate, before untangling
  std::size_t border_only_bad_tets = 0; ///< of those, tets with four border vertices
  std::size_t untangle_iterations = 0;
  bool untangled = false;   ///< the untangling ran and made every tet positive
  Discrete_lie_flow_report border; ///< the spherical map of the border
  double seconds_border = 0, seconds_interior = 0, seconds_untangle = 0;
};

/// The border surface that the start maps onto the sphere.
typedef Surface_mesh<Simple_cartesian<double>::Point_3> Volume_border_mesh;

/// The closed border surface of the ball onto the unit sphere by
/// `map_border` (see `volume_start()`): `x` receives the border vertices'
/// images (the others at the origin). `OK`, or the code with `message`.
template <class BorderToSphere>
int map_volume_border(const std::vector<Vec3>& xyz, const Ball_topology& topo, const BorderToSphere& map_border,
                      std::vector<Vec3>& x, Volume_start_info& info, std::string& message)
{
  const std::size_t V = xyz.size();
  typedef Volume_border_mesh Border_mesh;
  typedef Border_mesh::Point P3;
  Border_mesh border;
  std::vector<typename Border_mesh::Vertex_index> local(V);
  std::vector<int> global;
  for(std::size_t v = 0; v < V; ++v)
    if(topo.on_border[v]) {
      local[v] = border.add_vertex(P3(xyz[v][0], xyz[v][1], xyz[v][2]));
      global.push_back(int(v));
    }
  for(std::size_t f = 0; f < topo.border_faces.size(); ++f) {
    const auto& t = topo.border_faces[f];
    if(border.add_face(local[std::size_t(t[0])], local[std::size_t(t[1])], local[std::size_t(t[2])]) == Border_mesh::null_face()) {
      message = "the border triangle " + std::to_string(f) + " could not be added to a manifold surface";
      return ERROR_NO_TOPOLOGICAL_BALL;
    }
  }
  x.assign(V, Vec3{{ 0, 0, 0 }});
  {
    auto sphere = border.template add_property_map<typename Border_mesh::Vertex_index, P3>("v:dlf_sphere").first;
    const Error_code code = map_border(std::as_const(border), sphere, info.border);
    if(code != OK) {
      message = "the border could not be mapped onto the sphere: " + info.border.message;
      return code;
    }
    for(std::size_t i = 0; i < global.size(); ++i) {
      const P3& p = sphere[typename Border_mesh::Vertex_index(typename Border_mesh::size_type(i))];
      x[std::size_t(global[i])] = normalized(Vec3{{ p.x(), p.y(), p.z() }});
    }
  }
  return OK;
}

/// Tutte's embedding of the interior: every interior vertex of `x` at the
/// mean of its neighbours, the border held. `OK`, or the code with `message`.
template <class EigenSolver>
int tutte_volume_interior(const Ball_topology& topo, std::vector<Vec3>& x, std::string& message)
{
  const std::size_t V = x.size();
  std::vector<int> idx(V, -1);
  int n = 0;
  for(std::size_t v = 0; v < V; ++v)
    if(!topo.on_border[v]) idx[v] = n++;
  if(n > 0) {
    std::vector<Eigen::Triplet<double> > trip;
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(n, 3);
    std::vector<double> diag(std::size_t(n), 0.);
    for(const auto& e : topo.edges) {
      const int a = idx[std::size_t(e.first)], b = idx[std::size_t(e.second)];
      if(a >= 0) diag[std::size_t(a)] += 1;
      if(b >= 0) diag[std::size_t(b)] += 1;
      if(a >= 0 && b >= 0) {
        trip.emplace_back(a, b, -1.);
        trip.emplace_back(b, a, -1.);
      } else if(a >= 0) {
        for(int c = 0; c < 3; ++c) rhs(a, c) += x[std::size_t(e.second)][std::size_t(c)];
      } else if(b >= 0) {
        for(int c = 0; c < 3; ++c) rhs(b, c) += x[std::size_t(e.first)][std::size_t(c)];
      }
    }
    for(int i = 0; i < n; ++i) trip.emplace_back(i, i, diag[std::size_t(i)]);
    Sparse_matrix L(n, n);
    L.setFromTriplets(trip.begin(), trip.end());
    L.makeCompressed();
    EigenSolver solver;
    solver.compute(L);
    if(solver.info() != Eigen::Success) {
      message = "the interior (Tutte) system could not be factorised";
      return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
    }
    for(int c = 0; c < 3; ++c) {
      const Eigen::VectorXd sol = solver.solve(Eigen::VectorXd(rhs.col(c)));
      if(solver.info() != Eigen::Success || !sol.allFinite()) {
        message = "the interior (Tutte) system could not be solved";
        return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
      }
      for(std::size_t v = 0; v < V; ++v)
        if(idx[v] >= 0) x[v][std::size_t(c)] = sol[idx[v]];
    }
  }
  return OK;
}

/// The exact check of the start `x`; its folds (tets, or border triangles
/// seen from the centre) untangled (volume_untangle.h). `OK`, or
/// `ERROR_INITIAL_MAP_FOLDED` with `message` counting what is left.
inline int certify_volume_start(const std::vector<Vec3>& xyz, const std::vector<Tet>& tets, const Ball_topology& topo,
                                const std::vector<double>& target, std::size_t untangle_max_iterations,
                                const std::function<bool(const Volume_iteration&)>& callback, std::vector<Vec3>& x,
                                Volume_start_info& info, std::string& message)
{
  const std::chrono::steady_clock::time_point t0 = std::chrono::steady_clock::now();
  const Tet_orientation_counts bad = count_bad_tets(x, tets);
  info.tutte_negative_tets = bad.negative;
  info.tutte_flat_tets = bad.flat;
  if(bad.not_positive() == 0 && count_bad_border_faces(x, topo.border_faces) == 0) return OK;
  // Tets whose four corners lie on the border: only the border can unfold them.
  std::size_t border_only = 0;
  for(const Tet& k : tets) {
    const Vec3 &a = x[std::size_t(k[0])], &b = x[std::size_t(k[1])], &c = x[std::size_t(k[2])], &e = x[std::size_t(k[3])];
    if(topo.on_border[std::size_t(k[0])] && topo.on_border[std::size_t(k[1])] && topo.on_border[std::size_t(k[2])] &&
       topo.on_border[std::size_t(k[3])] && exact_tet_orientation(a, b, c, e) != POSITIVE)
      ++border_only;
  }
  info.border_only_bad_tets = border_only;
  const Untangle_outcome out = untangle_volume(x, tets, topo.on_border, topo.border_faces, xyz, target,
                                               untangle_max_iterations, callback);
  info.untangle_iterations = out.iterations;
  info.seconds_untangle = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const Tet_orientation_counts after = count_bad_tets(x, tets);
  const std::size_t bad_border = count_bad_border_faces(x, topo.border_faces);
  if(out.stopped && (after.not_positive() != 0 || bad_border != 0)) {
    message = "no certified start: the callback stopped the untangling after " + std::to_string(out.iterations) +
              " iterations, with " + std::to_string(after.negative) + " tetrahedra inverted and " +
              std::to_string(after.flat) + " flat (exact predicate)";
    return ERROR_INITIAL_MAP_FOLDED;
  }
  if(!out.success || after.not_positive() != 0 || bad_border != 0) {
    message = "no certified start: Tutte's embedding of the interior folds " + std::to_string(bad.negative) +
              " tetrahedra and flattens " + std::to_string(bad.flat) + " (exact predicate; " +
              std::to_string(border_only) + " of them with four border vertices); after " +
              std::to_string(out.iterations) + " untangling iterations " + std::to_string(after.negative) +
              " are still inverted and " + std::to_string(after.flat) + " flat (first: tetrahedron " +
              std::to_string(after.first_bad) + "), " + std::to_string(bad_border) +
              " border triangles not positive seen from the centre";
    return ERROR_INITIAL_MAP_FOLDED;
  }
  info.untangled = true;
  return OK;
}

/// Positions `x` of a certified start (every tet positive by the exact
/// predicate, border vertices on the unit sphere), or an error code with
/// `message`. `map_border` maps the closed border surface onto the unit
/// sphere: `Error_code map_border(const Volume_border_mesh&, sphere_map,
/// Discrete_lie_flow_report&)`, the sphere map a vertex property map of
/// points (the public volume parameterizer passes the spherical flow).
template <class EigenSolver, class BorderToSphere>
int volume_start(const std::vector<Vec3>& xyz, const std::vector<Tet>& tets, const Ball_topology& topo,
                 const std::vector<double>& target, const BorderToSphere& map_border,
                 std::size_t untangle_max_iterations,
                 const std::function<bool(const Volume_iteration&)>& callback, std::vector<Vec3>& x,
                 Volume_start_info& info, std::string& message)
{
  typedef std::chrono::steady_clock Clock;
  Clock::time_point t0 = Clock::now();
  int code = map_volume_border(xyz, topo, map_border, x, info, message);
  if(code != OK) return code;
  info.seconds_border = std::chrono::duration<double>(Clock::now() - t0).count();
  t0 = Clock::now();
  code = tutte_volume_interior<EigenSolver>(topo, x, message);
  if(code != OK) return code;
  info.seconds_interior = std::chrono::duration<double>(Clock::now() - t0).count();
  return certify_volume_start(xyz, tets, topo, target, untangle_max_iterations, callback, x, info, message);
}

} // namespace dlf
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
