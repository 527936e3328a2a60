// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Small helpers the tool's readers and checks share.

#ifndef DLF_CLI_UTIL_H
#define DLF_CLI_UTIL_H

#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <numeric>
#include <string>
#include <vector>

namespace dlf_cli {

/// A path as messages quote it.
inline std::string quoted(const std::string& path) { return "'" + path + "'"; }

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
