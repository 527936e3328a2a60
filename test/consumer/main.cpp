// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Consumer of an installed Discrete Lie Flow: runs the README's C++ program,
// compiled as is, on a disk mesh and checks what it printed, then checks
// the version macros against the version of the CMake package.
//
// Usage: dlf_consumer mesh.off   (a disk-topology triangle mesh)

// The README's program first, nothing before it: it must compile with what
// it includes itself. Its main, renamed readme_main by CMakeLists.txt, is
// called by the one below.
#include "readme_program.inc"

#include <cstdlib>
#include <cstring>
#include <iostream>
#include <sstream>
#include <string>

static int failures = 0;

static void check(bool ok, const std::string& what)
{
  std::cout << (ok ? "ok:     " : "FAILED: ") << what << std::endl;
  if(!ok) ++failures;
}

// Every public header, after the program so that it cannot supply what the
// program forgot; a header missing from the install fails the build here.
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
  std::cout << argv[1] << ": DiscreteLieFlow " << DISCRETE_LIE_FLOW_VERSION_STR
            << (DLF_EXPECT_CHOLMOD ? " with CHOLMOD" : "") << std::endl;

  // The README's program on the mesh, what it prints captured:
  // "converged, d_area D".
  std::ostringstream printed;
  std::streambuf* const cout_buffer = std::cout.rdbuf(printed.rdbuf());
  char name[] = "flatten";
  char* args[] = { name, argv[1], nullptr };
  const int code = readme_main(2, args);
  std::cout.rdbuf(cout_buffer);
  std::string line = printed.str();
  if(!line.empty() && line.back() == '\n') line.pop_back();
  check(code == 0, "the README's program exits with " + std::to_string(code) + " (0 expected)");
  const std::string prefix = "converged, d_area ";
  const bool converged = line.compare(0, prefix.size(), prefix) == 0;
  check(converged, "it prints '" + prefix + "D': " + line);
  const double d_area = converged ? std::strtod(line.c_str() + prefix.size(), nullptr) : 0;
  check(d_area >= 2 && d_area <= 2.01, "its d_area " + std::to_string(d_area) + " is in [2, 2.01]");
  std::cout << (failures == 0 ? "dlf_consumer: all checks passed" : "dlf_consumer: checks FAILED") << std::endl;
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
