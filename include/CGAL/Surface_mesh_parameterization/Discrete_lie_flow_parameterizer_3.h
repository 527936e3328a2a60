// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_DISCRETE_LIE_FLOW_PARAMETERIZER_3_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_DISCRETE_LIE_FLOW_PARAMETERIZER_3_H

#include <CGAL/license/Surface_mesh_parameterization.h>

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_options.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_report.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_solver.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/default_solver.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/disk/disk_flow.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/disk/loop_triangulation.h>
#include <CGAL/Surface_mesh_parameterization/internal/discrete_lie_flow/core/mesh_properties.h>

#include <CGAL/Surface_mesh_parameterization/Symmetric_barycentric_mapping_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Circular_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/LSCM_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Two_vertices_parameterizer_3.h>
#include <CGAL/Polygon_mesh_processing/measure.h>

// What a program written for Orbifold_Tutte_parameterizer_3 uses besides the
// class (cones read and located, their types, the shortest paths between
// them: in its header), so that with the class name swapped it compiles up
// to the constructor's one-line refusal.
// CGAL 5.5's orbifold_enums.h defines get_orbifold_type() without `inline`;
// declared inline first, the header may be included by every translation unit.
#if !defined(CGAL_SURFACE_MESH_PARAMETERIZATION_ORBIFOLD_ENUMS_H) && !defined(DOXYGEN_RUNNING)
namespace CGAL {
namespace Surface_mesh_parameterization {
inline const char* get_orbifold_type(int orb_type);
} // namespace Surface_mesh_parameterization
} // namespace CGAL
#endif
#include <CGAL/Surface_mesh_parameterization/orbifold_enums.h>
#include <CGAL/Surface_mesh_parameterization/Orbifold_Tutte_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Error_code.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <CGAL/Surface_mesh_parameterization/internal/Containers_filler.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/Surface_mesh_parameterization/internal/kernel_traits.h>

#include <CGAL/Default.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Eigen_solver_traits.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <chrono>
#include <functional>
#include <memory>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
namespace dlf {

/// Whether an initial parameterizer gives Tutte's map (uniform weights) with
/// the border on the circle by arc length, which the flow then computes
/// itself (the same map to rounding), whatever the parameterizer's solver.
template <class Initial, class TriangleMesh>
struct Is_tutte_on_arc_length_circle : std::false_type {};
template <class TriangleMesh, class Solver>
struct Is_tutte_on_arc_length_circle<Symmetric_barycentric_mapping_parameterizer_3<TriangleMesh, Default, Solver>,
                                     TriangleMesh> : std::true_type {};
template <class TriangleMesh, class Solver>
struct Is_tutte_on_arc_length_circle<
  Symmetric_barycentric_mapping_parameterizer_3<TriangleMesh, Circular_border_arc_length_parameterizer_3<TriangleMesh>, Solver>,
  TriangleMesh> : std::true_type {};

/// Whether `T` is one of the package's Tutte starts on a convex border,
/// with which the library's own Tutte start of a disk with holes is the
/// same kind of map as the caller asked for.
template <class T>
struct Is_symmetric_barycentric : std::false_type {};
template <class TriangleMesh, class Border, class Solver>
struct Is_symmetric_barycentric<Symmetric_barycentric_mapping_parameterizer_3<TriangleMesh, Border, Solver> >
  : std::true_type {};

/// Whether `T` is a CGAL border parameterizer (it places only the border;
/// CGAL's `Fixed_border_parameterizer_3` and `LSCM_parameterizer_3` take it
/// as their second template argument): they, and only they, say whether
/// the border they make is convex.
template <class T, class = void>
struct Is_border_parameterizer : std::false_type {};
template <class T>
struct Is_border_parameterizer<T, decltype(void(std::declval<const T&>().is_border_convex()))> : std::true_type {};

/// Whether `T` models `Parameterizer_3` for `TriangleMesh`: its
/// `parameterize(mesh, bhd, uvmap, vimap, vpmap)` accepts the maps CGAL's
/// `parameterize()` passes.
template <class T, class TriangleMesh, class = void>
struct Is_parameterizer_3 : std::false_type {};
template <class T, class TriangleMesh>
struct Is_parameterizer_3<T, TriangleMesh, decltype(void(std::declval<T&>().parameterize(
  std::declval<TriangleMesh&>(), std::declval<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor>(),
  std::declval<typename boost::property_map<TriangleMesh, CGAL::dynamic_vertex_property_t<
    typename CGAL::Surface_mesh_parameterization::internal::Kernel_traits<TriangleMesh>::Kernel::Point_2> >::type>(),
  std::declval<typename boost::property_map<TriangleMesh, CGAL::dynamic_vertex_property_t<int> >::type>(),
  std::declval<typename boost::property_map<TriangleMesh, CGAL::dynamic_vertex_property_t<bool> >::type>())))>
  : std::true_type {};

/// The initial parameterizer of `Discrete_lie_flow_parameterizer_3<TriangleMesh, Second>`:
/// the default Tutte start; Tutte's map inside the border of a CGAL border
/// parameterizer (the meaning CGAL's fixed-border parameterizers give their
/// second argument); LSCM with `Two_vertices_parameterizer_3` (the free
/// border CGAL's `LSCM_parameterizer_3` gives it); or `Second` itself.
template <class TriangleMesh, class Second, bool border = Is_border_parameterizer<Second>::value>
struct Initial_parameterizer_of { typedef Second type; };
template <class TriangleMesh, bool border>
struct Initial_parameterizer_of<TriangleMesh, Default, border>
{ typedef Symmetric_barycentric_mapping_parameterizer_3<TriangleMesh> type; };
template <class TriangleMesh, class Second>
struct Initial_parameterizer_of<TriangleMesh, Second, true>
{ typedef Symmetric_barycentric_mapping_parameterizer_3<TriangleMesh, Second> type; };
template <class TriangleMesh, class Mesh>
struct Initial_parameterizer_of<TriangleMesh, Two_vertices_parameterizer_3<Mesh>, true>
{ typedef LSCM_parameterizer_3<TriangleMesh, Two_vertices_parameterizer_3<Mesh> > type; };

/// Whether `T` is `Two_vertices_parameterizer_3`: CGAL's LSCM with it pins
/// two vertices and leaves the border free, so the drop-in lets the border
/// float (`Discrete_lie_flow_border::FLOATING`) by default.
template <class T>
struct Is_two_vertices_parameterizer : std::false_type {};
template <class Mesh>
struct Is_two_vertices_parameterizer<Two_vertices_parameterizer_3<Mesh> > : std::true_type {};

/// The key and value types of a property map, `void` for what is not one
/// (so that a wrongly bound argument gives one readable `static_assert`).
template <class Map, class = void>
struct Map_types { typedef void key_type; typedef void value_type; };
template <class Map>
struct Map_types<Map, std::void_t<typename boost::property_traits<Map>::key_type,
                                  typename boost::property_traits<Map>::value_type> >
{
  typedef typename boost::property_traits<Map>::key_type key_type;     ///< the key
  typedef typename boost::property_traits<Map>::value_type value_type; ///< the value
};

/// False for every `T`: a `static_assert` that fires only when its template is used.
template <class T>
struct Always_false : std::false_type {};

} // namespace dlf
} // namespace internal

/// \ingroup PkgDiscreteLieFlowParameterizers
///
/// The class `Discrete_lie_flow_parameterizer_3` computes an area-preserving
/// (or density-prescribed) parameterization of a disk-topology triangle mesh
/// by the Discrete Lie Flow of Kehua Su, Chenchen Li, Shifan Zhao, Na Lei and
/// Xianfeng Gu, "Discrete Lie flow: A measure controllable parameterization
/// method", Computer Aided Geometric Design 72 (2019) 49–68
/// (\ref DLFBibSu2019 "Su et al. 2019"): starting from any flip-free
/// initial map, the domain vertices flow until every triangle's domain area
/// is proportional to its (density-weighted) surface area, with the step
/// bounded by the closed-form critical roots and certified by CGAL's exact
/// orientation predicate.
///
/// Three modes (`Discrete_lie_flow_options::mode`): `CERTIFIED` (default)
/// keeps the caller's connectivity and never folds it; `LITERAL` runs the
/// paper's Algorithm 1 as printed (doc/paper_literal.md; its failure, a
/// collapse, is reported as the stop reason `COLLAPSED`); `PAPER` is that
/// flow stabilised (doc/paper_mode.md). Both flip edges of the flowing
/// domain mesh. Where the printed paper is corrected: doc/paper_errata.md.
///
/// Meshes with holes (a connected genus-0 component with several border
/// loops, certified mode): the loop of `bhd` goes to the domain's border
/// (circle, square or free, as the initial parameterizer places it); every
/// other loop floats. The flow runs on the disk made by filling each hole
/// with a fan of virtual triangles around a virtual vertex (their targets:
/// the fan's 3D area). The start keeps the initial parameterizer's map when
/// it is fold-free and each hole's virtual vertex can be placed inside the
/// hole's uv polygon: where a point sees the whole polygon, the fan around
/// it, else, where the polygon is simple, its constrained Delaunay
/// triangulation with the virtual vertex inside (checked by the exact
/// predicate); the package's Tutte
/// starts (`Symmetric_barycentric_mapping_parameterizer_3`), and any map
/// that cannot be kept, start from Tutte's embedding of the filled disk
/// inside the initial map's outer loop, or, when that folds (a non-convex
/// loop), on the circle by arc length; the report's message names the
/// start taken. The fill stays positively oriented like the caller's
/// triangles, so the result is globally injective: no hole overlaps the
/// rest of the map. The map, the report and the area elements are about
/// the caller's vertices and faces only.
///
/// A drop-in for CGAL's parameterizers: the second template argument may be
/// a CGAL border parameterizer, as CGAL's parameterizers take it (the start
/// is then Tutte's map inside that border, or LSCM with
/// `Two_vertices_parameterizer_3`), the constructor takes that border
/// parameterizer, with `Two_vertices_parameterizer_3` the border floats
/// (CGAL's free border: `Discrete_lie_flow_border::FLOATING` unless the
/// options name another), the calls of `Iterative_authalic_parameterizer_3` are
/// offered, and every entry point returns a code of CGAL's `Error_code`
/// (`discrete_lie_flow_cgal_error_code()`) with the precise one in `report()`.
///
/// \cgalModels `Parameterizer_3`
///
/// \tparam TriangleMesh_ a model of `FaceGraph`
/// \tparam InitialParameterizer_ a model of `Parameterizer_3` giving a flip-free
///   initial map; its border decides the domain (circle, square, or free).
///   Or a CGAL border parameterizer (a class with `is_border_convex()`, such
///   as `Circular_border_arc_length_parameterizer_3` or
///   `Square_border_uniform_parameterizer_3`): the initial map is then
///   `Symmetric_barycentric_mapping_parameterizer_3` with that border, or
///   `LSCM_parameterizer_3` with `Two_vertices_parameterizer_3` (a free
///   border: in certified mode the border then floats unless
///   `Discrete_lie_flow_disk_options::border` names another).
///   Default: Tutte on the circle by arc length (`Symmetric_barycentric_mapping_parameterizer_3`).
///   With that parameterizer (on the circle by arc length, any solver), a
///   disk and the certified mode, the flow computes the same map itself,
///   with its own solver: one factorization of Tutte's system then gives the
///   start and the start's border spacing by area (the same map to rounding).
/// \tparam SolverTraits_ `CGAL::Eigen_solver_traits<S>` with `S` an Eigen
///   sparse SPD solver offering `analyzePattern()`/`factorize()`. Default:
///   `Discrete_lie_flow_default_spd_solver` (CHOLMOD's supernodal LLT when
///   available, else `Eigen::SimplicialLDLT`).
template <class TriangleMesh_, class InitialParameterizer_ = Default, class SolverTraits_ = Default>
class Discrete_lie_flow_parameterizer_3
{
public:
  /// \name Types
  /// @{

  /// The mesh type, `TriangleMesh_`.
  typedef TriangleMesh_ Triangle_mesh;
  /// The parameterizer of the initial map (see `InitialParameterizer_`).
  typedef typename internal::dlf::Initial_parameterizer_of<TriangleMesh_, InitialParameterizer_>::type
    Initial_parameterizer;
  /// The solver traits of the flow's sparse SPD systems.
  typedef typename Default::Get<SolverTraits_,
    Eigen_solver_traits<Discrete_lie_flow_default_spd_solver> >::type Solver_traits;

  /// Vertex descriptor of the mesh.
  typedef typename boost::graph_traits<Triangle_mesh>::vertex_descriptor vertex_descriptor;
  /// Halfedge descriptor of the mesh.
  typedef typename boost::graph_traits<Triangle_mesh>::halfedge_descriptor halfedge_descriptor;
  /// Face descriptor of the mesh.
  typedef typename boost::graph_traits<Triangle_mesh>::face_descriptor face_descriptor;
  /// The kernel of the mesh's points.
  typedef typename internal::Kernel_traits<Triangle_mesh>::Kernel Kernel;
  /// The point type of the uv map.
  typedef typename Kernel::Point_2 Point_2;

  /// @}

  static_assert(internal::dlf::Is_border_parameterizer<Initial_parameterizer>::value ||
                internal::dlf::Is_parameterizer_3<Initial_parameterizer, Triangle_mesh>::value,
                "Discrete_lie_flow_parameterizer_3<Mesh, X>: X must be a CGAL border parameterizer "
                "(e.g. Circular_border_arc_length_parameterizer_3<Mesh>) or a Parameterizer_3 of Mesh giving "
                "the initial map (e.g. LSCM_parameterizer_3<Mesh>)");

  /// \param initial the parameterizer that gives the initial map
  /// \param options flow settings (mode, tolerance, caps, density, callback)
  /// \param solver_traits the sparse SPD solver
  explicit Discrete_lie_flow_parameterizer_3(Initial_parameterizer initial = Initial_parameterizer(),
                                             Discrete_lie_flow_options options = Discrete_lie_flow_options(),
                                             Solver_traits solver_traits = Solver_traits())
    : m_initial(initial), m_options(options), m_solver_traits(solver_traits)
  {}

  /// CGAL's idiom `Parameterizer parameterizer(border_parameterizer)`: the
  /// initial parameterizer is built from the border parameterizer `border`.
  /// \tparam BorderParameterizer a CGAL border parameterizer (it has `is_border_convex()`)
  /// \param border the parameterizer of the border
  /// \param options flow settings
  /// \param solver_traits the sparse SPD solver
  template <class BorderParameterizer,
            typename std::enable_if<internal::dlf::Is_border_parameterizer<BorderParameterizer>::value &&
                                    !std::is_same<BorderParameterizer, Initial_parameterizer>::value, int>::type = 0>
  Discrete_lie_flow_parameterizer_3(const BorderParameterizer& border,
                                    Discrete_lie_flow_options options = Discrete_lie_flow_options(),
                                    Solver_traits solver_traits = Solver_traits())
    : m_initial(make_initial(border)), m_options(options), m_solver_traits(solver_traits)
  {}

  /// Refused at compile time: CGAL's `Orbifold_Tutte_parameterizer_3(orbifold,
  /// weights)`; orbifold cones are not placed by this parameterizer.
  /// \tparam T not to be given
  template <class T = void>
  Discrete_lie_flow_parameterizer_3(Orbifold_type, Weight_type = Cotangent)
  {
    static_assert(internal::dlf::Always_false<T>::value,
                  "Discrete_lie_flow_parameterizer_3 places no orbifold cones: keep Orbifold_Tutte_parameterizer_3, "
                  "or cut the mesh to a disk (Seam_mesh) and flatten it without cones");
  }

  /// The flow settings, to read or change before `parameterize()`.
  Discrete_lie_flow_options& options() { return m_options; }
  /// The flow settings.
  const Discrete_lie_flow_options& options() const { return m_options; }
  /// The parameterizer of the initial map.
  Initial_parameterizer& initial_parameterizer() { return m_initial; }

  /// Sets a per-face density ρ > 0 (a readable property map, `face_descriptor`
  /// → number). The domain area of a face becomes proportional to ρ·area.
  template <class FaceDensityMap>
  void set_face_density(FaceDensityMap density)
  {
    m_face_density = [density](face_descriptor f) { return double(get(density, f)); };
  }
  /// Sets a per-vertex density ρ > 0; a face takes the mean of its corners.
  template <class VertexDensityMap>
  void set_vertex_density(VertexDensityMap density)
  {
    m_vertex_density = [density](vertex_descriptor v) { return double(get(density, v)); };
  }

  /// The report of this object's last run. Each copy owns its report: CGAL's
  /// `parameterize(mesh, parameterizer, bhd, uvmap)` runs a named
  /// `Discrete_lie_flow_parameterizer_3` itself (the overload below), so its
  /// `report()` describes that call.
  const Discrete_lie_flow_report& report() const { return m_report; }

  /// Writes the area elements of the last run into vertex property maps
  /// (`vertex_descriptor` → number): `target` receives A_M(v), the lumped
  /// (density-weighted) surface area scaled to the domain's total, `domain`
  /// receives A_Ω(v) of the final map. On a `Surface_mesh`, `parameterize()`
  /// already stores them as the properties "v:dlf_target_area" and
  /// "v:dlf_domain_area" (and the density as "f:dlf_density").
  template <class TargetAreaMap, class DomainAreaMap>
  void area_elements(TargetAreaMap target, DomainAreaMap domain) const
  {
    for(std::size_t i = 0; i < m_vertex_of.size() && i < m_report.target_area.size(); ++i) {
      put(target, m_vertex_of[i], m_report.target_area[i]);
      put(domain, m_vertex_of[i], m_report.domain_area[i]);
    }
  }

  /// The final domain triangulation of the last run, as vertex triples: the
  /// input triangles in certified mode, the flowing (flipped) ones in paper mode.
  std::vector<std::array<vertex_descriptor, 3> > domain_triangles() const
  {
    std::vector<std::array<vertex_descriptor, 3> > out;
    for(const std::array<int, 3>& t : m_report.domain_faces)
      out.push_back({{ m_vertex_of[std::size_t(t[0])], m_vertex_of[std::size_t(t[1])], m_vertex_of[std::size_t(t[2])] }});
    return out;
  }

  /// Computes the initial map, then flows it. Fills `uvmap` only with a map
  /// whose triangles all have the orientation of the initial map's (never NaN); on error, `uvmap` keeps whatever the
  /// initial parameterizer wrote, and the report's message names the element.
  ///
  /// Returns a code of CGAL's `Error_code` enum, the nearest in meaning
  /// (`discrete_lie_flow_cgal_error_code()`); `report().status` holds the
  /// precise one, a code of `Discrete_lie_flow_error_code` where it has one.
  ///
  /// \pre `bhd` is a border halfedge of `mesh`, whose connected component is
  /// a disk or, in certified mode, a disk with holes (genus 0); `vimap`
  /// indexes the vertices of that component from 0.
  ///
  /// \tparam VertexUVmap a `ReadWritePropertyMap`, `vertex_descriptor` → `Point_2`
  /// \tparam VertexIndexMap a `ReadablePropertyMap`, `vertex_descriptor` → integer
  /// \tparam VertexParameterizedMap a `ReadWritePropertyMap`, `vertex_descriptor` → `bool`
  /// \param mesh the mesh
  /// \param bhd a border halfedge of the component to map
  /// \param uvmap receives the map
  /// \param vimap numbers the component's vertices from 0
  /// \param vpmap marks the vertices the initial parameterizer placed
  template <typename VertexUVmap, typename VertexIndexMap, typename VertexParameterizedMap>
  Error_code parameterize(Triangle_mesh& mesh, halfedge_descriptor bhd, VertexUVmap uvmap,
                          VertexIndexMap vimap, VertexParameterizedMap vpmap)
  {
    // Wrongly bound maps stop here, with a message, not deep in the flow.
    typedef internal::dlf::Map_types<VertexUVmap> UV_traits;
    typedef internal::dlf::Map_types<VertexIndexMap> Index_traits;
    typedef internal::dlf::Map_types<VertexParameterizedMap> Parameterized_traits;
    constexpr bool uv_ok = std::is_convertible<vertex_descriptor, typename UV_traits::key_type>::value &&
                           std::is_convertible<typename UV_traits::value_type, Point_2>::value &&
                           std::is_convertible<Point_2, typename UV_traits::value_type>::value;
    constexpr bool index_ok = std::is_convertible<vertex_descriptor, typename Index_traits::key_type>::value &&
                              std::is_integral<typename Index_traits::value_type>::value;
    constexpr bool parameterized_ok = std::is_convertible<vertex_descriptor, typename Parameterized_traits::key_type>::value &&
                                      std::is_convertible<typename Parameterized_traits::value_type, bool>::value &&
                                      std::is_convertible<bool, typename Parameterized_traits::value_type>::value;
    static_assert(uv_ok, "parameterize(mesh, bhd, uvmap, vimap, vpmap): uvmap must map vertex_descriptor to Point_2 "
                         "(a cone map belongs to Orbifold_Tutte_parameterizer_3, which this parameterizer does not replace)");
    static_assert(!uv_ok || index_ok, "parameterize(mesh, bhd, uvmap, vimap, vpmap): vimap must map vertex_descriptor to an integer index");
    static_assert(!uv_ok || !index_ok || parameterized_ok,
                  "parameterize(mesh, bhd, uvmap, vimap, vpmap): vpmap must map vertex_descriptor to bool");
    if constexpr(uv_ok && index_ok && parameterized_ok)
      return discrete_lie_flow_cgal_error_code(run(mesh, bhd, uvmap, vimap, vpmap));
    else
      return ERROR_NO_1_TO_1_MAPPING;
  }

  /// \name Calls of CGAL's Iterative_authalic_parameterizer_3
  /// The calls of CGAL's `Iterative_authalic_parameterizer_3`, so that its
  /// programs run with the class name swapped: `iterations` caps the flow's
  /// iterations for this call (`Discrete_lie_flow_options::max_iterations`);
  /// on return, the in/out arguments receive the iterations the flow took and
  /// its area error, CGAL's measure `Σ_t |S_t − Ŝ_t|` of the final map
  /// (`Discrete_lie_flow_distortion::area_total`). The report says more.
  /// @{

  /// \param mesh the mesh
  /// \param bhd a border halfedge of the component to map
  /// \param uvmap receives the map
  /// \param vimap numbers the component's vertices from 0
  /// \param vpmap marks the vertices the initial parameterizer placed
  /// \param iterations in: the cap on the flow's iterations; out: the iterations taken
  /// \param error out: the final map's area error
  template <typename VertexUVmap, typename VertexIndexMap, typename VertexParameterizedMap>
  Error_code parameterize(Triangle_mesh& mesh, halfedge_descriptor bhd, VertexUVmap uvmap, VertexIndexMap vimap,
                          VertexParameterizedMap vpmap, unsigned int& iterations, double& error)
  {
    const std::size_t cap = m_options.max_iterations;
    m_options.max_iterations = iterations;
    const Error_code code = parameterize(mesh, bhd, uvmap, vimap, vpmap);
    m_options.max_iterations = cap;
    iterations = static_cast<unsigned int>(m_report.iterations);
    error = m_report.final_metrics.area_total;
    return code;
  }

  /// \param mesh the mesh
  /// \param bhd a border halfedge of the component to map
  /// \param uvmap receives the map
  /// \param vimap numbers the component's vertices from 0
  /// \param vpmap marks the vertices the initial parameterizer placed
  /// \param iterations in: the cap on the flow's iterations; out: the iterations taken
  template <typename VertexUVmap, typename VertexIndexMap, typename VertexParameterizedMap>
  Error_code parameterize(Triangle_mesh& mesh, halfedge_descriptor bhd, VertexUVmap uvmap, VertexIndexMap vimap,
                          VertexParameterizedMap vpmap, unsigned int& iterations)
  {
    double error = 0;
    return parameterize(mesh, bhd, uvmap, vimap, vpmap, iterations, error);
  }

  /// \param mesh the mesh
  /// \param bhd a border halfedge of the component to map
  /// \param uvmap receives the map
  /// \param vimap numbers the component's vertices from 0
  /// \param vpmap marks the vertices the initial parameterizer placed
  /// \param iterations the cap on the flow's iterations
  template <typename VertexUVmap, typename VertexIndexMap, typename VertexParameterizedMap>
  Error_code parameterize(Triangle_mesh& mesh, halfedge_descriptor bhd, VertexUVmap uvmap, VertexIndexMap vimap,
                          VertexParameterizedMap vpmap, const unsigned int& iterations)
  {
    unsigned int taken = iterations;
    return parameterize(mesh, bhd, uvmap, vimap, vpmap, taken);
  }

  /// Numbers the vertices of `bhd`'s component itself.
  /// \param mesh the mesh
  /// \param bhd a border halfedge of the component to map
  /// \param uvmap receives the map
  /// \param iterations the cap on the flow's iterations
  template <typename VertexUVmap>
  Error_code parameterize(Triangle_mesh& mesh, halfedge_descriptor bhd, VertexUVmap uvmap, const unsigned int iterations)
  {
    const std::size_t cap = m_options.max_iterations;
    m_options.max_iterations = iterations;
    const Error_code code = parameterize(mesh, bhd, uvmap);
    m_options.max_iterations = cap;
    return code;
  }

  /// Numbers the vertices of `bhd`'s component itself; the flow's own cap on iterations.
  /// \param mesh the mesh
  /// \param bhd a border halfedge of the component to map
  /// \param uvmap receives the map
  template <typename VertexUVmap>
  Error_code parameterize(Triangle_mesh& mesh, halfedge_descriptor bhd, VertexUVmap uvmap)
  {
    typedef CGAL::dynamic_vertex_property_t<int> Vertex_int_tag;
    typename boost::property_map<Triangle_mesh, Vertex_int_tag>::type vimap = get(Vertex_int_tag(), mesh);
    // A halfedge that is not on a border is reported by the parameterizer.
    if(bhd != boost::graph_traits<Triangle_mesh>::null_halfedge() && is_border(bhd, mesh))
      internal::fill_index_map_of_cc(bhd, mesh, vimap);
    typedef CGAL::dynamic_vertex_property_t<bool> Vertex_bool_tag;
    typename boost::property_map<Triangle_mesh, Vertex_bool_tag>::type vpmap = get(Vertex_bool_tag(), mesh);
    return parameterize(mesh, bhd, uvmap, vimap, vpmap);
  }

  /// The component of the mesh's longest border.
  /// \param mesh the mesh
  /// \param uvmap receives the map
  /// \param iterations the cap on the flow's iterations
  template <typename VertexUVmap>
  Error_code parameterize(Triangle_mesh& mesh, VertexUVmap uvmap, const unsigned int iterations)
  {
    return parameterize(mesh, Polygon_mesh_processing::longest_border(mesh).first, uvmap, iterations);
  }

  /// The component of the mesh's longest border; the flow's own cap on iterations.
  /// \param mesh the mesh
  /// \param uvmap receives the map
  template <typename VertexUVmap>
  Error_code parameterize(Triangle_mesh& mesh, VertexUVmap uvmap)
  {
    return parameterize(mesh, Polygon_mesh_processing::longest_border(mesh).first, uvmap);
  }

  /// @}

private:
  template <class BorderParameterizer>
  static Initial_parameterizer make_initial(const BorderParameterizer& border)
  {
    constexpr bool buildable = std::is_constructible<Initial_parameterizer, const BorderParameterizer&>::value;
    static_assert(buildable, "Discrete_lie_flow_parameterizer_3(border): the initial parameterizer is not built from "
                             "this border parameterizer; give it as the second template argument instead");
    if constexpr(buildable) return Initial_parameterizer(border);
    else return Initial_parameterizer();
  }

  // The run, with the package's own codes (the report's status).
  template <typename VertexUVmap, typename VertexIndexMap, typename VertexParameterizedMap>
  Error_code run(Triangle_mesh& mesh, halfedge_descriptor bhd, VertexUVmap uvmap,
                 VertexIndexMap vimap, VertexParameterizedMap vpmap)
  {
    typedef std::chrono::steady_clock Clock;
    namespace D = internal::dlf;
    Discrete_lie_flow_report& R = m_report;
    R = Discrete_lie_flow_report();
    auto fail = [&R](int code, const std::string& msg) { return D::report_failure(R, code, msg); };
    if(faces(mesh).empty()) return fail(ERROR_EMPTY_MESH, "");
    if(bhd == boost::graph_traits<Triangle_mesh>::null_halfedge() || !is_border(bhd, mesh))
      return fail(ERROR_NO_TOPOLOGICAL_DISC, "the given halfedge is not on a border");

    // Gather the connected component of bhd, its faces and its border loop.
    D::Disk_problem P;
    std::vector<vertex_descriptor> vertex_of;
    std::vector<face_descriptor> face_of;
    Error_code code = gather(mesh, bhd, vimap, P, vertex_of, face_of);
    if(code != OK) return code;
    m_vertex_of = vertex_of;

    // The solver's threads for the initial map too (Tutte's factorization
    // is as large as a flow step's); flow_disk() keeps them.
    const D::Scoped_blas_threads threads(m_options.solver_threads, vertex_of.size());
    typedef typename std::remove_reference<decltype(m_solver_traits.solver())>::type Eigen_solver;
    std::unique_ptr<D::Tutte_interior_system<Eigen_solver> > tutte;
    std::vector<D::Vec2> uv(vertex_of.size());
    const Clock::time_point t0 = Clock::now();
    // The library's own Tutte start in certified mode, whose start spacing
    // reuses the factorization; the paper's modes keep the caller's.
    if(D::Is_tutte_on_arc_length_circle<Initial_parameterizer, Triangle_mesh>::value && P.fill_faces == 0 &&
       m_options.mode == Discrete_lie_flow_mode::CERTIFIED) {
      code = tutte_start(P, uv, tutte);
      R.seconds_initial = std::chrono::duration<double>(Clock::now() - t0).count();
      if(code != OK) return fail(code, std::string("initial map: ") + discrete_lie_flow_error_message(code));
      for(std::size_t i = 0; i < vertex_of.size(); ++i) {
        put(uvmap, vertex_of[i], Point_2(uv[i][0], uv[i][1]));
        put(vpmap, vertex_of[i], true);
      }
    } else {
      code = m_initial.parameterize(mesh, bhd, uvmap, vimap, vpmap);
      R.seconds_initial = std::chrono::duration<double>(Clock::now() - t0).count();
      if(code != OK) return fail(code, std::string("initial map: ") + discrete_lie_flow_error_message(code));
    }

    // With holes, the initial map is kept only when the filled disk's start
    // built from it certifies (below); its outer loop is needed in any case.
    std::vector<char> taken(vertex_of.size(), P.fill_faces == 0);
    for(int b : P.boundary) taken[std::size_t(b)] = 1;
    bool all_finite = true;
    for(std::size_t i = 0; i < vertex_of.size(); ++i) {
      const Point_2 p = get(uvmap, vertex_of[i]);
      uv[i] = {{ CGAL::to_double(p.x()), CGAL::to_double(p.y()) }};
      const bool finite = std::isfinite(uv[i][0]) && std::isfinite(uv[i][1]);
      all_finite = all_finite && finite;
      if(taken[i] && !finite)
        return fail(ERROR_INITIAL_MAP_FOLDED, "initial map: vertex " + std::to_string(i) + " has a non-finite uv");
    }
    std::string start;
    if(P.fill_faces > 0) {
      // The initial parameterizer does not see the fill.
      const Clock::time_point t1 = Clock::now();
      uv.resize(P.xyz.size(), D::Vec2{{ 0, 0 }});
      code = start_with_holes<Eigen_solver>(P, uv, all_finite, start);
      if(code != OK) return fail(code, "initial map: " + start);
      R.seconds_initial += std::chrono::duration<double>(Clock::now() - t1).count();
    }
    // CGAL's free border (LSCM pinned at two vertices): the border floats,
    // it moves as freely as the interior (boundary_curve.h).
    Discrete_lie_flow_options options = m_options;
    if(options.disk.border == Discrete_lie_flow_border::AUTOMATIC && options.mode == Discrete_lie_flow_mode::CERTIFIED &&
       D::Is_two_vertices_parameterizer<InitialParameterizer_>::value)
      options.disk.border = Discrete_lie_flow_border::FLOATING;
    R.initial_uv.assign(uv.begin(), uv.begin() + std::ptrdiff_t(vertex_of.size()));
    code = D::flow_disk(P, uv, options, m_solver_traits.solver(), R, tutte.get());
    if(code != OK) {
      if(int(code) == int(ERROR_INITIAL_MAP_FOLDED) && P.holes > 0) R.message += " (the start on the disk with filled holes: " + start + ")";
      return code;
    }
    if(P.holes > 0)
      R.message = (R.converged() ? std::string("Success") : R.message) + "; " + std::to_string(P.holes) + (P.holes == 1 ? " hole" : " holes") +
                  " filled for the flow and left free; initial map: " + start;
    for(std::size_t i = 0; i < vertex_of.size(); ++i) put(uvmap, vertex_of[i], Point_2(uv[i][0], uv[i][1]));
    // On a Surface_mesh, the area elements and the densities become properties of the mesh.
    D::store_area_elements(mesh, vertex_of, R.target_area, R.domain_area, face_of, R.face_density);
    return OK;
  }

private:
  // The default initial map, Tutte's with the border on the circle by arc
  // length, from the problem: its factorization stays in `tutte`.
  template <class EigenSolver>
  Error_code tutte_start(const internal::dlf::Disk_problem& P, std::vector<internal::dlf::Vec2>& uv,
                         std::unique_ptr<internal::dlf::Tutte_interior_system<EigenSolver> >& tutte)
  {
    namespace D = internal::dlf;
    if(!D::circle_border_by_arc_length(P, uv)) return ERROR_BORDER_TOO_SHORT;
    // Coarse to fine, the caller's mesh is factorized for this start alone.
    if(D::flows_coarse_to_fine(m_options, P.faces.size())) D::use_amd_ordering(m_solver_traits.solver());
    tutte.reset(new D::Tutte_interior_system<EigenSolver>(P, uv.size(), m_solver_traits.solver()));
    if(tutte->unknowns() > 0 && !tutte->factorized()) return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
    return tutte->solve(uv) ? OK : ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
  }

  // The start of a disk with holes: the initial map itself, each hole's
  // virtual vertex inside the hole (unless the initial parameterizer is the
  // package's Tutte start, whose own map of the filled disk is the same kind
  // of map); else Tutte's embedding of the filled disk inside the initial
  // map's outer loop; else, when that folds, on the circle by arc length.
  // Each start is taken only if the exact predicate finds every face, the
  // fill's included, with one orientation. `start` names the start taken.
  template <class EigenSolver>
  Error_code start_with_holes(internal::dlf::Disk_problem& P, std::vector<internal::dlf::Vec2>& uv, bool all_finite,
                              std::string& start) const
  {
    namespace D = internal::dlf;
    std::string why;
    if(!internal::dlf::Is_symmetric_barycentric<Initial_parameterizer>::value) {
      if(!all_finite) why = "the initial map has non-finite coordinates";
      else if(place_hole_vertices(P, uv, why) && one_orientation(P, uv)) {
        start = "the initial parameterizer's map, each hole's virtual vertex inside the hole";
        return OK;
      }
      else if(why.empty()) why = "the initial map folds";
      why = "the initial parameterizer's map was not kept: " + why + "; ";
    }
    const std::vector<D::Vec2> given(uv);
    if(!D::filled_disk_tutte<EigenSolver>(P, uv))
      { start = why + "the Tutte solve of the disk with filled holes failed"; return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM; }
    if(one_orientation(P, uv)) {
      start = why + "Tutte's embedding of the filled disk inside the initial parameterizer's outer loop";
      return OK;
    }
    // A non-convex outer loop: the circle, whose Tutte embedding is bijective.
    uv = given;
    if(!D::circle_border_by_arc_length(P, uv))
      { start = why + "the outer loop is too short for the circle"; return ERROR_BORDER_TOO_SHORT; }
    if(!D::filled_disk_tutte<EigenSolver>(P, uv))
      { start = why + "the Tutte solve of the disk with filled holes failed"; return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM; }
    start = why + "Tutte's embedding inside the outer loop folds (a non-convex loop); fallback: Tutte's embedding of the "
                  "filled disk on the circle by arc length";
    return OK;
  }

  // Whether every face of `P` has one orientation under `uv`, by the exact predicate.
  static bool one_orientation(const internal::dlf::Disk_problem& P, const std::vector<internal::dlf::Vec2>& uv)
  {
    const internal::dlf::Orientation_count oc = internal::dlf::count_orientations_2(uv, P.faces);
    return oc.degenerate == 0 && (oc.inverted == 0 || oc.inverted == P.faces.size());
  }

  // The caller's orientation in `uv`: the sign of the signed area of its faces.
  static double caller_sign(const internal::dlf::Disk_problem& P, const std::vector<internal::dlf::Vec2>& uv)
  {
    namespace D = internal::dlf;
    double twice_area = 0;
    for(std::size_t f = 0; f < P.caller_faces(); ++f) {
      const D::Vec2 &a = uv[std::size_t(P.faces[f][0])], &b = uv[std::size_t(P.faces[f][1])], &c = uv[std::size_t(P.faces[f][2])];
      twice_area += (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    }
    return twice_area < 0 ? -1 : 1;
  }

  // Places each hole's virtual vertex inside the kernel of its uv polygon
  // (the points that see every loop edge from the fill's side): the kernel
  // is clipped from the loop's bounding box edge by edge, and its vertex
  // mean taken. A hole whose kernel is empty (no point sees the whole
  // polygon) is filled instead by the constrained Delaunay triangulation of
  // its polygon with the virtual vertex inside (as many faces as the fan;
  // their targets share the fan's by uv area). False, with `why`, when a
  // polygon is not simple either.
  static bool place_hole_vertices(internal::dlf::Disk_problem& P, std::vector<internal::dlf::Vec2>& uv, std::string& why)
  {
    namespace D = internal::dlf;
    const double sign = caller_sign(P, uv);
    // Fill faces (a, b, c) come hole by hole, c the hole's virtual vertex, as
    // gathered; a fill replaced below is behind the walk.
    std::size_t f = P.caller_faces();
    while(f < P.faces.size()) {
      const int c = P.faces[f][2];
      const std::size_t first = f;
      std::vector<std::array<D::Vec2, 2> > edges; // oriented so that the kernel is on their left
      std::vector<int> loop;
      D::Vec2 lo = uv[std::size_t(P.faces[f][0])], hi = lo;
      for(; f < P.faces.size() && P.faces[f][2] == c; ++f) {
        const D::Vec2 &a = uv[std::size_t(P.faces[f][0])], &b = uv[std::size_t(P.faces[f][1])];
        loop.push_back(P.faces[f][0]);
        edges.push_back(sign > 0 ? std::array<D::Vec2, 2>{{ a, b }} : std::array<D::Vec2, 2>{{ b, a }});
        for(int k = 0; k < 2; ++k) { lo[std::size_t(k)] = (std::min)(lo[std::size_t(k)], a[std::size_t(k)]); hi[std::size_t(k)] = (std::max)(hi[std::size_t(k)], a[std::size_t(k)]); }
      }
      std::vector<D::Vec2> kernel{{ lo, D::Vec2{{ hi[0], lo[1] }}, hi, D::Vec2{{ lo[0], hi[1] }} }};
      for(const std::array<D::Vec2, 2>& e : edges) {
        auto side = [&e](const D::Vec2& p) {
          return (e[1][0] - e[0][0]) * (p[1] - e[0][1]) - (e[1][1] - e[0][1]) * (p[0] - e[0][0]);
        };
        std::vector<D::Vec2> clipped;
        for(std::size_t i = 0; i < kernel.size(); ++i) {
          const D::Vec2 &p = kernel[i], &q = kernel[(i + 1) % kernel.size()];
          const double sp = side(p), sq = side(q);
          if(sp >= 0) clipped.push_back(p);
          if((sp > 0 && sq < 0) || (sp < 0 && sq > 0)) {
            const double t = sp / (sp - sq);
            clipped.push_back(D::Vec2{{ p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1]) }});
          }
        }
        kernel.swap(clipped);
        if(kernel.empty()) break;
      }
      if(kernel.size() >= 3) {
        D::Vec2 m{{ 0, 0 }};
        for(const D::Vec2& p : kernel) { m[0] += p[0] / double(kernel.size()); m[1] += p[1] / double(kernel.size()); }
        uv[std::size_t(c)] = m;
        continue;
      }
      std::vector<D::Face> fill;
      D::Vec2 at;
      if(!D::triangulate_hole(uv, loop, c, sign, fill, at)) {
        why = "a hole's uv polygon (" + std::to_string(edges.size()) + " edges) is not simple";
        return false;
      }
      uv[std::size_t(c)] = at;
      double target = 0, area = 0;
      std::vector<double> areas;
      for(std::size_t g = first; g < f; ++g) target += P.target[g];
      for(const D::Face& t : fill) {
        const D::Vec2 &a = uv[std::size_t(t[0])], &b = uv[std::size_t(t[1])], &d = uv[std::size_t(t[2])];
        areas.push_back(std::abs((b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0])));
        area += areas.back();
      }
      if(!(area > 0)) { why = "a hole's uv polygon has no area"; return false; }
      for(std::size_t k = 0; k < fill.size(); ++k) {
        P.faces[first + k] = fill[k];
        P.target[first + k] = target * areas[k] / area;
      }
    }
    return true;
  }

  // A face named by the indices of its vertices, the only names every mesh type shares.
  template <typename VertexIndexMap>
  static std::string face_name(const Triangle_mesh& mesh, VertexIndexMap vimap, face_descriptor f)
  {
    std::string s = "(vertices";
    for(vertex_descriptor v : vertices_around_face(halfedge(f, mesh), mesh)) s += " " + std::to_string(long(get(vimap, v)));
    return s + ")";
  }

  // The component of `bhd` in index form: positions, faces, targets, and
  // the holes filled (see `disk_holes.h`).
  template <typename VertexIndexMap>
  Error_code gather(Triangle_mesh& mesh, halfedge_descriptor bhd, VertexIndexMap vimap,
                    internal::dlf::Disk_problem& P, std::vector<vertex_descriptor>& vertex_of,
                    std::vector<face_descriptor>& face_of)
  {
    Error_code code = gather_component(mesh, bhd, vimap, P, vertex_of, face_of);
    if(code == OK) code = gather_targets(mesh, vimap, P, vertex_of, face_of);
    if(code == OK) code = gather_loops(mesh, bhd, vimap, P, face_of);
    return code;
  }

  template <typename VertexIndexMap>
  Error_code gather_component(Triangle_mesh& mesh, halfedge_descriptor bhd, VertexIndexMap vimap,
                              internal::dlf::Disk_problem& P, std::vector<vertex_descriptor>& vertex_of,
                              std::vector<face_descriptor>& face_of)
  {
    namespace D = internal::dlf;
    Discrete_lie_flow_report& R = m_report;
    auto fail = [&R](int code, const std::string& msg) { return D::report_failure(R, code, msg); };
    // Faces of the component, by a walk across non-border edges. Dynamic
    // property maps, not trees of descriptors: millions of faces.
    auto seen = get(CGAL::dynamic_face_property_t<bool>(), mesh);
    for(face_descriptor f : faces(mesh)) put(seen, f, false);
    std::vector<face_descriptor> stack(1, face(opposite(bhd, mesh), mesh));
    put(seen, stack.back(), true);
    while(!stack.empty()) {
      const face_descriptor f = stack.back();
      stack.pop_back();
      for(halfedge_descriptor h : halfedges_around_face(halfedge(f, mesh), mesh)) {
        const halfedge_descriptor o = opposite(h, mesh);
        if(is_border(o, mesh)) continue;
        const face_descriptor g = face(o, mesh);
        if(!get(seen, g)) { put(seen, g, true); stack.push_back(g); }
      }
    }
    // In the order of faces(mesh), so that domain faces follow the input.
    for(face_descriptor f : faces(mesh))
      if(get(seen, f)) face_of.push_back(f);
    auto in_component = get(CGAL::dynamic_vertex_property_t<bool>(), mesh);
    for(vertex_descriptor v : vertices(mesh)) put(in_component, v, false);
    std::vector<vertex_descriptor> vs;
    for(std::size_t k = 0; k < face_of.size(); ++k) {
      std::size_t corners = 0;
      for(vertex_descriptor v : vertices_around_face(halfedge(face_of[k], mesh), mesh)) {
        if(!get(in_component, v)) { put(in_component, v, true); vs.push_back(v); }
        ++corners;
      }
      if(corners != 3)
        return fail(ERROR_NON_TRIANGULAR_MESH, "face " + face_name(mesh, vimap, face_of[k]) + " has " + std::to_string(corners) + " vertices");
    }
    const std::size_t n = vs.size();
    vertex_of.assign(n, vertex_descriptor());
    std::vector<bool> used(n, false);
    for(vertex_descriptor v : vs) {
      const long i = long(get(vimap, v));
      if(i < 0 || std::size_t(i) >= n || used[std::size_t(i)])
        return fail(ERROR_WRONG_PARAMETER, "the vertex index map does not number the component's vertices 0.." + std::to_string(n - 1));
      used[std::size_t(i)] = true;
      vertex_of[std::size_t(i)] = v;
    }
    const typename internal::Kernel_traits<Triangle_mesh>::PPM ppmap = get(vertex_point, mesh);
    P.xyz.resize(n);
    for(std::size_t i = 0; i < n; ++i) {
      const auto& p = get(ppmap, vertex_of[i]);
      P.xyz[i] = {{ CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()) }};
      if(!std::isfinite(P.xyz[i][0]) || !std::isfinite(P.xyz[i][1]) || !std::isfinite(P.xyz[i][2]))
        return fail(Error_code(ERROR_DEGENERATE_INPUT), "vertex " + std::to_string(i) + " has a non-finite coordinate");
    }
    for(face_descriptor f : face_of) {
      D::Face t;
      int k = 0;
      for(vertex_descriptor v : vertices_around_face(halfedge(f, mesh), mesh)) t[k++] = int(get(vimap, v));
      P.faces.push_back(t);
    }
    return OK;
  }

  // Targets: ρ_f · area_M(f); options.face_density follows faces(mesh).
  template <typename VertexIndexMap>
  Error_code gather_targets(Triangle_mesh& mesh, VertexIndexMap vimap, internal::dlf::Disk_problem& P,
                            const std::vector<vertex_descriptor>& vertex_of, const std::vector<face_descriptor>& face_of)
  {
    namespace D = internal::dlf;
    Discrete_lie_flow_report& R = m_report;
    auto fail = [&R](int code, const std::string& msg) { return D::report_failure(R, code, msg); };
    auto position = get(CGAL::dynamic_face_property_t<std::size_t>(), mesh);
    if(!m_face_density && !m_vertex_density && !m_options.face_density.empty()) {
      std::size_t count = 0;
      for(face_descriptor f : faces(mesh)) put(position, f, count++);
      if(m_options.face_density.size() != count)
        return fail(Error_code(ERROR_INVALID_DENSITY), "the density has " + std::to_string(m_options.face_density.size()) +
                    " values for " + std::to_string(count) + " faces");
    }
    P.target.resize(P.faces.size());
    for(std::size_t f = 0; f < P.faces.size(); ++f) {
      const D::Face& t = P.faces[f];
      const double a = D::triangle_area_3(P.xyz[t[0]], P.xyz[t[1]], P.xyz[t[2]]);
      if(!(a > 0) || !std::isfinite(a))
        return fail(Error_code(ERROR_DEGENERATE_INPUT), "face " + face_name(mesh, vimap, face_of[f]) + " has zero area");
      double rho = 1;
      if(m_face_density) rho = m_face_density(face_of[f]);
      else if(m_vertex_density) {
        rho = 0;
        for(int k = 0; k < 3; ++k) {
          const double r = m_vertex_density(vertex_of[std::size_t(t[k])]);
          if(!(r > 0) || !std::isfinite(r))
            return fail(Error_code(ERROR_INVALID_DENSITY), "the density of vertex " + std::to_string(t[k]) + " is " + std::to_string(r));
          rho += r / 3;
        }
      }
      else if(!m_options.face_density.empty()) rho = m_options.face_density[get(position, face_of[f])];
      if(!(rho > 0) || !std::isfinite(rho))
        return fail(Error_code(ERROR_INVALID_DENSITY), "the density of face " + face_name(mesh, vimap, face_of[f]) + " is " + std::to_string(rho));
      P.target[f] = rho * a;
    }
    return OK;
  }

  // The border loops, bhd's first: the outer loop becomes `P.boundary`,
  // the topology is checked, and every other loop is filled.
  template <typename VertexIndexMap>
  Error_code gather_loops(Triangle_mesh& mesh, halfedge_descriptor bhd, VertexIndexMap vimap,
                          internal::dlf::Disk_problem& P, const std::vector<face_descriptor>& face_of)
  {
    namespace D = internal::dlf;
    Discrete_lie_flow_report& R = m_report;
    auto fail = [&R](int code, const std::string& msg) { return D::report_failure(R, code, msg); };
    const std::size_t n = P.xyz.size();
    std::vector<std::vector<halfedge_descriptor> > loops(1);
    auto walked = get(CGAL::dynamic_halfedge_property_t<bool>(), mesh);
    for(halfedge_descriptor h : halfedges(mesh)) put(walked, h, false);
    for(halfedge_descriptor h : halfedges_around_face(bhd, mesh)) { loops[0].push_back(h); put(walked, h, true); }
    std::size_t border_edges = 0;
    for(face_descriptor f : face_of)
      for(halfedge_descriptor h : halfedges_around_face(halfedge(f, mesh), mesh)) {
        const halfedge_descriptor o = opposite(h, mesh);
        if(!is_border(o, mesh)) continue;
        ++border_edges;
        if(get(walked, o)) continue;
        put(walked, o, true);
        loops.emplace_back(1, o);
        for(halfedge_descriptor b = next(o, mesh); b != o; b = next(b, mesh)) { loops.back().push_back(b); put(walked, b, true); }
      }
    for(halfedge_descriptor h : loops[0]) P.boundary.push_back(int(get(vimap, target(h, mesh))));
    if(P.boundary.size() < 3) return fail(ERROR_BORDER_TOO_SHORT, "the border has fewer than 3 vertices");
    // χ = V − E + F = 2 − 2g − (loops): a disk has one loop and χ = 1; a
    // genus-0 mesh with holes has χ = 2 − loops.
    const std::size_t E = (3 * P.faces.size() + border_edges) / 2;
    const long chi = long(n) - long(E) + long(P.faces.size());
    if(loops.size() == 1 && chi == 1) return OK;
    const long twice_genus = 2 - chi - long(loops.size());
    if(twice_genus != 0) {
      std::string s = "the component has " + std::to_string(loops.size()) + " border loop" +
                      (loops.size() == 1 ? "" : "s") + " (" + std::to_string(border_edges) + " border edges, " +
                      std::to_string(P.boundary.size()) + " on the given loop), Euler characteristic " + std::to_string(chi);
      if(twice_genus > 0 && twice_genus % 2 == 0) s += ", genus " + std::to_string(twice_genus / 2);
      if(face_of.size() < faces(mesh).size())
        s += "; it is one of the mesh's connected components (" + std::to_string(face_of.size()) + " of " +
             std::to_string(faces(mesh).size()) + " faces)";
      return fail(ERROR_NO_TOPOLOGICAL_DISC, s + "; the parameterizer takes genus 0: a disk, or a disk with holes");
    }
    // Genus 0 with holes: fill every other loop. A vertex on two loops
    // (or twice on one) would give the fill a repeated edge.
    std::vector<char> on_loop(n, 0);
    for(const std::vector<halfedge_descriptor>& loop : loops)
      for(halfedge_descriptor h : loop) {
        const std::size_t v = std::size_t(get(vimap, target(h, mesh)));
        if(on_loop[v]++)
          return fail(ERROR_NO_TOPOLOGICAL_DISC, "vertex " + std::to_string(v) + " lies twice on the border loops "
                      "(a pinched border); a disk with holes needs them disjoint");
      }
    auto index_of = get(CGAL::dynamic_face_property_t<std::size_t>(), mesh);
    for(std::size_t k = 0; k < face_of.size(); ++k) put(index_of, face_of[k], k);
    for(std::size_t l = 1; l < loops.size(); ++l) {
      std::vector<int> loop;
      std::vector<std::size_t> across;
      // The border halfedge s → t: the fill face (s, t, c) has the caller's orientation.
      for(halfedge_descriptor h : loops[l]) {
        loop.push_back(int(get(vimap, source(h, mesh))));
        across.push_back(get(index_of, face(opposite(h, mesh), mesh)));
      }
      D::fill_hole(P, loop, across);
    }
    return OK;
  }

  Initial_parameterizer m_initial;
  Discrete_lie_flow_options m_options;
  Solver_traits m_solver_traits;
  std::function<double(face_descriptor)> m_face_density;
  std::function<double(vertex_descriptor)> m_vertex_density;
  // The last run: its report and the vertex of each index.
  Discrete_lie_flow_report m_report;
  std::vector<vertex_descriptor> m_vertex_of;
};

/// \ingroup PkgDiscreteLieFlowParameterizers
/// CGAL's `parameterize(mesh, parameterizer, bhd, uvmap)` for a named
/// `Discrete_lie_flow_parameterizer_3`: the generic function takes its
/// parameterizer by value, this one runs `parameterizer` itself, so that
/// `parameterizer.report()` describes the call. Same maps and result as the
/// generic function.
template <class TriangleMesh, class InitialParameterizer, class SolverTraits, class HD, class VertexUVmap>
Error_code parameterize(TriangleMesh& mesh,
                        Discrete_lie_flow_parameterizer_3<TriangleMesh, InitialParameterizer, SolverTraits>& parameterizer,
                        HD bhd, VertexUVmap uvmap)
{
  return parameterizer.parameterize(mesh, bhd, uvmap);
}

/// \ingroup PkgDiscreteLieFlowParameterizers
/// CGAL's `parameterize(mesh, Parameterizer(), bhd, uvmap)` for a temporary
/// `Discrete_lie_flow_parameterizer_3`: the same as for a named one (a
/// halfedge that is not on a border is reported, not dereferenced).
template <class TriangleMesh, class InitialParameterizer, class SolverTraits, class HD, class VertexUVmap>
Error_code parameterize(TriangleMesh& mesh,
                        Discrete_lie_flow_parameterizer_3<TriangleMesh, InitialParameterizer, SolverTraits>&& parameterizer,
                        HD bhd, VertexUVmap uvmap)
{
  return parameterizer.parameterize(mesh, bhd, uvmap);
}

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif
