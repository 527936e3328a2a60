// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_DISCRETE_LIE_FLOW_VOLUME_3_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_DISCRETE_LIE_FLOW_VOLUME_3_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_options.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_report.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_solver.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_sphere_3.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_volume_options.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/default_solver.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/volume/volume_run.h>

#include <CGAL/Surface_mesh_parameterization/Error_code.h>

#include <array>
#include <map>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgDiscreteLieFlowParameterizers
///
/// Volume-preserving (or density-prescribed) map of a tetrahedral mesh of a
/// topological ball onto the unit ball, the volumetric Discrete Lie Flow:
/// the paper (Su et al. 2019, \ref DLFBibSu2019) proves its flow in any
/// dimension and leaves tetrahedral meshes as future work (§7.2).
///
/// The start is certified bijective: the border triangles go onto the unit
/// sphere by `Discrete_lie_flow_sphere_parameterizer_3` (every spherical
/// triangle positive by the exact predicate), the interior vertices by
/// Tutte's barycentric embedding; when that folds tets (it can in 3D),
/// Garanzha et al.'s regularised barrier (χ_ε(u) = (u + √(ε² + u²))/2 with
/// ε continuation) untangles them until every tet is positive by CGAL's
/// exact `orientation(p, q, r, s)`, else the run fails with
/// `ERROR_INITIAL_MAP_FOLDED` and a message counting the folds.
///
/// The flow descends D_vol = Σ w_t (r_t + 1/r_t) (w_t the tet's prescribed
/// share ρ_t vol_t / Σ ρ vol, r_t its achieved share over w_t; minimum 2)
/// along a regularised Gauss–Newton direction solved by preconditioned
/// conjugate gradients: the interior vertices move in space, the border
/// vertices in the tangent planes of the sphere and are re-normalised
/// after the step. Every step is at most μ times the smallest positive
/// root of the tets' cubics det(p + λv), then halved until the energy drops
/// and every tet is positive by the exact predicate: the result is never
/// folded. The paper mode (`options().mode = Discrete_lie_flow_mode::PAPER`)
/// replaces the direction by the paper's Poisson step, from the same start
/// and with the same certification.
///
/// \tparam SolverTraits_ `CGAL::Eigen_solver_traits<S>` with `S` an Eigen
///   sparse SPD solver with `analyzePattern()`/`factorize()` for Tutte's system of the start (the border's spherical map uses its own default).
///   Default: `Discrete_lie_flow_default_spd_solver`.
template <class SolverTraits_ = Default>
class Discrete_lie_flow_volume_parameterizer_3
{
public:
  /// The solver traits of the start's sparse SPD system (Tutte's embedding).
  typedef typename Default::Get<SolverTraits_,
    Eigen_solver_traits<Discrete_lie_flow_default_spd_solver> >::type Solver_traits;

  /// \param options flow settings (tolerances, caps, density, callback)
  explicit Discrete_lie_flow_volume_parameterizer_3(const Discrete_lie_flow_volume_options& options =
                                                      Discrete_lie_flow_volume_options())
    : m_options(options)
  {}

  /// The settings, to read or change before `parameterize()`.
  Discrete_lie_flow_volume_options& options() { return m_options; }
  /// The settings.
  const Discrete_lie_flow_volume_options& options() const { return m_options; }
  /// The report of this object's last run.
  const Discrete_lie_flow_volume_report& report() const { return m_report; }

  /// Maps the tet soup (`points`: anything with `x()`, `y()`, `z()`;
  /// `tets`: four 0-based indices per tet, positively oriented) into the
  /// unit ball: `ball` receives one point per input point (only on success).
  template <class InputPoint, class OutputPoint>
  Error_code parameterize(const std::vector<InputPoint>& points, const std::vector<std::array<int, 4> >& tets,
                          std::vector<OutputPoint>& ball)
  {
    std::vector<internal::dlf::Vec3> xyz(points.size());
    for(std::size_t i = 0; i < points.size(); ++i)
      xyz[i] = {{ CGAL::to_double(points[i].x()), CGAL::to_double(points[i].y()), CGAL::to_double(points[i].z()) }};
    std::vector<internal::dlf::Vec3> out;
    const Error_code code = run(xyz, tets, out);
    if(code != OK) return code;
    ball.clear();
    for(const auto& p : out) ball.push_back(OutputPoint(p[0], p[1], p[2]));
    return OK;
  }

  /// Maps the cells of a `Mesh_complex_3_in_triangulation_3` (CGAL's Mesh_3
  /// output) into the unit ball: `ball_map` (a writable property map
  /// `Vertex_handle` → point constructible from three doubles) receives the
  /// image of every vertex of a cell in the complex. The tet of a cell is
  /// (v0, v1, v2, v3) as the triangulation stores it (positively oriented).
  template <class C3T3, class VertexBallMap>
  Error_code parameterize_complex(const C3T3& c3t3, VertexBallMap ball_map)
  {
    typedef typename C3T3::Triangulation::Vertex_handle Vertex_handle;
    std::map<Vertex_handle, int> index;
    std::vector<Vertex_handle> handles;
    std::vector<internal::dlf::Vec3> xyz;
    std::vector<std::array<int, 4> > tets;
    for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c) {
      std::array<int, 4> t;
      for(int k = 0; k < 4; ++k) {
        const Vertex_handle v = c->vertex(k);
        auto it = index.find(v);
        if(it == index.end()) {
          it = index.emplace(v, int(handles.size())).first;
          handles.push_back(v);
          const auto& p = c3t3.triangulation().point(v);
          xyz.push_back({{ CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()) }});
        }
        t[std::size_t(k)] = it->second;
      }
      tets.push_back(t);
    }
    std::vector<internal::dlf::Vec3> out;
    const Error_code code = run(xyz, tets, out);
    if(code != OK) return code;
    typedef typename boost::property_traits<VertexBallMap>::value_type Point;
    for(std::size_t i = 0; i < handles.size(); ++i) put(ball_map, handles[i], Point(out[i][0], out[i][1], out[i][2]));
    return OK;
  }

private:
  Error_code run(const std::vector<internal::dlf::Vec3>& xyz, const std::vector<std::array<int, 4> >& tets,
                 std::vector<internal::dlf::Vec3>& x)
  {
    typedef internal::dlf::Volume_border_mesh Border_mesh;
    const Discrete_lie_flow_options& border_options = m_options.border;
    // The border's spherical map: the public sphere parameterizer, which the
    // internal run cannot include.
    const auto border_to_sphere = [&border_options](const Border_mesh& border, auto sphere,
                                                    Discrete_lie_flow_report& report) {
      Discrete_lie_flow_sphere_parameterizer_3<Border_mesh> flow(border_options);
      const Error_code c = flow.parameterize(border, sphere);
      report = flow.report();
      return c;
    };
    return internal::dlf::run_volume_parameterization<typename Solver_traits::Solver>(m_options, xyz, tets,
                                                                                      border_to_sphere, x, m_report);
  }

  Discrete_lie_flow_volume_options m_options;
  Discrete_lie_flow_volume_report m_report;
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
