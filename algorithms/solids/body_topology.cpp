// Body topology (see body_topology.hpp): counting sort of edge uses by their lower vertex,
// then a sort within each bucket, every pass on all cores. The buckets are filled in any order
// (atomic cursors) and then sorted by (edge, slot), a total order, so the result does not
// depend on the thread count.
#include "algorithms/solids/body_topology.hpp"

#include <algorithm>
#include <atomic>
#include <new>
#include <stdexcept>
#include <utility>

#include "algorithms/support/parallel.hpp"
#include "algorithms/support/parallel_scan.hpp"

namespace hlr {
BodyTopology body_topology(const std::vector<Face>& faces, std::size_t nv, unsigned threads) {
  BodyTopology t;
  const ParallelLoop loop(threads);
  // The large arrays' pages are touched on all cores before one thread fills them in order.
  t.face_offset = parallel_offsets<int>(faces.size(), [&](std::size_t f) { return faces[f].size(); }, loop);
  const std::vector<int>& fo = t.face_offset;
  if (fo.back() >= (1 << 30)) throw std::length_error("body topology: more than 2^30 face corners in one body");
  t.slot_third.resize(fo.back());  // fresh pages: written (and so touched) on all cores
  t.slot_edge.resize(fo.back());
  loop.for_each(t.slot_edge.size(), 1 << 16, [&](std::size_t i) { t.slot_third[i] = t.slot_edge[i] = -1; });
  constexpr std::size_t kGrain = 8192;
  // Uses per lower vertex, then each bucket's start.
  RawVector<std::uint32_t> start(nv + 1);
  loop.for_each(start.size(), 1 << 16, [&](std::size_t i) { start[i] = 0; });
  loop.for_each(faces.size(), kGrain, [&](std::size_t f) {
    for (std::size_t k = 0; k < faces[f].size(); ++k) {
      const int u = faces[f][k], v = faces[f][(k + 1) % faces[f].size()];
      if (u != v) std::atomic_ref<std::uint32_t>(start[std::min(u, v) + 1]).fetch_add(1, std::memory_order_relaxed);
    }
  });
  for (std::size_t i = 1; i <= nv; ++i) start[i] += start[i - 1];
  // A use in its lower vertex's bucket in 8 bytes: the higher vertex in the high half, then the
  // slot and whether it runs from the lower vertex. Sorting a bucket's words sorts its uses by
  // (higher vertex, slot): each edge's uses together, in order of slot.
  RawVector<std::uint64_t> uses;
  uses.reserve(start[nv]);
  touch_pages(uses.data(), start[nv] * sizeof(std::uint64_t), loop);  // fresh pages on all cores; each use is written below
  uses.resize(start[nv]);
  {
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    loop.for_each(faces.size(), kGrain, [&](std::size_t f) {
      for (std::size_t k = 0; k < faces[f].size(); ++k) {
        const int u = faces[f][k], v = faces[f][(k + 1) % faces[f].size()];
        if (u == v) continue;
        const std::uint32_t at = std::atomic_ref<std::uint32_t>(fill[std::min(u, v)]).fetch_add(1, std::memory_order_relaxed);
        uses[at] = (static_cast<std::uint64_t>(std::max(u, v)) << 32) | (static_cast<std::uint64_t>(fo[f] + k) << 1) | (u < v ? 1u : 0u);
      }
    });
  }
  // Each bucket sorted, and its edges counted (runs of one higher vertex); then the edges of
  // each lower vertex from its place, on all cores, in the order (u, v).
  std::vector<std::uint32_t> at(nv + 1, 0);
  loop.for_each(nv, kGrain, [&](std::size_t i) {
    if (start[i + 1] - start[i] > 1) std::sort(uses.begin() + start[i], uses.begin() + start[i + 1]);
    std::uint32_t n = 0;
    for (std::uint32_t j = start[i]; j < start[i + 1]; ++j) n += j == start[i] || (uses[j] >> 32) != (uses[j - 1] >> 32);
    at[i + 1] = n;
  });
  for (std::size_t i = 1; i <= nv; ++i) at[i] += at[i - 1];
  const bool triangles = std::all_of(faces.begin(), faces.end(), [](const Face& f) { return f.size() == 3; });
  auto face_of = [&](int slot) {  // (a mesh of triangles: slot / 3)
    return triangles ? slot / 3 : static_cast<int>(std::upper_bound(fo.begin(), fo.end(), slot) - fo.begin()) - 1;
  };
  t.edges.resize(at[nv]);  // unconstructed: each edge made below, on all cores
  loop.for_each(t.edges.size(), kGrain, [&](std::size_t e) { ::new (static_cast<void*>(&t.edges[e])) BodyEdge; });
  loop.for_each(nv, kGrain, [&](std::size_t i) {  // (may throw: every edge is constructed by now)
    std::uint32_t e = at[i] - 1;
    for (std::uint32_t j = start[i]; j < start[i + 1]; ++j) {
      if (j == start[i] || (uses[j] >> 32) != (uses[j - 1] >> 32)) {
        ++e;
        t.edges[e].u = static_cast<int>(i);
        t.edges[e].v = static_cast<int>(uses[j] >> 32);
      }
      EdgeUse use;
      use.slot = static_cast<int>((uses[j] & 0xffffffffu) >> 1);
      use.forward = static_cast<unsigned>(uses[j] & 1u);
      use.face = face_of(use.slot);
      t.edges[e].uses.push_back(use);
      t.slot_edge[use.slot] = static_cast<int>(e);
    }
  });
  return t;
}

void pair_sides(BodyTopology& t, unsigned threads) {
  if (t.paired) return;
  const ParallelLoop loop(threads);
  // Each slot is one use of one edge, so every edge writes only its own slots.
  loop.for_each(t.edges.size(), 8192, [&](std::size_t e) {
    const EdgeUses& uses = t.edges[e].uses;
    if (uses.size() == 2) {
      t.slot_edge[uses[0].slot] = uses[1].face;
      t.slot_edge[uses[1].slot] = uses[0].face;
      std::swap(t.slot_third[uses[0].slot], t.slot_third[uses[1].slot]);
    } else {
      for (std::size_t k = 0; k < uses.size(); ++k) t.slot_edge[uses[k].slot] = -1;
    }
  });
  RawVector<BodyEdge>().swap(t.edges);
  t.paired = true;
}

}  // namespace hlr
