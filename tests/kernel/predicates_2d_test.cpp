// The one home of picture-plane exactness (kernel/predicates_2d.hpp, kernel/error_bounds.hpp):
// the orientation filter never disagrees with the exact sign, on near-collinear points, at the
// ends of the filter's range and beyond the doubles; the interval form and the comparison
// filter decide only what is true.
#include "kernel/predicates_2d.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "support/numbers.hpp"

using namespace hlr;

namespace {
using hlr::test::Q;
Rational R(long n, long d) {
  Rational q(n);
  q /= d;
  return q;
}
Double2 D(const Exact2& p) { return {p[0].get_d(), p[1].get_d()}; }
Interval2 I(const Exact2& p) {
  auto one = [](const Rational& q) {
    const double d = q.get_d();
    return Interval{next_down(d), next_up(d)};
  };
  return {one(p[0]), one(p[1])};
}

// Three points near one line through a and b, at scale s: c = a + t·(b - a) + e·n.
Exact2 near_line(const Exact2& a, const Exact2& b, const Rational& t, const Rational& e) {
  return {a[0] + t * (b[0] - a[0]) - e * (b[1] - a[1]), a[1] + t * (b[1] - a[1]) + e * (b[0] - a[0])};
}
}  // namespace

TEST(Predicates2d, FilterAgreesWithExactNearOneLine) {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<long> num(-1000000, 1000000);
  int decided = 0, undecided = 0;
  for (const char* scale : {"1", "1/3", "1e-30", "1e30", "1e-119", "1e119"}) {
    const Rational s = Q(scale);
    for (int k = 0; k < 3000; ++k) {
      const Exact2 a{s * R(num(rng), 7), s * R(num(rng), 11)};
      const Exact2 b{s * R(num(rng), 13), s * R(num(rng), 3)};
      // Offsets from far off the line down to zero and to one part in 10^40.
      const Rational e = k % 4 == 0 ? Rational(0) : Rational(num(rng)) / Rational(mpz_class(10) * (k % 40 == 1 ? mpz_class("10000000000000000000000000000000000000000") : mpz_class(1 + k % 1000000)));
      const Exact2 c = near_line(a, b, R(num(rng), 977), e);
      const int exact = orient2d_exact(a, b, c);
      EXPECT_EQ(orient2d(a, b, c), exact) << "scale " << scale;
      EXPECT_EQ(orient2d(a, b, c, D(a), D(b), D(c)), exact);
      const int f = filter_usable(a, D(a)) && filter_usable(b, D(b)) && filter_usable(c, D(c)) ? orient2d_filter(D(a), D(b), D(c)) : 0;
      if (f != 0) {
        EXPECT_EQ(f, exact);
        ++decided;
      } else {
        ++undecided;
      }
      const int iv = orient2d_interval(I(a), I(b), I(c));
      if (iv != 2) EXPECT_EQ(iv, exact);
      if (e == 0) EXPECT_EQ(exact, 0);
    }
  }
  // The filter must do its job on most random points, and leave the collinear ones to exact.
  EXPECT_GT(decided, 10000);
  EXPECT_GT(undecided, 4500);
}

TEST(Predicates2d, OutsideTheFilterRangeTheAnswerIsStillExact) {
  // 2^-1100 and 2^1100 are beyond doubles: the filter is off (get_d gives 0 or a huge value)
  // and the exact sign decides.
  const Rational tiny = Rational(1) / Rational(mpz_class(1) << 1100), huge = Rational(mpz_class(1) << 1100);
  for (const Rational& s : {tiny, huge}) {
    const Exact2 a{0, 0}, b{s, s}, left{s, s + s * Q("1e-50")}, on{2 * s, 2 * s};
    EXPECT_FALSE(filter_usable(left, D(left)));
    EXPECT_EQ(orient2d(a, b, left), 1);
    EXPECT_EQ(orient2d(a, b, on), 0);
    EXPECT_EQ(orient2d(b, a, left), -1);
  }
}

// The boxes' float steps are std::nextafter's, bit for bit: zeros, subnormals, the largest
// float, infinities and random floats of every exponent.
TEST(Predicates2d, FloatStepsAreNextafterBitForBit) {
  const float inf = std::numeric_limits<float>::infinity(), top = std::numeric_limits<float>::max();
  const float tiny = std::numeric_limits<float>::denorm_min(), least = std::numeric_limits<float>::min();
  std::vector<float> v{0.0f, -0.0f, tiny, -tiny, least, -least, top, -top, inf, -inf, 1.0f, -1.0f, 2 * tiny, 0.1f};
  std::mt19937 rng(7);
  for (int i = 0; i < 100000; ++i) {
    const std::uint32_t b = static_cast<std::uint32_t>(rng());
    float f;
    std::memcpy(&f, &b, sizeof f);
    if (!std::isnan(f)) v.push_back(f);
  }
  auto bits = [](float f) {
    std::uint32_t b;
    std::memcpy(&b, &f, sizeof b);
    return b;
  };
  for (float f : v) {
    EXPECT_EQ(bits(next_float_up(f)), bits(std::nextafter(f, inf))) << f;
    EXPECT_EQ(bits(next_float_down(f)), bits(std::nextafter(f, -inf))) << f;
  }
  EXPECT_TRUE(std::isnan(next_float_up(NAN)));
  EXPECT_TRUE(std::isnan(next_float_down(NAN)));
}

TEST(Predicates2d, RangeEndsAndOneUlp) {
  EXPECT_TRUE(in_filter_range(0));
  EXPECT_TRUE(in_filter_range(0x1p-400));
  EXPECT_TRUE(in_filter_range(-0x1p400));
  EXPECT_FALSE(in_filter_range(0x1p-401));
  EXPECT_FALSE(in_filter_range(0x1p401));
  EXPECT_FALSE(in_filter_range(NAN));
  EXPECT_EQ(next_up(1.0), std::nextafter(1.0, 2.0));
  EXPECT_EQ(next_down(-1.0), std::nextafter(-1.0, -2.0));
  EXPECT_EQ(next_up(0.0), 0x1p-1022);  // no subnormal enters
  EXPECT_EQ(kToDoubleError, 0x1p-52);
  // A rational's double is within kToDoubleError of it (mpq_get_d truncates).
  for (const char* s : {"1/3", "0.1", "-2/7", "123456789/1000000007"}) {
    const Rational q = Q(s);
    const Rational err = abs(Rational(q.get_d()) - q);
    EXPECT_LE(err, abs(q) * Rational(kToDoubleError)) << s;
  }
}

TEST(Predicates2d, ComparisonFilterAndIntervalsOnlyDecideWhatIsTrue) {
  const Rational third = Q("1/3"), close = third + Q("1e-30");
  EXPECT_EQ(compare_filter(third.get_d(), close.get_d()), 0);  // one double: undecided
  EXPECT_EQ(compare_filter(0.25, 0.5), 1);
  EXPECT_EQ(compare_filter(0.5, 0.25), -1);
  // A product with an exact zero interval is zero; sums widen by an ulp each way.
  const Interval z = interval::mul(Interval{0, 0}, Interval{-1e300, 1e300});
  EXPECT_EQ(z.lo, 0);
  EXPECT_EQ(z.hi, 0);
  const Interval s = interval::add(Interval{0.1, 0.1}, Interval{0.2, 0.2});
  EXPECT_LT(Rational(s.lo), Q("3/10"));
  EXPECT_GT(Rational(s.hi), Q("3/10"));
  Interval q;
  EXPECT_FALSE(interval::divide(Interval{1, 1}, Interval{-1, 1}, q));
  // The picture box pad keeps std::max's order (a NaN first stays NaN).
  EXPECT_EQ(box_pad({2.0, -4.0}), 4e-9);
  EXPECT_EQ(box_pad({}), 1e-9 * 1e-300);
  EXPECT_TRUE(std::isnan(box_pad({NAN, 1.0})));
}
