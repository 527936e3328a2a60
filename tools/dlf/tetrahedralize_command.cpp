// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// `dlf tetrahedralize`: a tetrahedral mesh of the solid a closed surface
// bounds, by CGAL's Mesh_3, written as Medit `.mesh` (the input of
// `dlf volume`). In its own translation unit: Mesh_3 compiles slowly, and
// builds configured with DLF_WITH_TETRAHEDRALIZE=OFF (the sanitizer build)
// leave it out.

#include "arguments.h"
#include "cli_error.h"
#include "commands.h"

#ifdef DLF_WITHOUT_TETRAHEDRALIZE

namespace dlf_cli {

int tetrahedralize_command(const std::vector<std::string>&)
{
  throw Cli_error("'dlf tetrahedralize' is not available: this dlf was built without CGAL's Mesh_3 (CMake option "
                  "DLF_WITH_TETRAHEDRALIZE=OFF); 'dlf volume' reads the Medit .mesh of any tetrahedral mesher",
                  EXIT_FLOW_ERROR);
}

} // namespace dlf_cli

#else

#include "mesh_input.h"
#include "output_files.h"

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_medit.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_tet_mesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polyhedral_mesh_domain_3.h>
#include <CGAL/Random.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/make_mesh_3.h>

#include <boost/program_options.hpp>

#include <array>
#include <chrono>
#include <cmath>
#include <iostream>
#include <map>

namespace dlf_cli {

namespace {

namespace po = boost::program_options;
namespace SMP = CGAL::Surface_mesh_parameterization;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Polyhedron;
typedef CGAL::Polyhedral_mesh_domain_3<Polyhedron, K> Mesh_domain;
typedef CGAL::Mesh_triangulation_3<Mesh_domain, CGAL::Default, CGAL::Sequential_tag>::type Tr;
typedef CGAL::Mesh_complex_3_in_triangulation_3<Tr> C3t3;
typedef CGAL::Mesh_criteria_3<Tr> Mesh_criteria;

const char* tetrahedralize_help =
  "Usage: dlf tetrahedralize SURFACE -o OUT.mesh [--tets N | --size S] [options]\n"
  "\n"
  "Meshes the solid bounded by a closed genus-0 triangle surface with\n"
  "tetrahedra (CGAL's Mesh_3, a fixed seed) and writes Medit .mesh:\n"
  "the input of 'dlf volume'. Only the vertices of the tetrahedra are written.\n"
  "The border triangles' size bound is --facet-ratio times the tetrahedra's:\n"
  "thin parts then get interior vertices, and few tetrahedra have all four\n"
  "corners on the border (those limit how well 'dlf volume' can give every\n"
  "tetrahedron its share; --facet-ratio 1 is Mesh_3's usual uniform sizing).\n"
  "\n"
  "Examples:\n"
  "  dlf tetrahedralize build/data/meshes/bunny00.off -o bunny.mesh --tets 20000\n"
  "  dlf tetrahedralize camel.off -o camel.mesh --size 0.02 --no-optimize\n";

/// The cells of the complex as index arrays, their vertices numbered in
/// order of appearance.
void complex_cells(const C3t3& c3t3, std::vector<Vec3>& points, std::vector<std::array<int, 4> >& tets)
{
  std::map<Tr::Vertex_handle, int> index;
  points.clear();
  tets.clear();
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c) {
    std::array<int, 4> t;
    for(int k = 0; k < 4; ++k) {
      auto it = index.find(c->vertex(k));
      if(it == index.end()) {
        it = index.emplace(c->vertex(k), int(points.size())).first;
        const auto& p = c3t3.triangulation().point(c->vertex(k));
        points.push_back({{ CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()) }});
      }
      t[std::size_t(k)] = it->second;
    }
    tets.push_back(t);
  }
}

} // namespace

int tetrahedralize_command(const std::vector<std::string>& args)
{
  std::string output, input;
  double size = 0, facet_ratio = 4, distance_ratio = 0.05;
  std::size_t target_tets = 0;
  po::options_description visible("Options");
  visible.add_options()
    ("help,h", "this help")
    ("output,o", po::value<std::string>(&output)->value_name("OUT.mesh"), "the Medit .mesh to write")
    ("tets", po::value<std::size_t>(&target_tets)->value_name("N"),
     "the tetrahedra's size bound derived from N and the solid's volume (default 10000; Mesh_3 makes about N tetrahedra on CGAL's meshes)")
    ("size", po::value<double>(&size)->value_name("S"),
     "the tetrahedra's size bound as a fraction of the bounding box's diagonal (instead of --tets)")
    ("facet-ratio", po::value<double>(&facet_ratio)->value_name("F"),
     "the border triangles' size bound over the tetrahedra's, in [1, 10] (default 4)")
    ("distance-ratio", po::value<double>(&distance_ratio)->value_name("D"),
     "the border triangles' distance bound to the surface over their size bound (default 0.05)")
    ("no-optimize", "skip the sliver perturbation and exudation (faster, worse tetrahedra)")
    ("quiet,q", "print nothing on success");
  const po::variables_map vm = parse_command_line("tetrahedralize", args, visible, "input");
  if(vm.count("help")) {
    std::cout << tetrahedralize_help << "\n" << visible;
    return EXIT_OK;
  }
  const std::vector<std::string> inputs = positional_arguments(vm, "input");
  if(inputs.size() != 1) throw Cli_error("expected one input surface (see 'dlf tetrahedralize --help')");
  input = inputs[0];
  if(output.empty()) throw Cli_error("missing -o OUT.mesh");
  if(vm.count("tets") && vm.count("size")) throw Cli_error("--tets and --size exclude each other");
  if(vm.count("size") && !(size > 0 && size < 1)) throw Cli_error("--size must lie in (0, 1)");
  if(vm.count("tets") && target_tets < 10) throw Cli_error("--tets must be at least 10");
  if(!vm.count("size") && !vm.count("tets")) target_tets = 10000;
  if(!(facet_ratio >= 1 && facet_ratio <= 10)) throw Cli_error("--facet-ratio must lie in [1, 10]");
  if(!(distance_ratio > 0 && distance_ratio <= 1)) throw Cli_error("--distance-ratio must lie in (0, 1]");
  const bool quiet = vm.count("quiet") != 0;
  Output_files files;
  files.declare(output, "-o");

  const Indexed_mesh surface = read_triangle_mesh(input);
  Polyhedron poly;
  std::vector<Polyhedron::Vertex_index> vi;
  for(const Vec3& p : surface.xyz) vi.push_back(poly.add_vertex(K::Point_3(p[0], p[1], p[2])));
  for(std::size_t f = 0; f < surface.faces.size(); ++f) {
    const Triangle& t = surface.faces[f];
    if(poly.add_face(vi[std::size_t(t[0])], vi[std::size_t(t[1])], vi[std::size_t(t[2])]) == Polyhedron::null_face())
      throw Cli_error(input + ": face " + std::to_string(f) + " makes the surface non-manifold");
  }
  if(!CGAL::is_closed(poly))
    throw Cli_error(input + ": the surface has a border; the solid needs a closed surface");
  const long long chi = (long long)(poly.number_of_vertices()) - (long long)(poly.number_of_edges()) +
                        (long long)(poly.number_of_faces());
  if(chi != 2)
    throw Cli_error(input + ": the surface has Euler characteristic " + std::to_string(chi) +
                    "; a ball's border is one sphere (2)");
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(poly);
  const double diag = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                CGAL::square(box.zmax() - box.zmin()));
  double s = size * diag;
  if(!vm.count("size")) {
    const double volume = std::abs(CGAL::to_double(CGAL::Polygon_mesh_processing::volume(poly)));
    if(!(volume > 0)) throw Cli_error(input + ": the surface bounds no volume");
    // A regular tet of edge a has volume a³/(6√2); Mesh_3's cells are not
    // regular and come out smaller than the bound: 0.8 a gives about N.
    s = 0.8 * std::cbrt(6 * std::sqrt(2.) * volume / double(target_tets));
  }
  const auto t0 = std::chrono::steady_clock::now();
  Mesh_domain domain(poly);
  namespace params = CGAL::parameters;
  const double facet = facet_ratio * s;
  Mesh_criteria criteria(params::facet_angle = 25, params::facet_size = facet,
                         params::facet_distance = distance_ratio * facet, params::cell_radius_edge_ratio = 3,
                         params::cell_size = s);
  // Mesh_3's manifold criterion holds for the surface it refines; the sliver
  // perturbation and exudation that follow can still leave two cells of the
  // complex meeting at a border edge (homer at --tets 20000). Such a mesh
  // is not a ball: it is made again without exudation, then without either.
  struct Attempt { bool perturb, exude; const char* name; };
  const std::vector<Attempt> attempts = vm.count("no-optimize")
    ? std::vector<Attempt>{ { false, false, "" } }
    : std::vector<Attempt>{ { true, true, "" }, { true, false, " (without exudation: the exuded mesh was not a ball)" },
                            { false, false, " (without optimisation: the optimised meshes were not balls)" } };
  std::vector<Vec3> points;
  std::vector<std::array<int, 4> > tets;
  SMP::Discrete_lie_flow_ball_border border;
  std::string message, note;
  for(const Attempt& attempt : attempts) {
    CGAL::get_default_random() = CGAL::Random(0);
    const C3t3 c3t3 = CGAL::make_mesh_3<C3t3>(domain, criteria, params::manifold(),
                                              attempt.perturb ? params::perturb() : params::no_perturb(),
                                              attempt.exude ? params::exude() : params::no_exude());
    complex_cells(c3t3, points, tets);
    if(tets.empty()) throw Cli_error(input + ": Mesh_3 produced no tetrahedra (an inside-out or open surface?)");
    border = SMP::Discrete_lie_flow_ball_border();
    if(SMP::discrete_lie_flow_ball_border(points, tets, border, message) == SMP::OK) { note = attempt.name; message.clear(); break; }
  }
  if(!message.empty())
    throw Cli_error(input + ": the tetrahedral mesh is not a ball (" + message + "); try a smaller --size", EXIT_FLOW_ERROR);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  files.write(output, [&](std::ostream& os) {
    SMP::write_medit_tet_mesh(os, points, tets, std::vector<int>(tets.size(), 1), border.faces);
  });
  files.commit();
  if(!quiet)
    std::cout << "tetrahedralize: " << points.size() << " vertices (" << border.vertices << " on the border), "
              << tets.size() << " tetrahedra, " << seconds << " s -> " << output << note << std::endl;
  return EXIT_OK;
}

} // namespace dlf_cli

#endif // DLF_WITHOUT_TETRAHEDRALIZE
