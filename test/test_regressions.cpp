// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Regression tests of the findings of the fuzz target (fuzz/dlf_fuzz.cpp):
// each input is the reduced file that failed, and each test fails without
// its fix (some only under the sanitizers, which .ci/sanitize runs).

#include <gtest/gtest.h>

// The reader is part of the `dlf` tool, not of the library, and the test
// executable does not link the tool's objects: compile it in.
#include "../examples/dlf/mesh_input.cpp"

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>

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
