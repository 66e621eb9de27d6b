// Order-keeping scans on all cores (the parallel loop of parallel.hpp): which indices pass a
// test, where each index's output starts when each writes a known count, and a stable sort by
// integer keys. Each counts per fixed chunk, adds the chunks' counts in order, then writes each
// chunk after the ones before it, so the result does not depend on the thread count.
#pragma once

#include <algorithm>
#include <array>
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

/// Sorts v by key(e) (an unsigned integer of up to 64 bits), stable: a least significant digit
/// radix sort, 11-bit digits over the bits the keys use. Each pass counts digits per fixed
/// chunk on all cores, places every (digit, chunk) run after the ones before it, and scatters
/// the chunks on all cores: the same order on any number of threads.
template <class E, class Key>
void radix_sort(std::vector<E>& v, const Key& key, const ParallelLoop& loop) {
  const std::size_t n = v.size();
  const std::size_t chunks = std::clamp<std::size_t>(n / 65536, 1, 64), per = (n + chunks - 1) / chunks;
  std::vector<std::uint64_t> any(chunks, 0);
  loop.for_each(chunks, 1, [&](std::size_t c) {
    std::uint64_t a = 0;  // (a local: neighbouring chunks' slots share a cache line)
    for (std::size_t i = c * per, e = std::min(n, i + per); i < e; ++i) a |= static_cast<std::uint64_t>(key(v[i]));
    any[c] = a;
  });
  std::uint64_t all = 0;
  for (std::uint64_t a : any) all |= a;
  std::vector<E> tmp;
  reserve_touched(tmp, n, loop);
  tmp.resize(n);
  std::vector<std::array<std::size_t, 2048>> at(chunks);
  for (int shift = 0; shift < 64 && (all >> shift) != 0; shift += 11) {
    auto digit = [&](const E& e) { return (static_cast<std::uint64_t>(key(e)) >> shift) & 2047; };
    loop.for_each(chunks, 1, [&](std::size_t c) {
      at[c].fill(0);
      for (std::size_t i = c * per, e = std::min(n, i + per); i < e; ++i) ++at[c][digit(v[i])];
    });
    std::size_t run = 0;
    for (std::size_t d = 0; d < 2048; ++d)
      for (std::size_t c = 0; c < chunks; ++c) {
        const std::size_t k = at[c][d];
        at[c][d] = run;
        run += k;
      }
    loop.for_each(chunks, 1, [&](std::size_t c) {
      for (std::size_t i = c * per, e = std::min(n, i + per); i < e; ++i) tmp[at[c][digit(v[i])]++] = v[i];
    });
    v.swap(tmp);
  }
}

}  // namespace hlr
