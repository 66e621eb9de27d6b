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
  struct U {
    std::uint64_t key;
    int face, slot;
    bool forward;
  };
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
  RawVector<U> uses;
  uses.reserve(start[nv]);
  touch_pages(uses.data(), start[nv] * sizeof(U), loop);  // fresh pages on all cores; each use is written below
  uses.resize(start[nv]);
  {
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    loop.for_each(faces.size(), kGrain, [&](std::size_t f) {
      for (std::size_t k = 0; k < faces[f].size(); ++k) {
        const int u = faces[f][k], v = faces[f][(k + 1) % faces[f].size()];
        if (u == v) continue;
        const std::uint64_t key = (static_cast<std::uint64_t>(std::min(u, v)) << 32) | static_cast<std::uint32_t>(std::max(u, v));
        const std::uint32_t at = std::atomic_ref<std::uint32_t>(fill[std::min(u, v)]).fetch_add(1, std::memory_order_relaxed);
        uses[at] = {key, static_cast<int>(f), fo[f] + static_cast<int>(k), u < v};
      }
    });
  }
  auto less = [](const U& a, const U& c) { return a.key < c.key || (a.key == c.key && a.slot < c.slot); };
  loop.for_each(nv, kGrain, [&](std::size_t i) {
    if (start[i + 1] - start[i] > 1) std::sort(uses.begin() + start[i], uses.begin() + start[i + 1], less);
  });
  // One edge per run of equal keys: the runs found in one pass, the edges built on all cores.
  std::vector<std::uint32_t> first =  // the first use of each edge
      parallel_select(uses.size(), [&](std::size_t i) { return i == 0 || uses[i].key != uses[i - 1].key; }, loop, 1);
  first.push_back(static_cast<std::uint32_t>(uses.size()));
  t.edges.resize(first.size() - 1);  // unconstructed: each edge made below, on all cores
  loop.for_each(t.edges.size(), kGrain, [&](std::size_t e) { ::new (static_cast<void*>(&t.edges[e])) BodyEdge; });
  loop.for_each(t.edges.size(), kGrain, [&](std::size_t e) {  // (may throw: every edge is constructed by now)
    BodyEdge& edge = t.edges[e];
    edge.u = static_cast<int>(uses[first[e]].key >> 32);
    edge.v = static_cast<int>(uses[first[e]].key & 0xffffffffu);
    for (std::uint32_t j = first[e]; j < first[e + 1]; ++j) {
      EdgeUse use;
      use.face = uses[j].face, use.slot = uses[j].slot, use.forward = uses[j].forward;
      edge.uses.push_back(use);
      t.slot_edge[uses[j].slot] = static_cast<int>(e);
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
