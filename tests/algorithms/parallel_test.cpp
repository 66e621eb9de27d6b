// The parallel loop and the process-wide thread limit (algorithms/support/parallel.hpp):
// `--threads 1` must mean one thread for every stage, sorts and readers included.
#include "algorithms/support/parallel.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <execution>
#include <map>
#include <mutex>
#include <set>
#include <thread>
#include <type_traits>
#include <vector>

#include "algorithms/solids/body_topology.hpp"
#include "algorithms/support/parallel_scan.hpp"
#include "algorithms/support/union_find.hpp"

using namespace hlr;

namespace {

// The threads that ran a loop's work. The first index waits (up to a second) for a second
// thread to join in, so that a busy machine, whose other threads start late, gives the same
// count as a quiet one.
std::size_t threads_used(unsigned loop_threads) {
  std::mutex m;
  std::set<std::thread::id> ids;
  auto count = [&] {
    std::lock_guard<std::mutex> g(m);
    return ids.size();
  };
  ParallelLoop(loop_threads).for_each(20000, 16, [&](std::size_t i) {
    {
      std::lock_guard<std::mutex> g(m);
      ids.insert(std::this_thread::get_id());
    }
    for (int wait = 0; i == 0 && wait < 1000 && count() < 2; ++wait) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  });
  return ids.size();
}

TEST(Parallel, ThreadLimitHoldsEveryLoop) {
  {
    const ThreadLimit one(1);
    EXPECT_EQ(threads_used(0), 1u);  // a loop asking for all cores
    EXPECT_EQ(threads_used(8), 1u);
  }
  if (std::thread::hardware_concurrency() >= 2) {
    EXPECT_GE(threads_used(0), 2u) << "without the limit, more cores work";
  }
}

TEST(Parallel, EveryIndexOnceInOrderOfRanges) {
  std::vector<int> seen(100003, 0);
  ParallelLoop(0).for_each(seen.size(), 97, [&](std::size_t i) { ++seen[i]; });
  EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int c) { return c == 1; }));
}

}  // namespace

// Body topology on all cores equals the definition (a map from each undirected edge to its
// uses in slot order) and is the same on 1, 2 and 8 threads: a grid of quads and triangles
// large enough for many chunks, with a fin (an edge in three faces), a face with a repeated
// vertex (no edge on that side) and a lone triangle.
namespace {

// A grid of quads and triangles (vertex (i, j) is i * 301 + j) with a fin on the diagonal
// (1,1)-(2,2) (an edge of three uses), a face with a repeated vertex and a lone triangle (a
// boundary of three edges).
std::vector<Face> fin_grid(std::size_t& nv) {
  const int n = 300;
  std::vector<Face> faces;
  auto id = [&](int i, int j) { return i * (n + 1) + j; };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      if ((i + j) % 3 == 0) faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
      else faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)}), faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  const int extra = (n + 1) * (n + 1);
  faces.push_back({id(1, 1), id(2, 2), extra});        // the fin
  faces.push_back({id(5, 5), id(5, 5), id(6, 6)});     // a repeated vertex
  faces.push_back({extra + 1, extra + 2, extra + 3});  // a lone triangle
  nv = extra + 4;
  return faces;
}

// Every undirected edge's uses (face, slot, forward), by (u, v), from a plain loop.
std::map<std::pair<int, int>, std::vector<std::array<int, 3>>> edge_uses_map(const std::vector<Face>& faces) {
  std::map<std::pair<int, int>, std::vector<std::array<int, 3>>> want;
  int slot = 0;
  for (std::size_t f = 0; f < faces.size(); ++f)
    for (std::size_t k = 0; k < faces[f].size(); ++k, ++slot) {
      const int u = faces[f][k], v = faces[f][(k + 1) % faces[f].size()];
      if (u != v) want[{std::min(u, v), std::max(u, v)}].push_back({static_cast<int>(f), slot, u < v});
    }
  return want;
}

}  // namespace

TEST(Parallel, BodyTopologyEqualsTheMapOfEdgeUsesOnAnyThreadCount) {
  using namespace hlr;
  std::size_t nv = 0;
  const std::vector<Face> faces = fin_grid(nv);
  auto id = [](int i, int j) { return i * 301 + j; };
  const auto want = edge_uses_map(faces);
  std::vector<std::vector<int>> edge_of_slot;
  for (unsigned threads : {1u, 2u, 8u}) {
    const BodyTopology t = body_topology(faces, nv, threads);
    ASSERT_EQ(t.edges.size(), want.size()) << threads;
    std::size_t e = 0;
    for (const auto& [uv, uses] : want) {
      const BodyEdge& got = t.edges[e];
      ASSERT_EQ(got.u, uv.first);
      ASSERT_EQ(got.v, uv.second);
      ASSERT_EQ(got.uses.size(), uses.size());
      for (std::size_t k = 0; k < uses.size(); ++k) {
        EXPECT_EQ(got.uses[k].face, uses[k][0]);
        EXPECT_EQ(got.uses[k].slot, uses[k][1]);
        EXPECT_EQ(got.uses[k].forward, uses[k][2] != 0);
        EXPECT_EQ(t.slot_edge[uses[k][1]], static_cast<int>(e));
      }
      ++e;
    }
    edge_of_slot.emplace_back(t.slot_edge.begin(), t.slot_edge.end());
    auto fin = std::find_if(t.edges.begin(), t.edges.end(), [&](const BodyEdge& x) { return x.u == id(1, 1) && x.v == id(2, 2); });
    ASSERT_NE(fin, t.edges.end());
    EXPECT_EQ(fin->uses.size(), 3u) << "the fin's edge has three uses";
    const BodyEdge copy = *fin;  // a copy keeps the uses beyond the two in place
    ASSERT_EQ(copy.uses.size(), 3u);
    for (std::size_t k = 0; k < 3; ++k) EXPECT_EQ(copy.uses[k].slot, fin->uses[k].slot);
  }
  EXPECT_EQ(edge_of_slot[0], edge_of_slot[1]);
  EXPECT_EQ(edge_of_slot[0], edge_of_slot[2]);
}

// pair_sides against the map: a side of an edge with exactly two uses gets the other use's
// face and third vertex; a side of a boundary edge, of the fin's three-use edge or with a
// repeated vertex gets -1; the edges are freed. The same on any thread count.
TEST(Parallel, PairedSidesAreTheOtherUseOfTwoUseEdgesOnAnyThreadCount) {
  std::size_t nv = 0;
  const std::vector<Face> faces = fin_grid(nv);
  const auto want = edge_uses_map(faces);
  for (unsigned threads : {1u, 2u, 8u}) {
    BodyTopology t = body_topology(faces, nv, threads);
    for (std::size_t s = 0; s < t.slot_third.size(); ++s) t.slot_third[s] = 7 * static_cast<int>(s) + 1;  // the caller's
    pair_sides(t, threads);
    ASSERT_TRUE(t.paired);
    EXPECT_TRUE(t.edges.empty());
    std::vector<int> face(t.slot_edge.size(), -1), third(t.slot_third.size(), -2);  // -2: not a side of an edge
    std::size_t pairs = 0, others = 0;
    for (const auto& [uv, uses] : want) {
      for (std::size_t k = 0; k < uses.size(); ++k) {
        if (uses.size() != 2) {
          third[uses[k][1]] = -3;  // any: no mate to read
          continue;
        }
        face[uses[k][1]] = uses[1 - k][0];
        third[uses[k][1]] = 7 * uses[1 - k][1] + 1;
      }
      (uses.size() == 2 ? pairs : others) += 1;
    }
    EXPECT_GT(pairs, 100000u);
    // The grid's rim (1,200), the fin's three edges (one of three uses), the diagonal the
    // repeated-vertex face runs along twice (four uses), the lone triangle's three.
    EXPECT_EQ(others, 1200u + 3u + 1u + 3u);
    for (std::size_t s = 0; s < face.size(); ++s) {
      ASSERT_EQ(t.slot_edge[s], face[s]) << "slot " << s << ", " << threads << " threads";
      if (third[s] >= 0) {
        ASSERT_EQ(t.slot_third[s], third[s]) << "slot " << s;
      }
    }
  }
}

// A body of triangles keeps no third vertex per side (the engine reads its faces): without
// `thirds` the edges, their uses (the fin's third use kept beside, read through a moved
// topology) and the paired mates are those with them, and slot_third stays empty. Edges need
// no destructor (an array of them whose pages were given back is freed untouched).
TEST(Parallel, BodyTopologyWithoutThirdsPairsTheSameMates) {
  static_assert(std::is_trivially_destructible_v<BodyEdge>);
  std::size_t nv = 0;
  const std::vector<Face> faces = fin_grid(nv);
  for (unsigned threads : {1u, 2u}) {
    BodyTopology with = body_topology(faces, nv, threads);
    BodyTopology made = body_topology(faces, nv, threads, false);
    BodyTopology without = std::move(made);  // the uses beside stay where the edges point
    EXPECT_TRUE(without.slot_third.empty());
    ASSERT_EQ(without.edges.size(), with.edges.size());
    std::size_t beyond = 0;
    for (std::size_t e = 0; e < with.edges.size(); ++e) {
      const BodyEdge &a = with.edges[e], &b = without.edges[e];
      ASSERT_EQ(a.u, b.u);
      ASSERT_EQ(a.v, b.v);
      ASSERT_EQ(a.uses.size(), b.uses.size());
      for (std::size_t k = 0; k < a.uses.size(); ++k) {
        EXPECT_EQ(a.uses[k].face, b.uses[k].face);
        EXPECT_EQ(a.uses[k].slot, b.uses[k].slot);
        EXPECT_EQ(a.uses[k].forward, b.uses[k].forward);
      }
      beyond += b.uses.size() > 2 ? b.uses.size() - 2 : 0;
    }
    EXPECT_EQ(beyond, without.beyond.size());
    EXPECT_GE(beyond, 3u) << "the fin's third use and the repeated diagonal's two more";
    EXPECT_EQ(std::vector<int>(without.slot_edge.begin(), without.slot_edge.end()), std::vector<int>(with.slot_edge.begin(), with.slot_edge.end()));
    pair_sides(with, threads);
    pair_sides(without, threads);
    EXPECT_TRUE(without.slot_third.empty() && without.edges.empty() && without.beyond.empty());
    EXPECT_EQ(std::vector<int>(without.slot_edge.begin(), without.slot_edge.end()), std::vector<int>(with.slot_edge.begin(), with.slot_edge.end()));
  }
}

// The order-keeping scans (parallel_scan.hpp) against a plain loop: sizes around the chunk
// (0, 1, one chunk, one more, several), 1, 2 and 8 threads, the same result every time.
TEST(ParallelScan, SelectAndOffsetsMatchAPlainLoopOnAnyThreadCount) {
  for (std::size_t n : {std::size_t{0}, std::size_t{1}, kScanChunk - 1, kScanChunk, kScanChunk + 1, 5 * kScanChunk + 77}) {
    auto keep = [](std::size_t i) { return (i * 2654435761u) % 7 < 3; };
    auto count = [](std::size_t i) -> std::size_t { return (i * 40503u) % 5; };
    std::vector<std::uint32_t> want_sel;
    std::vector<std::size_t> want_off(1, 0);
    for (std::size_t i = 0; i < n; ++i) {
      if (keep(i)) want_sel.push_back(static_cast<std::uint32_t>(i));
      want_off.push_back(want_off.back() + count(i));
    }
    for (unsigned t : {1u, 2u, 8u}) {
      const ParallelLoop loop(t);
      EXPECT_EQ(parallel_select(n, keep, loop), want_sel) << "n " << n << ", threads " << t;
      EXPECT_EQ(parallel_offsets(n, count, loop), want_off) << "n " << n << ", threads " << t;
    }
  }
  // Nothing kept, everything kept.
  const ParallelLoop loop(2);
  auto none = [](std::size_t) { return false; };
  auto every = [](std::size_t) { return true; };
  auto three = [](std::size_t) -> std::size_t { return 3; };
  EXPECT_TRUE(parallel_select(100000, none, loop).empty());
  EXPECT_EQ(parallel_select(100000, every, loop).size(), 100000u);
  EXPECT_EQ(parallel_offsets(100000, three, loop).back(), 300000u);
}

// Unions made by many threads at once give the sets, and the roots (each set's smallest
// index), that one thread's UnionFind gives: random pairs, chains (long paths to halve) and
// a star, on 1, 2 and 8 threads.
TEST(ConcurrentUnionFind, SameSetsAndRootsAsTheSequentialOneOnAnyThreadCount) {
  const std::size_t n = 50000;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  std::uint64_t x = 88172645463325252ull;
  auto next = [&] {
    x ^= x << 13, x ^= x >> 7, x ^= x << 17;
    return static_cast<std::uint32_t>(x % 40000);
  };  // random pairs below 40000
  for (int i = 0; i < 30000; ++i) pairs.emplace_back(next(), next());
  for (std::uint32_t i = 40000; i + 1 < 45000; ++i) pairs.emplace_back(i + 1, i);  // a chain, linked from its far end
  for (std::uint32_t i = 45001; i < 46000; ++i) pairs.emplace_back(i, 45999);      // a star around its largest index
  UnionFind want(n);
  for (auto [a, b] : pairs) want.unite(a, b);
  for (unsigned t : {1u, 2u, 8u}) {
    for (int round = 0; round < 3; ++round) {
      ConcurrentUnionFind got(n);
      ParallelLoop(t).for_each(pairs.size(), 64, [&](std::size_t i) { got.unite(pairs[i].first, pairs[i].second); });
      std::size_t differ = 0;
      for (std::uint32_t v = 0; v < n; ++v) differ += got.root(v) != want.find(v);
      EXPECT_EQ(differ, 0u) << "threads " << t << ", round " << round;
    }
  }
  EXPECT_EQ(want.find(44999), 40000u);
  EXPECT_EQ(want.find(45001), 45001u);
}

// The radix sort is stable and sorts by the whole key: keys of few bits (many ties, one pass),
// of all 64 bits, and of none (all zero), against std::stable_sort, on 1, 2 and 8 threads.
TEST(ParallelScan, RadixSortIsAStableSortByKeyOnAnyThreadCount) {
  auto key = [](const std::pair<std::uint64_t, std::uint32_t>& e) { return e.first; };
  for (std::size_t n : {std::size_t{0}, std::size_t{1}, std::size_t{65535}, std::size_t{300001}}) {
    for (int bits : {0, 5, 64}) {
      std::vector<std::pair<std::uint64_t, std::uint32_t>> v(n);  // (key, position)
      std::uint64_t x = 88172645463325252ull;
      for (std::size_t i = 0; i < n; ++i) {
        x ^= x << 13, x ^= x >> 7, x ^= x << 17;
        v[i] = {bits == 64 ? x : bits == 0 ? 0 : x >> (64 - bits), static_cast<std::uint32_t>(i)};
      }
      auto want = v;
      std::stable_sort(want.begin(), want.end(), [&](const auto& a, const auto& b) { return key(a) < key(b); });
      for (unsigned t : {1u, 2u, 8u}) {
        auto got = v;
        const ParallelLoop loop(t);
        radix_sort(got, key, loop);
        EXPECT_EQ(got, want) << "n " << n << ", bits " << bits << ", threads " << t;
      }
    }
  }
}
