// The intersection lines' broad phase (algorithms/hlr/intersection_broad_phase.hpp): every
// overlapping pair once, against a quadratic oracle, in doubles and in floats rounded outward,
// with huge boxes among the small ones (long, flat across the scene, across one axis and part of
// another, over all of it);
// boxes with a corner in common passed over without the judge;
// the segment's owned and borrowed ends (algorithms/model/line_drawing.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <mutex>
#include <random>
#include <set>

#include "algorithms/hlr/intersection_broad_phase.hpp"
#include "algorithms/model/line_drawing.hpp"

using namespace hlr;

namespace {

// `rare`: one box in `rare` of each large kind (fewer, smaller small ones make a finer grid).
std::vector<Box3> random_boxes(std::mt19937_64& rng, std::size_t n, double scale, unsigned rare = 1) {
  std::uniform_real_distribution<double> at(-scale, scale), size(0, scale / (rare > 1 ? 50 : 20));
  std::vector<Box3> out(n);
  for (Box3& b : out) {
    for (int k = 0; k < 3; ++k) {
      b[k] = at(rng);
      b[k + 3] = b[k] + (rng() % 7 == 0 ? 0 : size(rng));  // some flat boxes
    }
    if (rng() % (50 * rare) == 0) b[3] = b[0] + 2 * scale;                                                // a huge one now and then
    if (rng() % (40 * rare) == 0) b[0] = -scale, b[3] = scale, b[5] = b[2] + scale / 2;                   // across x, a quarter of z, thin in y
    if (rng() % (60 * rare) == 0) b[0] = -scale, b[3] = scale, b[1] = -scale, b[4] = scale, b[5] = b[2];  // a flat one across (a cap's)
    if (rng() % (200 * rare) == 0) b = {-scale, -scale, -scale, scale, scale, scale};                     // one over everything
  }
  return out;
}

std::set<std::pair<std::uint32_t, std::uint32_t>> oracle(const std::vector<Box3>& b) {
  std::set<std::pair<std::uint32_t, std::uint32_t>> out;
  for (std::uint32_t i = 0; i < b.size(); ++i)
    for (std::uint32_t j = i + 1; j < b.size(); ++j) {
      bool meet = true;
      for (int k = 0; k < 3; ++k) meet = meet && b[i][k] <= b[j][k + 3] && b[j][k] <= b[i][k + 3];
      if (meet) out.insert({i, j});
    }
  return out;
}

}  // namespace

TEST(BroadPhase, EveryOverlappingPairOnceInDoublesAndInOutwardFloats) {
  std::mt19937_64 rng(7);
  for (double scale : {1.0, 1e-30, 1e30, 2.0}) {
    // (6,000 boxes: a grid fine enough that a box across one axis and part of another is huge)
    std::vector<Box3> boxes = scale == 2.0 ? random_boxes(rng, 6000, scale, 8) : random_boxes(rng, 600, scale);
    if (scale == 2.0)
      for (int t = 0; t < 8; ++t) {  // huge boxes thin in y, and small ones reaching them from below in z
        const double y = -1.5 + 0.4 * t, z = -1.2 + 0.3 * t;
        boxes.push_back({-2, y, z, 2, y + 0.01, z + 1});
        for (int k = 1; k <= 4; ++k) boxes.push_back({0.1 * t, y, z - 0.012 * k, 0.1 * t + 0.01, y + 0.01, z + 0.001});
      }
    const auto want = oracle(boxes);
    for (unsigned threads : {1u, 2u}) {
      std::set<std::pair<std::uint32_t, std::uint32_t>> seen;
      std::mutex m;
      auto keep_all = [&](std::uint32_t a, std::uint32_t b) {
        std::lock_guard<std::mutex> lock(m);
        EXPECT_TRUE(seen.insert({a, b}).second) << "pair twice";
        return PairVerdict::Keep;
      };
      BoxPairs d = overlapping_box_pairs(boxes, ParallelLoop(threads), keep_all);
      EXPECT_EQ(seen, want) << "doubles, scale " << scale;
      const std::set<std::pair<std::uint32_t, std::uint32_t>> kept(d.kept.begin(), d.kept.end());
      EXPECT_EQ(kept, want);
      // Floats rounded outward: every true pair is still found (a few more may be).
      std::vector<Box3f> f(boxes.size());
      for (std::size_t i = 0; i < boxes.size(); ++i) ASSERT_TRUE(outward_floats(boxes[i], f[i]));
      seen.clear();
      BoxPairs fp = overlapping_box_pairs(f, ParallelLoop(threads), keep_all);
      for (const auto& p : want) EXPECT_TRUE(seen.count(p)) << "floats lost a pair, scale " << scale;
    }
  }
}

// Tiny boxes spread over a wide scene: a grid of over 2^32 cells (at least 10^4 on each axis),
// whose cell ids take the wide entries; each box has a twin shifted by half its size, and a
// few chains of touching boxes cross cell borders. Every pair once, as the oracle.
TEST(BroadPhase, AGridOfMoreThanTwoToThe32CellsFindsEveryPairOnce) {
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> at(-1, 1), size(1e-5, 1e-4);
  std::vector<Box3> boxes;
  for (int i = 0; i < 1500; ++i) {
    Box3 b;
    for (int k = 0; k < 3; ++k) b[k] = at(rng), b[k + 3] = b[k] + size(rng);
    boxes.push_back(b);
    for (int k = 0; k < 3; ++k) {
      const double h = (b[k + 3] - b[k]) / 2;
      b[k] += h, b[k + 3] += h;
    }
    boxes.push_back(b);
  }
  for (int c = 0; c < 20; ++c) {  // touching boxes in a row along x (shared faces meet)
    Box3 b{at(rng), at(rng), at(rng), 0, 0, 0};
    for (int k = 0; k < 3; ++k) b[k + 3] = b[k] + 5e-5;
    for (int j = 0; j < 12; ++j, b[0] += 5e-5, b[3] += 5e-5) boxes.push_back(b);
  }
  const auto want = oracle(boxes);
  ASSERT_GT(want.size(), 1500u);
  for (unsigned threads : {1u, 2u}) {
    std::set<std::pair<std::uint32_t, std::uint32_t>> seen;
    std::mutex m;
    BoxPairs d = overlapping_box_pairs(boxes, ParallelLoop(threads), [&](std::uint32_t a, std::uint32_t b) {
      std::lock_guard<std::mutex> lock(m);
      EXPECT_TRUE(seen.insert({a, b}).second) << "pair twice";
      return PairVerdict::Keep;
    });
    EXPECT_EQ(seen, want);
    const std::set<std::pair<std::uint32_t, std::uint32_t>> kept(d.kept.begin(), d.kept.end());
    EXPECT_EQ(kept, want);
  }
}

// A grid swept in slabs of x layers (a few entries at a time, as a 10M-triangle mesh's are
// made a slab at a time): the same pairs, once each, as in one sweep and as the oracle, with
// the same verdicts kept; boxes across slabs (huge ones, long ones) included.
TEST(BroadPhase, SlabsOfTheGridFindEveryPairOnceAsOneSweep) {
  std::mt19937_64 rng(41);
  const std::vector<Box3> boxes = random_boxes(rng, 3000, 1.0, 8);
  const auto want = oracle(boxes);
  ASSERT_GT(want.size(), 3000u);
  for (std::size_t slab : {std::size_t{1}, std::size_t{97}, std::size_t{5000}, kSlabEntries}) {
    for (unsigned threads : {1u, 2u}) {
      std::set<std::pair<std::uint32_t, std::uint32_t>> seen;
      std::mutex m;
      std::size_t judged = 0;
      BoxPairs d = overlapping_box_pairs(
          boxes, ParallelLoop(threads),
          [&](std::uint32_t a, std::uint32_t b) {
            std::lock_guard<std::mutex> lock(m);
            EXPECT_TRUE(seen.insert({a, b}).second) << "pair twice, slabs of " << slab;
            ++judged;
            return (a + b) % 3 == 0 ? PairVerdict::Keep : PairVerdict::Reject;
          },
          slab);
      EXPECT_EQ(seen, want) << "slabs of " << slab << " entries, " << threads << " threads";
      EXPECT_EQ(d.tested, judged);
      std::vector<std::pair<std::uint32_t, std::uint32_t>> kept;
      for (const auto& p : want)
        if ((p.first + p.second) % 3 == 0) kept.push_back(p);
      EXPECT_EQ(d.kept, kept);
    }
  }
}

// Corner ids read in place from records (three ints inside a larger struct, as a triangle's
// vertices): a pair with an id in common never reaches the judge, every other overlapping pair
// does, once, on the cell path, the huge boxes' path and in slabs, and is kept as judged.
TEST(BroadPhase, BoxesWithACornerInCommonArePassedOverWithoutTheJudge) {
  struct Record {
    int tag;
    std::array<int, 3> v;
    bool flag;
  };
  std::mt19937_64 rng(23);
  const std::vector<Box3> boxes = random_boxes(rng, 3000, 1.0, 8);
  std::vector<Record> records(boxes.size());
  for (Record& r : records) r = {7, {int(rng() % 200), int(rng() % 200), int(rng() % 200)}, true};
  auto share = [&](std::uint32_t a, std::uint32_t b) {
    for (int x : records[a].v)
      for (int y : records[b].v)
        if (x == y) return true;
    return false;
  };
  std::set<std::pair<std::uint32_t, std::uint32_t>> want;
  std::size_t shared = 0;
  for (const auto& p : oracle(boxes)) {
    if (share(p.first, p.second)) ++shared;
    else want.insert(p);
  }
  ASSERT_GT(shared, 100u);
  ASSERT_GT(want.size(), 3000u);
  const BoxCorners corners{reinterpret_cast<const std::byte*>(records.data()) + offsetof(Record, v), sizeof(Record)};
  for (std::size_t slab : {std::size_t{97}, kSlabEntries})
    for (unsigned threads : {1u, 2u}) {
      std::set<std::pair<std::uint32_t, std::uint32_t>> seen;
      std::mutex m;
      BoxPairs d = overlapping_box_pairs(
          boxes, ParallelLoop(threads),
          [&](std::uint32_t a, std::uint32_t b) {
            std::lock_guard<std::mutex> lock(m);
            EXPECT_FALSE(share(a, b)) << a << " and " << b << " share a corner";
            EXPECT_TRUE(seen.insert({std::min(a, b), std::max(a, b)}).second) << "pair twice";
            return PairVerdict::Keep;
          },
          slab, corners);
      EXPECT_EQ(seen, want) << "slabs of " << slab << ", " << threads << " threads";
      EXPECT_EQ(d.tested, want.size());
      const std::set<std::pair<std::uint32_t, std::uint32_t>> kept(d.kept.begin(), d.kept.end());
      EXPECT_EQ(kept, want);
    }
}

TEST(BroadPhase, OutwardFloatsEncloseTheDoublesAndRefuseBeyondTheirRange) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 10000; ++i) {
    const double e = std::ldexp(1.0, static_cast<int>(rng() % 200) - 100);
    Box3 b{u(rng) * e, u(rng) * e, u(rng) * e, 0, 0, 0};
    for (int k = 0; k < 3; ++k) b[k + 3] = b[k] + std::fabs(u(rng)) * e;
    Box3f f;
    ASSERT_TRUE(outward_floats(b, f));
    for (int k = 0; k < 3; ++k) {
      EXPECT_LE(static_cast<double>(f[k]), b[k]);
      EXPECT_GE(static_cast<double>(f[k + 3]), b[k + 3]);
    }
  }
  Box3f f;
  EXPECT_FALSE(outward_floats({0, 0, 0, 1e39, 1, 1}, f));
  EXPECT_FALSE(outward_floats({-1e300, 0, 0, 1, 1, 1}, f));
  EXPECT_FALSE(outward_floats({0, 0, 0, std::numeric_limits<double>::infinity(), 1, 1}, f));
  EXPECT_FALSE(outward_floats({0, std::numeric_limits<double>::quiet_NaN(), 0, 1, 1, 1}, f));
  // Subnormal floats still enclose (rounding toward the outside, not to zero).
  ASSERT_TRUE(outward_floats({1e-45, 1e-45, 1e-45, 2e-45, 2e-45, 2e-45}, f));
  EXPECT_LE(static_cast<double>(f[0]), 1e-45);
  EXPECT_GE(static_cast<double>(f[3]), 2e-45);
}

TEST(SegmentEnds, BorrowedEndsFollowTheVertexIndicesAndOwnedEndsAreCopiedDeep) {
  std::vector<Point3> v{Point3(0, 0, 0), Point3(1, 2, 3), Point3(4, 5, 6)};
  Segment s;
  s.v0 = 2, s.v1 = 1;
  s.borrow_ends(v);
  EXPECT_EQ(s.from(), v[2]);
  EXPECT_EQ(&s.to(), &v[1]) << "borrowed, not copied";
  Segment own;
  own.set_ends(Point3(7, 8, 9), Point3(1, 1, 1));
  Segment copy = own;
  EXPECT_NE(&copy.from(), &own.from());
  EXPECT_EQ(copy.from(), Point3(7, 8, 9));
  Segment moved = std::move(copy);
  EXPECT_EQ(moved.to(), Point3(1, 1, 1));
  moved = s;  // owned ends given up for borrowed ones
  EXPECT_EQ(&moved.from(), &v[2]);
  EXPECT_EQ(moved.at(Rational(1, 2)), Point3(Rational(5, 2), Rational(7, 2), Rational(9, 2)));
  EXPECT_LE(sizeof(Segment), 64u);
}
