// Vertex stores (kernel/point_store.hpp): the compact form's points, bounds and lazy points
// against exact rationals.
#include "kernel/point_store.hpp"

#include <gtest/gtest.h>

#include <random>
#include <thread>

#include "kernel/polyhedron.hpp"

using namespace hlr;

namespace {

Rational q(std::int64_t num, std::int64_t den) {
  Rational r;
  mpz_set_si(r.get_num_mpz_t(), static_cast<long>(num));
  mpz_set_si(r.get_den_mpz_t(), static_cast<long>(den));
  r.canonicalize();
  return r;
}

}  // namespace

// Every compact point is num / den in lowest terms, and its bounds are bounds_of's doubles for
// that rational: numerators divisible by the denominator (one double), zeros, negatives, the
// limits 2^53, denominators 1, powers of ten and odd ones, on random and edge values.
TEST(PointStore, CompactPointsAndBoundsAreTheRationals) {
  std::mt19937_64 rng(53);
  const std::int64_t lim = PointStore::kLimit;
  for (std::int64_t den : {std::int64_t{1}, std::int64_t{10}, std::int64_t{10000000}, std::int64_t{1000000000000000}, std::int64_t{3},
                           std::int64_t{7 * 1024}, lim, lim - 1}) {
    std::vector<PointStore::Numerators> nums = {{0, den, -den}, {lim, -lim, 1}, {-1, 2 * (den % 1000 + 1), lim - 1}};
    std::uniform_int_distribution<std::int64_t> any(-lim, lim), small(-1000, 1000);
    for (int i = 0; i < 300; ++i) nums.push_back({any(rng), small(rng), small(rng) * (den % 97 + 1)});
    const PointStore s(nums, den);
    ASSERT_TRUE(s.compact());
    ASSERT_EQ(s.size(), nums.size());
    EXPECT_FALSE(s.points_made());
    for (std::size_t i = 0; i < nums.size(); ++i) {
      const Point3 p = s.point(i);
      for (int k = 0; k < 3; ++k) {
        const Rational want = q(nums[i][k], den);
        ASSERT_EQ(p[k], want) << nums[i][k] << "/" << den;
        const Bounds b = s.approx(i, k), w = bounds_of(want);
        ASSERT_EQ(b.lo, w.lo) << nums[i][k] << "/" << den;
        ASSERT_EQ(b.hi, w.hi) << nums[i][k] << "/" << den;
        ASSERT_EQ(p.approx(k).lo, w.lo);
      }
    }
    EXPECT_FALSE(s.points_made());  // point(i) and approx() make nothing
    const std::vector<Point3>& all = s.points();
    EXPECT_TRUE(s.points_made());
    for (std::size_t i = 0; i < nums.size(); ++i) ASSERT_EQ(all[i], s.point(i));
  }
}

TEST(PointStore, CompactLimitsAreChecked) {
  EXPECT_THROW(PointStore({{0, 0, 0}}, 0), std::invalid_argument);
  EXPECT_THROW(PointStore({{0, 0, 0}}, -5), std::invalid_argument);
  EXPECT_THROW(PointStore({{0, 0, 0}}, PointStore::kLimit + 1), std::invalid_argument);
  EXPECT_THROW(PointStore({{0, PointStore::kLimit + 1, 0}}, 10), std::invalid_argument);
  EXPECT_THROW(PointStore({{0, 0, -PointStore::kLimit - 1}}, 10), std::invalid_argument);
}

// Threads asking for the points at once all get the one array, made once.
TEST(PointStore, PointsAreMadeOnceAcrossThreads) {
  std::vector<PointStore::Numerators> nums;
  for (int i = 0; i < 20000; ++i) nums.push_back({i, -3 * i, i % 7});
  const PointStore s(nums, 1000);
  std::vector<const std::vector<Point3>*> seen(8);
  std::vector<std::thread> ts;
  for (int t = 0; t < 8; ++t) ts.emplace_back([&, t] { seen[t] = &s.points(); });
  for (auto& t : ts) t.join();
  for (const auto* p : seen) EXPECT_EQ(p, seen[0]);
  EXPECT_EQ((*seen[0])[19999], Point3(q(19999, 1000), q(-59997, 1000), q(19999 % 7, 1000)));
}

// A polyhedron on a compact store: its vertices are made only when asked for, copies and the
// reversed polyhedron keep the same points, and the store stays where it is when the
// polyhedron moves (segments borrow it).
TEST(PointStore, PolyhedronMakesItsPointsOnlyWhenAsked) {
  std::vector<PointStore::Numerators> nums = {{0, 0, 0}, {10, 0, 0}, {0, 10, 0}, {0, 0, 10}};
  const auto each = [](std::size_t n, const std::function<void(std::size_t)>& body) {
    for (std::size_t i = 0; i < n; ++i) body(i);
  };
  Polyhedron p(PointStore(nums, 4), {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}, each);
  const PointStore* at = &p.vertex_store();
  EXPECT_EQ(p.num_vertices(), 4u);
  EXPECT_FALSE(p.vertex_store().points_made());
  const Polyhedron moved = std::move(p);
  EXPECT_EQ(&moved.vertex_store(), at);
  const Polyhedron r = moved.reversed();
  EXPECT_TRUE(r.vertex_store().compact());
  EXPECT_FALSE(moved.vertex_store().points_made());
  EXPECT_EQ(moved.vertices()[1], Point3(Rational(5, 2), Rational(0), Rational(0)));
  EXPECT_TRUE(moved.vertex_store().points_made());
  EXPECT_EQ(r.vertices(), moved.vertices());
  EXPECT_EQ(six_signed_volume(moved.vertices(), moved.faces()), Rational(125, 8));
  EXPECT_THROW(Polyhedron(PointStore(nums, 4), {{0, 1, 4}}, each), FaceError);
}
