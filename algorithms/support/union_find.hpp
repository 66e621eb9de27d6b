// Disjoint sets over 0..n-1 with path halving; the smallest index of a set is its root, so the
// result does not depend on the order of the unions (deterministic output). Used by the 2D
// stage (line_dedup.cpp: points and overlap groups; path_chaining.cpp: components).
#pragma once

#include <algorithm>
#include <atomic>
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

/// Disjoint sets that threads unite at the same time (lock-free: a root is linked under the
/// smaller one by compare-and-swap, paths halved by compare-and-swap writes that only ever
/// point a node higher in its tree; all with acquire-release order). Each set's root is its smallest index, as in UnionFind,
/// so the result does not depend on the order of the unions or the number of threads.
/// root() may be called once the unions are done.
class ConcurrentUnionFind {
 public:
  explicit ConcurrentUnionFind(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0u); }
  void unite(std::uint32_t a, std::uint32_t b) {
    for (;;) {
      a = find(a), b = find(b);
      if (a == b) return;
      if (a < b) std::swap(a, b);  // link the larger root under the smaller
      std::uint32_t expected = a;
      if (std::atomic_ref<std::uint32_t>(parent_[a]).compare_exchange_strong(expected, b, std::memory_order_acq_rel)) return;
    }
  }
  std::uint32_t root(std::uint32_t a) const {
    while (parent_[a] != a) a = parent_[a];
    return a;
  }

 private:
  std::uint32_t find(std::uint32_t a) {
    for (;;) {
      const std::uint32_t p = std::atomic_ref<std::uint32_t>(parent_[a]).load(std::memory_order_acquire);
      if (p == a) return a;
      const std::uint32_t g = std::atomic_ref<std::uint32_t>(parent_[p]).load(std::memory_order_acquire);
      std::uint32_t expected = p;
      if (g != p) std::atomic_ref<std::uint32_t>(parent_[a]).compare_exchange_weak(expected, g, std::memory_order_acq_rel);
      a = g;
    }
  }
  std::vector<std::uint32_t> parent_;
};

}  // namespace hlr
