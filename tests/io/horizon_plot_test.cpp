// The horizon's picture route (io/pipeline/horizon.hpp, HorizonDrawing::plot: runs straight to the 2D
// stage) against the general one (the exact line drawing through make_plot): the same layers,
// strokes and points, bit for bit, and the same clean-up numbers, on surfaces whose pictures
// have what the clean-up must decide exactly: flat and terraced regions (collinear neighbours,
// pieces of different cuts on one line seen from the side), equal heights, touching cuts.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <string>

#include "algorithms/plot/plot.hpp"
#include "io/pipeline/horizon.hpp"
#include "support/horizon_grids.hpp"

namespace hlr {
namespace {

using test::uniform_grid;
const auto& grid = uniform_grid;

void expect_same_plot(const Plot& a, const Plot& b, const std::string& what) {
  ASSERT_EQ(a.layers.size(), b.layers.size()) << what;
  for (std::size_t l = 0; l < a.layers.size(); ++l) {
    const PlotLayer &p = a.layers[l], &q = b.layers[l];
    ASSERT_EQ(p.name(), q.name()) << what;
    ASSERT_EQ(p.strokes.size(), q.strokes.size()) << what << " layer " << p.name();
    for (std::size_t s = 0; s < p.strokes.size(); ++s) {
      ASSERT_EQ(p.strokes[s].closed, q.strokes[s].closed) << what;
      ASSERT_EQ(p.strokes[s].points, q.strokes[s].points) << what << " layer " << p.name() << " stroke " << s;
    }
  }
  EXPECT_EQ(a.bounds, b.bounds) << what;
  EXPECT_EQ(a.stats.pieces, b.stats.pieces) << what;
  EXPECT_EQ(a.stats.edges, b.stats.edges) << what;
  EXPECT_EQ(a.stats.zero_length, b.stats.zero_length) << what;
  EXPECT_EQ(a.stats.overlap_groups, b.stats.overlap_groups) << what;
  EXPECT_EQ(a.stats.overlapped_pieces, b.stats.overlapped_pieces) << what;
  EXPECT_EQ(a.stats.exact_point_tests, b.stats.exact_point_tests) << what;
  EXPECT_EQ(a.stats.exact_line_tests, b.stats.exact_line_tests) << what;
  EXPECT_EQ(a.stats.path_count, b.stats.path_count) << what;
}

// Returns how many exact decisions the clean-up took over all cases (the hard places were met).
std::size_t compare(const HeightGrid& g, const std::string& name) {
  std::size_t exact = 0;
  for (const Vector3& v : {Vector3(1, 2, 3), Vector3(0, 1, 4), Vector3(-2, 1, 5), Vector3(3, 0, 1), Vector3(1, -1, 3)})
    for (const char* cuts : {"z", "both"})
      for (bool hidden : {false, true}) {
        if (std::string(cuts) == "both" && v.x() == 0) continue;  // the x cuts are seen edge-on
        const Camera cam = make_orthographic(v, Vector3(0, 1, 0));
        const HorizonDrawing hd(g, cam, 0, cuts);
        PlotOptions po;
        po.hidden = hidden;
        po.threads = 2;
        std::optional<Plot> fast = hd.plot(po);
        if (!fast) {
          ADD_FAILURE() << name << ": no fast route";
          continue;
        }
        const std::string what = name + " view " + to_string(v) + " cuts " + cuts + (hidden ? " hidden" : "");
        Plot general = make_plot(hd.model(name).drawing, cam, po);
        expect_same_plot(*fast, general, what);
        exact += general.stats.exact_point_tests + general.stats.exact_line_tests;
        order_plot(*fast, {fast->bounds[0], fast->bounds[3]});
        order_plot(general, {general.bounds[0], general.bounds[3]});
        expect_same_plot(*fast, general, what + " ordered");
      }
  return exact;
}

TEST(HorizonPlot, SameStrokesAsTheExactModelOnAPeakAndASaddle) {
  compare(grid(13, 9, [](const Rational& x, const Rational& z) { return Rational(Rational(1) / (1 + 8 * (x * x + z * z))); }), "peak");
  compare(grid(11, 11, [](const Rational& x, const Rational& z) { return Rational((x * x - z * z) / 2); }), "saddle");
}

TEST(HorizonPlot, SameStrokesWhereTheCleanUpDecidesExactly) {
  std::size_t exact = 0;
  // Flat with a bump: collinear neighbours along the cuts, and from the side (view (3, 0, 1))
  // pieces of different cuts on one line.
  exact += compare(grid(12, 10, [](const Rational& x, const Rational& z) {
                     Rational d = x * x + z * z;
                     return d < Rational(1, 4) ? Rational(Rational(1, 4) - d) : Rational(0);
                   }),
                   "flat with a bump");
  // Terraces of equal heights.
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> level(0, 2);
  exact += compare(grid(10, 8, [&](const Rational&, const Rational&) { return rational(level(rng), 8); }), "terraces");
  // A plane: every cut on a line.
  exact += compare(grid(7, 6, [](const Rational& x, const Rational& z) { return Rational(x / 2 + z / 3); }), "plane");
  EXPECT_GT(exact, 0u) << "the clean-up met pairs it had to decide exactly";
}

TEST(HorizonPlot, FallsBackWhereTheFrameIsNotTheIdentity) {
  const Rational s = parse_rational("1e120");
  HeightGrid g = grid(5, 4, [&](const Rational& x, const Rational& z) { return Rational(s * (x * x - z / 2)); });
  for (Rational& x : g.xs) x *= s;
  for (Rational& z : g.zs) z *= s;
  const HorizonDrawing hd(g, make_orthographic(Vector3(1, 2, 3), Vector3(0, 1, 0)));
  EXPECT_FALSE(hd.plot(PlotOptions{}).has_value());
}

}  // namespace
}  // namespace hlr

// The view angles `hlr horizon --angles` takes are realised within the bound --help states
// (kHorizonAngleErrorDegrees), for every elevation and azimuth on a fine grid and for the
// decimals users type: the realised angles are read back from the exact view direction.
namespace hlr {
TEST(HorizonAngles, RealisedWithinTheStatedBound) {
  const long double pi = 3.14159265358979323846264338327950288L, deg = 180 / pi;
  auto ld = [](const Rational& q) { return static_cast<long double>(q.get_d()); };
  long double worst = 0;
  auto check = [&](const std::string& e, const std::string& a) {
    const Vector3 v = horizon_view_from_angles(parse_rational(e), parse_rational(a));
    // (cos e sin a, sin e, cos e cos a), exactly of length 1.
    EXPECT_EQ(v.x() * v.x() + v.y() * v.y() + v.z() * v.z(), 1) << e << "," << a;
    const long double ge = std::atan2(ld(v.y()), std::hypot(ld(v.x()), ld(v.z()))) * deg;
    const long double ga = std::atan2(ld(v.x()), ld(v.z())) * deg;
    const long double we = std::stold(e), wa = std::stold(a);
    long double da = std::fabs(ga - wa);
    if (da > 180) da = 360 - da;
    const long double err = std::max(std::fabs(ge - we), da);
    worst = std::max(worst, err);
    EXPECT_LE(err, kHorizonAngleErrorDegrees + 1e-9) << "--angles " << e << "," << a;
  };
  for (int e = -178; e <= 178; e += 3)  // elevations in (-90, 90) by 1.5 degrees
    for (int a = -359; a <= 359; a += 7) check(std::to_string(e / 2.0), std::to_string(a / 2.0));
  for (const char* ea : {"30,30", "35,-20", "-20,30", "35,0", "12.345,67.891", "89.99,0.01", "-0.004,179.999", "45,45", "60,-135"}) {
    std::string t(ea);
    check(t.substr(0, t.find(',')), t.substr(t.find(',') + 1));
  }
  EXPECT_GT(worst, 0);  // the angles are not exact: the check measures something
}
}  // namespace hlr
