// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Consumer of an installed Discrete Lie Flow: runs the README's C++ snippet,
// compiled as is, on a disk mesh and checks what it computed, then checks
// the version macros against the version of the CMake package.
//
// Usage: dlf_consumer mesh.off   (a disk-topology triangle mesh)

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/measure.h>

#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>

typedef CGAL::Simple_cartesian<double> Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
typedef boost::graph_traits<Mesh>::halfedge_descriptor halfedge_descriptor;
typedef boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
typedef Mesh::Property_map<vertex_descriptor, Kernel::Point_2> UV_map;

// The README's #include lines and namespace alias, nothing else before the
// snippet: it must compile with what it includes itself.
#include "readme_snippet_head.inc"

static int failures = 0;

static void check(bool ok, const std::string& what)
{
  std::cout << (ok ? "ok:     " : "FAILED: ") << what << std::endl;
  if(!ok) ++failures;
}

static void run_readme_snippet(Mesh& mesh, halfedge_descriptor bhd, UV_map uvmap)
{
#include "readme_snippet_body.inc"
  check(err == SMP::OK, err == SMP::OK ? std::string("parameterize() returns OK")
                                        : std::string("parameterize() returns OK, not ") +
                                            SMP::discrete_lie_flow_error_name(err) + ": " + dlf.report().message);
  check(dlf.report().status == SMP::OK, "report status OK");
  check(dlf.report().iterations > 0, "the flow ran (" + std::to_string(dlf.report().iterations) + " iterations)");
  check(dlf.report().final_d_area <= 2.01, "final d_area " + std::to_string(dlf.report().final_d_area) + " <= 2.01");
  check(dlf.report().caller_inverted_faces == 0, "no inverted triangle");
}

// Every public header, after the snippet so that it cannot supply what the
// snippet forgot; a header missing from the install fails the build here.
#include "all_public_headers.inc"

static_assert(DISCRETE_LIE_FLOW_VERSION_MAJOR == DLF_EXPECTED_MAJOR &&
              DISCRETE_LIE_FLOW_VERSION_MINOR == DLF_EXPECTED_MINOR &&
              DISCRETE_LIE_FLOW_VERSION_PATCH == DLF_EXPECTED_PATCH,
              "the version macros differ from the version of the CMake package");
static_assert(DISCRETE_LIE_FLOW_VERSION_NR ==
                DISCRETE_LIE_FLOW_VERSION_NUMBER(DLF_EXPECTED_MAJOR, DLF_EXPECTED_MINOR, DLF_EXPECTED_PATCH),
              "DISCRETE_LIE_FLOW_VERSION_NR does not encode the package version");
#if defined(CGAL_DLF_USE_CHOLMOD) != DLF_EXPECT_CHOLMOD
#error "CGAL_DLF_USE_CHOLMOD does not match DiscreteLieFlow_WITH_CHOLMOD of the CMake package"
#endif

int main(int argc, char** argv)
{
  if(argc != 2) {
    std::cerr << "usage: " << argv[0] << " mesh.off  (a disk-topology triangle mesh)" << std::endl;
    return EXIT_FAILURE;
  }
  check(std::strcmp(DISCRETE_LIE_FLOW_VERSION_STR, DLF_EXPECTED_VERSION) == 0,
        std::string("DISCRETE_LIE_FLOW_VERSION_STR ") + DISCRETE_LIE_FLOW_VERSION_STR + " == package version " +
          DLF_EXPECTED_VERSION);

  Mesh mesh;
  if(!CGAL::Polygon_mesh_processing::IO::read_polygon_mesh(argv[1], mesh) || faces(mesh).empty()) {
    std::cerr << "dlf_consumer: cannot read a mesh from " << argv[1] << std::endl;
    return EXIT_FAILURE;
  }
  const halfedge_descriptor bhd = CGAL::Polygon_mesh_processing::longest_border(mesh).first;
  if(bhd == boost::graph_traits<Mesh>::null_halfedge()) {
    std::cerr << "dlf_consumer: " << argv[1] << " has no border (a disk is needed)" << std::endl;
    return EXIT_FAILURE;
  }
  UV_map uvmap = mesh.add_property_map<vertex_descriptor, Kernel::Point_2>("v:uv").first;
  std::cout << argv[1] << ": " << num_faces(mesh) << " faces, DiscreteLieFlow " << DISCRETE_LIE_FLOW_VERSION_STR
            << (DLF_EXPECT_CHOLMOD ? " with CHOLMOD" : "") << std::endl;
  run_readme_snippet(mesh, bhd, uvmap);
  std::cout << (failures == 0 ? "dlf_consumer: all checks passed" : "dlf_consumer: checks FAILED") << std::endl;
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
