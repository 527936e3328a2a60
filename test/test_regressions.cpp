// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Regression tests of the findings of the fuzz target (fuzz/dlf_fuzz.cpp):
// each input is the reduced file that failed, and each test fails without
// its fix (some only under the sanitizers, which .ci/sanitize runs).

#include <gtest/gtest.h>

// The reader is part of the `dlf` tool, not of the library, and the test
// executable does not link the tool's objects: compile it in.
#include "../tools/dlf/mesh_input.cpp"
#include "../tools/dlf/surface_mesh.h"

#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_parameterizer_3.h>

#include <Eigen/SparseCholesky>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <cstdio>
#include <fstream>
#include <string>

// The tests compile in unity batches (DLF_UNITY_BUILD): each file keeps its
// names in a namespace of its own.
namespace dlf_test_regressions {

namespace {

using dlf_cli::Cli_error;
using dlf_cli::Indexed_mesh;

// Writes `text` to a scratch file with the given extension and reads it.
// CTest runs each test as its own process, several at once: the file is
// named after the test, so two tests never share it.
Indexed_mesh read_text(const std::string& text, const std::string& extension = ".off")
{
  const testing::TestInfo* test = testing::UnitTest::GetInstance()->current_test_info();
  const std::string path = testing::TempDir() + "dlf_regression_" + test->test_suite_name() + "_" + test->name() +
                           extension;
  {
    std::ofstream out(path, std::ios::binary);
    out << text;
  }
  struct Remove { std::string p; ~Remove() { std::remove(p.c_str()); } } remove{ path };
  return dlf_cli::read_triangle_mesh(path);
}

// The header of a binary OFF file with these counts (big-endian 32-bit).
std::string binary_off_header(std::uint32_t vertices, std::uint32_t faces)
{
  std::string text = "OFF BINARY\n";
  for(const std::uint32_t n : { vertices, faces, std::uint32_t(0) })
    for(int b = 3; b >= 0; --b) text += char((n >> (8 * b)) & 0xff);
  return text;
}

std::string cli_error_of(const std::string& text)
{
  try {
    read_text(text);
  } catch(const Cli_error& e) {
    return e.what();
  }
  return "(no error)";
}

} // namespace

// CGAL's OFF reader resizes its arrays to the header's counts before reading
// a vertex: a 30-byte file asked for ~100 GB (bad_alloc, or the OOM killer
// where memory is overcommitted).
TEST(Regression, OffCountsBeyondTheFileSizeAreRefusedBeforeAllocating)
{
  EXPECT_NE(cli_error_of("OFF\n2000000000 2000000000 0\n0 0 0\n").find("header announces 2000000000 vertices"),
            std::string::npos);
  EXPECT_NE(cli_error_of("OFF 100000000 1 0\n0 0 0\n").find("more than the file's"), std::string::npos);
  EXPECT_NE(cli_error_of(binary_off_header(1000, 1)).find("header announces 1000 vertices"), std::string::npos);
  // Counts that fit are left to CGAL (here: too few vertex lines).
  EXPECT_NE(cli_error_of("OFF\n3 1 0\n0 0 0\n1 0 0\n").find("cannot read"), std::string::npos);
}

// CGAL's reader resized a face to the number at the start of its line
// before checking it against the line: a negative size was converted from
// double to std::size_t (UB, then std::length_error escaped the reader), a
// large one allocated gigabytes.
TEST(Regression, OffFaceSizesAreCheckedAgainstTheirLine)
{
  const std::string vertices = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n";
  EXPECT_NE(cli_error_of(vertices + "-2 0 1\n").find("cannot read"), std::string::npos);
  EXPECT_NE(cli_error_of(vertices + "1000000000 0 1 2\n").find("cannot read"), std::string::npos);
  EXPECT_NE(cli_error_of(vertices + "3.5 0 1 2\n").find("cannot read"), std::string::npos);
  EXPECT_NE(cli_error_of(vertices + "3 0 1 7\n").find("cannot read"), std::string::npos);
  EXPECT_NE(cli_error_of(vertices + "3 0 1\n").find("cannot read"), std::string::npos);
  // A colour after the indices is ignored.
  EXPECT_EQ(read_text(vertices + "3 0 1 2 255 0 0\n").faces.size(), 1u);
}

// Binary OFF: a negative vertex count became a huge std::size_t in CGAL's
// header (std::length_error escaped the reader).
TEST(Regression, BinaryOffNegativeCountsAreRefused)
{
  const std::string text = binary_off_header(std::uint32_t(-1), 1) + std::string(64, '\0');
  EXPECT_NE(cli_error_of(text).find("cannot read"), std::string::npos);
}

// CGAL 5.5's binary OFF header computed 2 × the edge count in an int
// (signed overflow on 1,258,291,200 edges), and its face reader allocated a
// face of the size the file claims (5.6 GB) before reading it: binary OFF is
// read by the tool now, every count checked against the bytes left.
TEST(Regression, BinaryOffIsReadWithItsCountsChecked)
{
  auto word = [](std::uint32_t n) {
    std::string w;
    for(int b = 3; b >= 0; --b) w += char((n >> (8 * b)) & 0xff);
    return w;
  };
  auto real = [&word](float x) {
    std::uint32_t u;
    std::memcpy(&u, &x, 4);
    return word(u);
  };
  std::string vertices;
  for(float x : { 0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f }) vertices += real(x);
  auto file = [&](std::uint32_t edges, const std::string& faces) {
    return "OFF BINARY\n" + word(3) + word(1) + word(edges) + vertices + faces;
  };
  const std::string face = word(3) + word(0) + word(1) + word(2);
  // A valid file, with a colour after the face, and a huge edge count (unused).
  const Indexed_mesh m = read_text(file(1258291200u, face + word(3) + real(1) + real(0) + real(0)));
  ASSERT_EQ(m.xyz.size(), 3u);
  ASSERT_EQ(m.faces.size(), 1u);
  EXPECT_EQ(m.xyz[1][0], 1.);
  EXPECT_EQ(m.xyz[2][1], 1.);
  EXPECT_EQ(m.faces[0][2], 2);
  // A face size beyond the file, an index out of range, a negative colour count, a truncated face.
  EXPECT_NE(cli_error_of(file(0, word(1400000000u) + word(0))).find("cannot read"), std::string::npos);
  EXPECT_NE(cli_error_of(file(0, word(3) + word(0) + word(1) + word(3) + word(0))).find("cannot read"), std::string::npos);
  EXPECT_NE(cli_error_of(file(0, face + word(std::uint32_t(-2)))).find("cannot read"), std::string::npos);
  EXPECT_NE(cli_error_of(file(0, word(3) + word(0))).find("cannot read"), std::string::npos);
  // Binary variants with colours or normals are refused by name.
  std::string coloured = file(0, face + word(0));
  coloured.replace(0, 3, "COFF");
  EXPECT_NE(cli_error_of(coloured).find("binary COFF"), std::string::npos);
}

// CGAL 5.5 reads a colour past the values of a vertex line that has fewer
// colour components than three (through a null pointer when the line has no
// number at all), and converts out-of-range colours to unsigned char (UB);
// colours are ignored now.
TEST(Regression, ColouredOffWithShortOrOutOfRangeColoursIsRead)
{
  EXPECT_NE(cli_error_of("COFF\n3 1 0\nx\n1 0 0\n0 1 0\n3 0 1 2\n").find("cannot read"), std::string::npos);
  const Indexed_mesh m = read_text("# comment first\nCOFF\n3 1 0\n0 0 0 0.5 0.5\n1 0 0 1785 2 3\n0 1 0\n3 0 1 2\n");
  ASSERT_EQ(m.xyz.size(), 3u);
  ASSERT_EQ(m.faces.size(), 1u);
  EXPECT_EQ(m.xyz[1][0], 1.);
  EXPECT_EQ(m.xyz[2][1], 1.);
}

// With texture coordinates announced (ST) and no colours, CGAL 5.5 indexes
// the vertex line's values with an uninitialised member.
TEST(Regression, TexturedOffWithoutTextureValuesIsRead)
{
  const Indexed_mesh m = read_text("STCNOFF\n3 1 0\n0 0 0\n1 0 0 0 0 1\n0 1 0 0 0 1 0.5 0.5 0.5 1 1\n3 0 1 2\n");
  ASSERT_EQ(m.xyz.size(), 3u);
  EXPECT_EQ(m.xyz[2][1], 1.);
  EXPECT_EQ(m.faces[0][2], 2);
}

// A relaxation sweep evaluated a moved face's area with its corners rotated
// (the moved vertex first), the flow then recomputed it in the face's own
// order: on a strip of needles 10⁶ away from the origin the two roundings
// disagreed on the sign of one area, and the certified run reported d_area
// +inf (found with Eigen's LDLᵀ, the solver the fuzz target links).
TEST(Regression, RelaxationAndFlowAgreeOnTheSignOfEveryArea)
{
  const Indexed_mesh mesh = read_text(
    "OFF\n16 18 0\n"
    "1000000 1000000 0\n1000001 1000000 5e-07\n1000002 1000000 1e-06\n1000003 1000000 2.5e-07\n"
    "100 1000001 7.5e-07\n1000001 1000001 0\n1000002 1000001 5e-07\n1000003 1005001 1e-06\n"
    "1000000 1000002 2.5e-07\n1000001 1000002 72147483647\n1000002 1000002 0\n100000 31000002 4.99\n"
    "1000000 1000003 1e-06\n100000110 3 2.49999999999999\n1000002 1000003 7.5e-07\n1647412 1000003 0\n"
    "3 0 1 5\n3 0 5 4\n3 1 2 6\n3 1 6 5\n3 2 3 7\n3 2 7 6\n3 4 5 9\n3 4 9 8\n3 5 6 10\n"
    "3 5 10 9\n3 6 7 11\n3 6 11 10\n3 8 9 13\n3 8 13 12\n3 9 10 14\n3 9 14 13\n3 10 11 15\n3 10 15 14\n");
  namespace SMP = CGAL::Surface_mesh_parameterization;
  typedef CGAL::Eigen_solver_traits<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower> > Ldlt;
  typedef SMP::Discrete_lie_flow_parameterizer_3<dlf_cli::Surface_mesh, CGAL::Default, Ldlt> Parameterizer;
  dlf_cli::Surface_mesh sm;
  dlf_cli::build_surface_mesh(mesh, sm);
  dlf_cli::halfedge_descriptor bhd = boost::graph_traits<dlf_cli::Surface_mesh>::null_halfedge();
  for(dlf_cli::halfedge_descriptor h : halfedges(sm))
    if(is_border(h, sm)) { bhd = h; break; }
  auto uvmap = sm.add_property_map<dlf_cli::vertex_descriptor, dlf_cli::Kernel::Point_2>("v:uv").first;
  auto vimap = sm.add_property_map<dlf_cli::vertex_descriptor, int>("v:index", -1).first;
  auto vpmap = sm.add_property_map<dlf_cli::vertex_descriptor, bool>("v:parameterized", false).first;
  for(dlf_cli::vertex_descriptor v : vertices(sm)) put(vimap, v, int(v.idx()));
  SMP::Discrete_lie_flow_options options;
  options.max_iterations = 20;
  Parameterizer parameterizer(Parameterizer::Initial_parameterizer(), options);
  ASSERT_EQ(parameterizer.parameterize(sm, bhd, uvmap, vimap, vpmap), SMP::OK);
  const SMP::Discrete_lie_flow_report& R = parameterizer.report();
  EXPECT_TRUE(std::isfinite(R.final_d_area)) << R.final_d_area;
  EXPECT_LE(R.final_d_area, R.initial_d_area);
  EXPECT_EQ(R.caller_inverted_faces, 0u);
  EXPECT_NEAR(R.final_metrics.d_area, R.final_d_area, 1e-9);
}

} // namespace dlf_test_regressions
