// Disjoint sets over 0..n-1 with path halving; the smallest index of a set is its root, so the
// result does not depend on the order of the unions (deterministic output). Used by the 2D
// stage (line_dedup.cpp: points and overlap groups; path_chaining.cpp: components).
#pragma once

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <vector>

namespace hlr {

struct UnionFind {
  std::vector<std::uint32_t> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  std::uint32_t find(std::uint32_t a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
  }
  void unite(std::uint32_t a, std::uint32_t b) {
    a = find(a), b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

}  // namespace hlr
