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
BodyTopology body_topology(const std::vector<Face>& faces, std::size_t nv, unsigned threads, bool thirds) {
  BodyTopology t;
  const ParallelLoop loop(threads);
  // The large arrays' pages are touched on all cores before one thread fills them in order.
  t.face_offset = parallel_offsets<int>(faces.size(), [&](std::size_t f) { return faces[f].size(); }, loop);
  const std::vector<int>& fo = t.face_offset;
  if (fo.back() >= (1 << 30)) throw std::length_error("body topology: more than 2^30 face corners in one body");
  if (thirds) t.slot_third.resize(fo.back());  // fresh pages: written (and so touched) on all cores
  t.slot_edge.resize(fo.back());
  loop.for_each(t.slot_edge.size(), 1 << 16, [&](std::size_t i) {
    t.slot_edge[i] = -1;
    if (thirds) t.slot_third[i] = -1;
  });
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
  // A use after an edge's first two (a non-manifold edge: few) is listed by its worker with
  // its edge, in order; the lists are joined by edge into `beyond` afterwards.
  PerWorker<std::vector<std::pair<std::uint32_t, EdgeUse>>> later(loop);
  loop.run(nv, kGrain, [&](unsigned w, std::size_t lo, std::size_t hi) {
    for (std::size_t i = lo; i < hi; ++i) {
      std::uint32_t e = at[i] - 1;
      for (std::uint32_t j = start[i]; j < start[i + 1]; ++j) {
        if (j == start[i] || (uses[j] >> 32) != (uses[j - 1] >> 32)) {
          ++e;
          ::new (static_cast<void*>(&t.edges[e])) BodyEdge;
          t.edges[e].u = static_cast<int>(i);
          t.edges[e].v = static_cast<int>(uses[j] >> 32);
        }
        EdgeUse use;
        use.slot = static_cast<int>((uses[j] & 0xffffffffu) >> 1);
        use.forward = static_cast<unsigned>(uses[j] & 1u);
        use.face = face_of(use.slot);
        if (t.edges[e].uses.size() >= 2) later[w].emplace_back(e, use);
        t.edges[e].uses.push_back(use);
        t.slot_edge[use.slot] = static_cast<int>(e);
      }
    }
  });
  std::vector<std::pair<std::uint32_t, EdgeUse>> all;
  for (unsigned w = 0; w < later.size(); ++w) all.insert(all.end(), later[w].begin(), later[w].end());
  // (an edge's uses are one worker's, in slot order: a stable sort by edge keeps that order)
  std::stable_sort(all.begin(), all.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  t.beyond.reserve(all.size());
  for (const auto& x : all) t.beyond.push_back(x.second);
  for (std::size_t k = 0; k < all.size(); ++k)
    if (k == 0 || all[k].first != all[k - 1].first) t.edges[all[k].first].uses.set_beyond(t.beyond.data() + k);
  return t;
}

void pair_sides(BodyTopology& t, unsigned threads, bool free_edges) {
  if (t.paired) return;
  const ParallelLoop loop(threads);
  // Each slot is one use of one edge, so every edge writes only its own slots.
  loop.for_each(t.edges.size(), 8192, [&](std::size_t e) {
    const EdgeUses& uses = t.edges[e].uses;
    if (uses.size() == 2) {
      t.slot_edge[uses[0].slot] = uses[1].face;
      t.slot_edge[uses[1].slot] = uses[0].face;
      if (!t.slot_third.empty()) std::swap(t.slot_third[uses[0].slot], t.slot_third[uses[1].slot]);
    } else {
      for (std::size_t k = 0; k < uses.size(); ++k) t.slot_edge[uses[k].slot] = -1;
    }
  });
  if (free_edges) RawVector<BodyEdge>().swap(t.edges), std::vector<EdgeUse>().swap(t.beyond);
  t.paired = true;
}

}  // namespace hlr
