// Filtered exact predicates (kernel/predicates.hpp): answers are exact even when the interval
// filter cannot decide.
#include "kernel/predicates.hpp"

#include <gtest/gtest.h>

#include "kernel/epeck_bridge.hpp"
#include "support/numbers.hpp"

using namespace hlr;

namespace {
using hlr::test::Q;
Point3 P(const char* x, const char* y, const char* z) { return Point3(Q(x), Q(y), Q(z)); }
}  // namespace

TEST(Predicates, SideOfPlaneExactOnDecimals) {
  // The plane x + y + z = 0.6 through (0.1, 0.2, 0.3): in doubles 0.1 + 0.2 + 0.3 != 0.6.
  Plane h(1, 1, 1, Q("-0.6"));
  EXPECT_EQ(side_of_plane(h, P("0.1", "0.2", "0.3")), Sign::Zero);
  EXPECT_EQ(side_of_plane(h, P("0.1", "0.2", "0.30000000000000000001")), Sign::Positive);
  EXPECT_EQ(side_of_plane(h, P("0.1", "0.2", "0.29999999999999999999")), Sign::Negative);
}

TEST(Predicates, FallbackRunsOnlyWhenNeeded) {
  Plane h(1, 1, 1, Q("-0.6"));
  predicate_stats() = {};
  side_of_plane(h, P("5", "5", "5"));
  EXPECT_EQ(predicate_stats().evaluations, 1u);
  EXPECT_EQ(predicate_stats().exact_fallbacks, 0u);
  side_of_plane(h, P("0.1", "0.2", "0.3"));
  EXPECT_EQ(predicate_stats().exact_fallbacks, 1u);
}

TEST(Predicates, OrientationAgreesWithCgalEpeck) {
  const Point3 pts[] = {P("0", "0", "0"), P("1", "0", "0"), P("0", "1", "0"), P("0", "0", "1"),
                        P("0.1", "0.2", "0.3"), P("1/3", "1/3", "1/3"), P("0.7", "0.1", "0.2"), P("1e-30", "0", "0")};
  for (const auto& a : pts)
    for (const auto& b : pts)
      for (const auto& c : pts)
        for (const auto& d : pts) {
          int ours = static_cast<int>(orientation(a, b, c, d));
          int cgal = static_cast<int>(CGAL::orientation(to_epeck(a), to_epeck(b), to_epeck(c), to_epeck(d)));
          ASSERT_EQ(ours, cgal) << to_string(a) << to_string(b) << to_string(c) << to_string(d);
        }
}

TEST(Predicates, OrientationSigns) {
  Point3 o = P("0", "0", "0"), x = P("1", "0", "0"), y = P("0", "1", "0");
  EXPECT_EQ(orientation(o, x, y, P("0", "0", "1")), Sign::Positive);
  EXPECT_EQ(orientation(o, x, y, P("0", "0", "-1")), Sign::Negative);
  EXPECT_EQ(orientation(o, x, y, P("0.3", "0.7", "0")), Sign::Zero);
  EXPECT_TRUE(collinear(P("0.1", "0.1", "0.1"), P("0.2", "0.2", "0.2"), P("0.3", "0.3", "0.3")));
  EXPECT_FALSE(collinear(P("0.1", "0.1", "0.1"), P("0.2", "0.2", "0.2"), P("0.3", "0.3", "0.30000000000000001")));
}

TEST(Predicates, EpeckRoundTrip) {
  Point3 p = P("1/3", "-0.1", "1e-20");
  EXPECT_EQ(from_epeck(to_epeck(p)), p);
}

TEST(Geometry, NewellPlaneOfPolygonAndPrimitiveForm) {
  Point3 a = P("0", "0", "1/2"), b = P("2", "0", "1/2"), c = P("2", "2", "1/2"), d = P("0", "2", "1/2");
  const Point3* quad[] = {&a, &b, &c, &d};
  Plane h = plane_of_polygon(quad, 4);
  EXPECT_EQ(h, Plane(0, 0, 8, -4));  // twice the area (4) times +z, through z = 1/2
  EXPECT_EQ(primitive_plane(h), Plane(0, 0, 2, -1));
  EXPECT_EQ(primitive_plane(Plane(Q("1/2"), Q("-1/3"), 0, Q("5/6"))), Plane(3, -2, 0, 5));
}

#include <random>

TEST(Geometry, FastPrimitivePlaneEqualsTheRationalOne) {
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> c(-1000, 1000), den(1, 40), big(0, 15), nverts(3, 7);
  int checked = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    // A planar polygon: points a + s·u + t·w on a random plane (or off it, for non-planar).
    auto R = [&] {
      Rational q = rational(c(rng), den(rng));
      if (big(rng) == 0) q += Rational(mpz_class("98765432109876543210"), 3);  // beyond 128 bits
      return q;
    };
    Point3 a(R(), R(), R());
    Vector3 u(R(), R(), R()), w(R(), R(), R());
    int n = nverts(rng);
    std::vector<Point3> pts;
    for (int i = 0; i < n; ++i) {
      double ang = 6.283185307179586 * i / n;
      Rational s = rational(static_cast<long>(std::lround(100 * std::cos(ang))), 7);
      Rational t = rational(static_cast<long>(std::lround(100 * std::sin(ang))), 9);
      pts.push_back(a + (s * u + t * w));
    }
    std::vector<const Point3*> ptr;
    for (auto& p : pts) ptr.push_back(&p);
    EXPECT_EQ(primitive_plane_of_polygon(ptr.data(), n), primitive_plane(plane_of_polygon(ptr.data(), n)));
    ++checked;
  }
  EXPECT_EQ(checked, 4000);
}

#include <CGAL/Interval_nt.h>
#include <CGAL/mpq_class.h>

#include <cstdio>

// bounds_of is CGAL's tightest interval (the doubles next to the value, or the value itself)
// for numerators and denominators of 54 to 128 bits, where it divides limbs instead of calling
// MPFR: random fractions, numpy's %.18e decimals, exact doubles with long numerators, values
// near the ends of the normal range.
TEST(Geometry, BoundsOfLongFractionsAreCgalsTightInterval) {
  std::mt19937_64 rng(128);
  auto bits = [&](int n) {
    mpz_class v = 0;
    for (int i = 0; i < n; i += 32) v = (v << 32) + static_cast<unsigned long>(rng() & 0xffffffffu);
    return mpz_class(v >> ((n + 31) / 32 * 32 - n));
  };
  int exact = 0, inexact = 0;
  for (int trial = 0; trial < 30000; ++trial) {
    Rational q;
    char text[64];
    switch (trial % 4) {
      case 0:
        q = Rational(bits(1 + static_cast<int>(rng() % 128)), bits(1 + static_cast<int>(rng() % 128)) + 1);
        break;
      case 1: {  // an exporter's 19 significant digits
        const double v = std::ldexp(static_cast<double>(rng() >> 11), -static_cast<int>(rng() % 70));
        std::snprintf(text, sizeof text, "%.18e", v);
        q = parse_rational(text);
        break;
      }
      case 2: {  // a double itself, written as a long numerator over a power of two
        const mpz_class m = bits(1 + static_cast<int>(rng() % 53)) << static_cast<int>(rng() % 70);
        mpz_class d = 1;
        d <<= static_cast<int>(rng() % 127);
        q = Rational(m, d);
        break;
      }
      default: {  // near the ends of the normal range
        mpz_class d = 1;
        d <<= 1000 + static_cast<int>(rng() % 40);
        q = rng() % 2 ? Rational(bits(100), d) : Rational(bits(100) << 900, mpz_class(bits(60) + 1));
        break;
      }
    }
    q.canonicalize();
    if (rng() % 2) q = -q;
    if (mpz_sizeinbase(q.get_num_mpz_t(), 2) <= 53 && mpz_sizeinbase(q.get_den_mpz_t(), 2) <= 53) continue;  // the 2-ulp path
    const Bounds b = bounds_of(q);
    const std::pair<double, double> c = CGAL::to_interval(q);
    ASSERT_EQ(b.lo, c.first) << q;
    ASSERT_EQ(b.hi, c.second) << q;
    ASSERT_LE(Rational(b.lo), q);
    ASSERT_GE(Rational(b.hi), q);
    (b.lo == b.hi ? exact : inexact) += 1;
  }
  EXPECT_GT(exact, 2000);
  EXPECT_GT(inexact, 10000);
}
