// The floating horizon on certified doubles (algorithms/horizon/floating_horizon_filtered.*) against the
// same sweep on rationals (floating_horizon_exact): identical results, exactly, on random
// surfaces and on the places where a double filter alone would be wrong or undecided: flat
// and planar regions (every line the same, every turn zero), heightmaps with equal values,
// views whose picture puts samples of different cuts at one abscissa (no x component, the
// diagonal view of a square grid), the view from below and from behind, uneven grids, and
// numbers far outside the range of doubles.
#include "algorithms/horizon/floating_horizon_filtered.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <random>

#include "algorithms/horizon/floating_horizon.hpp"
#include "support/horizon_grids.hpp"

namespace hlr {
namespace {

using test::uniform_grid;
const auto& grid = uniform_grid;

void expect_same(const HorizonResult& a, const HorizonResult& b, const std::string& what) {
  ASSERT_EQ(a.order, b.order) << what;
  EXPECT_EQ(a.horizon_breakpoints, b.horizon_breakpoints) << what;
  ASSERT_EQ(a.visible.size(), b.visible.size()) << what;
  for (std::size_t k = 0; k < a.visible.size(); ++k) {
    const HorizonPiece &p = a.visible[k], &q = b.visible[k];
    ASSERT_TRUE(p.curve == q.curve && p.segment == q.segment && p.t0 == q.t0 && p.t1 == q.t1)
        << what << ": piece " << k << " (" << p.curve << "," << p.segment << "," << p.t0 << "," << p.t1 << ") against (" << q.curve
        << "," << q.segment << "," << q.t0 << "," << q.t1 << ")";
  }
  ASSERT_EQ(a.side.size(), b.side.size()) << what;
  for (std::size_t k = 0; k < a.side.size(); ++k) {
    const HorizonPiece &p = a.side[k], &q = b.side[k];
    ASSERT_TRUE(p.curve == q.curve && p.segment == q.segment && p.t0 == q.t0 && p.t1 == q.t1) << what << ": side piece " << k;
  }
}

const std::vector<Vector3>& views() {
  static const std::vector<Vector3> v = {Vector3(1, 2, 3),  Vector3(-2, 1, 5), Vector3(0, 1, 4),  Vector3(3, 1, -2),
                                         Vector3(1, -1, 3), Vector3(5, 1, 1),  Vector3(1, 1, 1),  Vector3(-1, 3, -1),
                                         Vector3(rational(7, 1000), 1, rational(-3, 7))};
  return v;
}

// Every view, with up (0, 1, 0) and (0, -1, 0); returns how many pairs were compared.
int compare_all(const HeightGrid& g, const std::string& name, std::uint64_t* exact_decisions = nullptr) {
  int n = 0;
  for (const Vector3& v : views())
    for (int up : {1, -1}) {
      Camera cam = make_orthographic(v, Vector3(0, up, 0));
      HorizonCounters counters;
      HorizonResult f = floating_horizon_filtered(g, cam, 0, &counters);
      expect_same(f, floating_horizon_exact(g, cam), name + " view " + to_string(v) + " up " + std::to_string(up));
      if (exact_decisions) *exact_decisions += counters.exact;
      ++n;
    }
  return n;
}

TEST(FloatingHorizonFiltered, EqualsTheExactSweepOnRandomSurfaces) {
  std::mt19937 rng(18);
  int compared = 0;
  for (int trial = 0; trial < 6; ++trial) {
    const int nx = 4 + trial % 4, nz = 3 + trial;
    std::uniform_int_distribution<int> h(-50, 50);
    HeightGrid g = grid(nx, nz, [&](const Rational&, const Rational&) { return rational(h(rng), 40); });
    compared += compare_all(g, "random " + std::to_string(trial));
  }
  EXPECT_EQ(compared, 6 * 18);
}

TEST(FloatingHorizonFiltered, EqualsTheExactSweepOnSmoothDoubleSurfaces) {
  // Heights as an expression's doubles are read (53-bit binary rationals).
  HeightGrid g = grid(15, 11, [](const Rational& x, const Rational& z) {
    const double xd = to_double(x), zd = to_double(z);
    return rational_from_double(0.35 * std::exp(-3 * xd * xd) * (1 + std::sin(5 * zd + 2 * xd)) + 0.05 * std::cos(7 * xd + 3 * zd));
  });
  EXPECT_EQ(compare_all(g, "smooth"), 18);
}

TEST(FloatingHorizonFiltered, FlatAndPlanarSurfacesEveryLineTheSame) {
  std::uint64_t exact = 0;
  compare_all(grid(6, 5, [](const Rational&, const Rational&) { return Rational(0); }), "flat", &exact);
  compare_all(grid(6, 5, [](const Rational& x, const Rational& z) { return Rational(x / 3 - z / 5); }), "plane", &exact);
  compare_all(grid(7, 6, [](const Rational& x, const Rational& z) {
                Rational d = x * x + z * z;
                return d < Rational(1, 3) ? Rational(Rational(1, 3) - d) : Rational(0);
              }),
              "flat with a bump", &exact);
  EXPECT_GT(exact, 0u) << "the planar cases need exact decisions: the filter cannot certify a zero";
}

TEST(FloatingHorizonFiltered, HeightmapWithEqualValuesAndTerraces) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> level(0, 3);
  HeightGrid g = grid(8, 7, [&](const Rational&, const Rational&) { return rational(level(rng), 12); });
  EXPECT_EQ(compare_all(g, "terraces"), 18);
}

TEST(FloatingHorizonFiltered, UnevenGridAndSamplesAtOneAbscissa) {
  HeightGrid g;
  for (const char* x : {"-1", "-3/7", "0", "1/10", "1/3", "1"}) g.xs.push_back(parse_rational(x));
  for (const char* z : {"-1", "-1/2", "1/5", "1"}) g.zs.push_back(parse_rational(z));
  for (std::size_t j = 0; j < g.zs.size(); ++j)
    for (std::size_t i = 0; i < g.xs.size(); ++i) g.ys.push_back(rational(static_cast<long>((i * 7 + j * 3) % 5), 6));
  EXPECT_EQ(compare_all(g, "uneven"), 18);
  // A square grid seen along (1, 1, 1): X = x − z puts the samples of each diagonal at one
  // abscissa.
  HeightGrid d = grid(7, 7, [](const Rational& x, const Rational& z) { return Rational(x * z / 2); });
  for (int up : {1, -1}) {
    Camera cam = make_orthographic(Vector3(1, 1, 1), Vector3(0, up, 0));
    expect_same(floating_horizon_filtered(d, cam), floating_horizon_exact(d, cam), "diagonal");
  }
}

TEST(FloatingHorizonFiltered, NumbersBeyondTheRangeOfDoubles) {
  for (const char* scale : {"1e400", "1e-400"}) {
    const Rational s = parse_rational(scale);
    HeightGrid g = grid(5, 4, [&](const Rational& x, const Rational& z) { return Rational(s * (x * x - z / 2)); });
    for (Rational& x : g.xs) x *= s;
    for (Rational& z : g.zs) z *= s;
    std::uint64_t exact = 0;
    compare_all(g, scale, &exact);
    EXPECT_GT(exact, 0u) << scale << ": the filter is off there";
  }
}

TEST(FloatingHorizonFiltered, TheFilterDecidesAlmostEverythingOnASmoothSurface) {
  HeightGrid g = grid(60, 40, [](const Rational& x, const Rational& z) {
    const double xd = to_double(x), zd = to_double(z);
    return rational_from_double(0.3 * std::exp(-4 * xd * xd) * (1 + std::sin(6 * zd + xd)));
  });
  HorizonCounters counters;
  Camera cam = make_orthographic(Vector3(1, 2, 3), Vector3(0, 1, 0));
  expect_same(floating_horizon_filtered(g, cam, 0, &counters), floating_horizon_exact(g, cam), "60x40");
  EXPECT_EQ(counters.exact, 0u);
}

// Cuts of many more segments than one parallel chunk (128), so that the chunks' outputs meet
// (a chunk once wrote into another's list when the loop's ranges were not aligned).
TEST(FloatingHorizonFiltered, SameResultOnOneTwoAndFourThreadsWithLongCuts) {
  HeightGrid g = grid(700, 5, [](const Rational& x, const Rational& z) {
    const double xd = to_double(x), zd = to_double(z);
    return rational_from_double(0.2 * std::sin(40 * xd + 3 * zd) + 0.1 * zd);
  });
  Camera cam = make_orthographic(Vector3(-2, 1, 5), Vector3(0, 1, 0));
  const HorizonResult one = floating_horizon_filtered(g, cam, 1);
  EXPECT_GT(one.visible.size(), 1000u);
  expect_same(one, floating_horizon_exact(g, cam), "exact");
  for (unsigned t : {2u, 4u}) expect_same(floating_horizon_filtered(g, cam, t), one, "threads " + std::to_string(t));
}

}  // namespace
}  // namespace hlr
