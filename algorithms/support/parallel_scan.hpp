// Order-keeping scans on all cores (the parallel loop of parallel.hpp): which indices pass a
// test, and where each index's output starts when each writes a known count. Both count per
// fixed chunk, add the chunks' counts in order, then write each chunk after the ones before
// it, so the result does not depend on the thread count.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "algorithms/support/parallel.hpp"

namespace hlr {

inline constexpr std::size_t kScanChunk = 16384;

/// The indices i in [0, n) with keep(i) (called twice per index: it must be pure), in
/// increasing order, as Index (which must hold n - 1); room for `spare` more is reserved.
template <class Index = std::uint32_t, class Keep>
std::vector<Index> parallel_select(std::size_t n, const Keep& keep, const ParallelLoop& loop, std::size_t spare = 0) {
  const std::size_t chunks = (n + kScanChunk - 1) / kScanChunk;
  std::vector<std::size_t> at(chunks + 1, 0);
  loop.for_each(chunks, 1, [&](std::size_t c) {
    std::size_t s = 0;
    for (std::size_t i = c * kScanChunk, e = std::min(n, i + kScanChunk); i < e; ++i) s += keep(i) ? 1 : 0;
    at[c + 1] = s;
  });
  for (std::size_t c = 0; c < chunks; ++c) at[c + 1] += at[c];
  std::vector<Index> out;
  reserve_touched(out, at[chunks] + spare, loop);
  out.resize(at[chunks]);
  loop.for_each(chunks, 1, [&](std::size_t c) {
    std::size_t w = at[c];
    for (std::size_t i = c * kScanChunk, e = std::min(n, i + kScanChunk); i < e; ++i)
      if (keep(i)) out[w++] = static_cast<Index>(i);
  });
  return out;
}

/// Exclusive prefix sums: offsets[i] = count(0) + ... + count(i - 1) for i in [0, n], so
/// offsets[n] is the total (count is called once per index), in T (which must hold the total).
template <class T = std::size_t, class Count>
std::vector<T> parallel_offsets(std::size_t n, const Count& count, const ParallelLoop& loop) {
  std::vector<T> out;
  reserve_touched(out, n + 1, loop);
  out.resize(n + 1, T(0));
  const std::size_t chunks = (n + kScanChunk - 1) / kScanChunk;
  std::vector<std::size_t> at(chunks + 1, 0);
  loop.for_each(chunks, 1, [&](std::size_t c) {
    std::size_t s = 0;
    for (std::size_t i = c * kScanChunk, e = std::min(n, i + kScanChunk); i < e; ++i) {
      out[i + 1] = static_cast<T>(count(i));
      s += static_cast<std::size_t>(out[i + 1]);
    }
    at[c + 1] = s;
  });
  for (std::size_t c = 0; c < chunks; ++c) at[c + 1] += at[c];
  loop.for_each(chunks, 1, [&](std::size_t c) {
    std::size_t s = at[c];
    for (std::size_t i = c * kScanChunk, e = std::min(n, i + kScanChunk); i < e; ++i) {
      s += static_cast<std::size_t>(out[i + 1]);
      out[i + 1] = static_cast<T>(s);
    }
  });
  return out;
}

}  // namespace hlr
