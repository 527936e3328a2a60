// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Small helpers the tool's readers and checks share.

#ifndef DLF_CLI_UTIL_H
#define DLF_CLI_UTIL_H

#include "cli_error.h"

#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

namespace dlf_cli {

/// A path as messages quote it.
inline std::string quoted(const std::string& path) { return "'" + path + "'"; }

/// The indices of one line of a selection file (`path`, line `line_number`):
/// whole numbers >= 0; another word throws `Cli_error` ("'x' is not
/// `expected`"). `refuse_overflow`: a number too large for a long (which
/// strtol reads as its largest value) is refused too, for the callers that
/// check no range after.
inline std::vector<long> selection_indices(const std::string& line, const std::string& path, int line_number,
                                           const std::string& expected, bool refuse_overflow)
{
  std::istringstream words(line);
  std::vector<long> out;
  std::string token;
  while(words >> token) {
    char* end = nullptr;
    const long i = std::strtol(token.c_str(), &end, 10);
    if(end != token.c_str() + token.size() || i < 0 || (refuse_overflow && i == std::numeric_limits<long>::max()))
      throw Cli_error(quoted(path) + ": line " + std::to_string(line_number) + ": '" + token + "' is not " + expected);
    out.push_back(i);
  }
  return out;
}

/// The shortest decimal text that reads back as `x` (0.005, where a
/// 17-digit default prints 0.0050000000000000001): for `--help`'s defaults.
inline std::string shortest_text(double x)
{
  char text[32];
  for(int digits = 1; digits <= 17; ++digits) {
    std::snprintf(text, sizeof text, "%.*g", digits, x);
    if(std::strtod(text, nullptr) == x) break;
  }
  return text;
}

/// A union-find over indices, for connected components and fans.
struct Union_find
{
  std::vector<std::size_t> parent;
  explicit Union_find(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), std::size_t(0)); }
  std::size_t find(std::size_t i)
  {
    while(parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }
  void unite(std::size_t a, std::size_t b) { parent[find(a)] = find(b); }
};

} // namespace dlf_cli

#endif
