// Exact numbers from text (kernel/number.hpp).
#include "kernel/number.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using hlr::parse_rational;
using hlr::Rational;

TEST(Number, DecimalsAreExact) {
  EXPECT_EQ(parse_rational("0.1") + parse_rational("0.2"), Rational(3, 10));
  EXPECT_EQ(parse_rational("0.1"), Rational(1, 10));
  EXPECT_EQ(parse_rational("-2.50"), Rational(-5, 2));
  EXPECT_EQ(parse_rational(".5"), Rational(1, 2));
  EXPECT_EQ(parse_rational("5."), Rational(5));
  EXPECT_EQ(parse_rational("+7"), Rational(7));
  EXPECT_EQ(parse_rational("0.333333333333333333333333"), Rational(mpz_class("333333333333333333333333"), mpz_class("1000000000000000000000000")));
}

TEST(Number, FractionsInLowestTerms) {
  EXPECT_EQ(parse_rational("-3/7"), Rational(-3, 7));
  EXPECT_EQ(hlr::to_string(parse_rational("6/8")), "3/4");
  EXPECT_EQ(hlr::to_string(parse_rational("-6/3")), "-2");
  EXPECT_EQ(parse_rational("0/5"), Rational(0));
}

TEST(Number, Scientific) {
  EXPECT_EQ(parse_rational("1e-3"), Rational(1, 1000));
  EXPECT_EQ(parse_rational("2.5E+2"), Rational(250));
  EXPECT_EQ(parse_rational("-1.25e1"), Rational(-25, 2));
  EXPECT_EQ(parse_rational("1e0"), Rational(1));
}

// The forms exporters write (up to 19 digits, a point anywhere, an exponent of up to three
// digits, signs, leading and trailing zeros) against n·10^p made in GMP and reduced by gcd.
TEST(Number, ExportersDecimalsAreExact) {
  const auto q = [](const char* n, const char* d) {
    Rational r(mpz_class(n, 10), mpz_class(d, 10));
    r.canonicalize();
    return r;
  };
  EXPECT_EQ(parse_rational("6.123233995736766e-17"), q("6123233995736766", "100000000000000000000000000000000"));
  EXPECT_EQ(parse_rational("-1.234567890123456789e-01"), q("-1234567890123456789", "10000000000000000000"));
  EXPECT_EQ(parse_rational("9999999999999999999"), Rational(mpz_class("9999999999999999999")));
  EXPECT_EQ(parse_rational("-0.0e+000"), Rational(0));
  std::mt19937_64 rng(20261205);
  for (int i = 0; i < 20000; ++i) {
    const int digits = 1 + static_cast<int>(rng() % 19);
    std::string ds;
    for (int k = 0; k < digits; ++k) {
      const bool lead = k == 0 && rng() % 4 != 0;  // mostly no leading zero
      ds += static_cast<char>(lead ? '1' + rng() % 9 : '0' + rng() % 10);
    }
    const int point = static_cast<int>(rng() % (digits + 1));  // digits before the point
    const long e = rng() % 3 ? static_cast<long>(rng() % 801) - 400 : 0;
    const bool neg = rng() % 2 != 0;
    std::string text = (neg ? "-" : (rng() % 8 == 0 ? "+" : "")) + ds.substr(0, point) + "." + ds.substr(point);
    if (e != 0 || rng() % 4 == 0) text += (rng() % 2 ? "e" : "E") + std::string(e < 0 ? "-" : (rng() % 2 ? "+" : "")) + std::to_string(std::labs(e));
    mpz_class n(ds, 10), p10;
    const long p = e - (digits - point);
    mpz_ui_pow_ui(p10.get_mpz_t(), 10, static_cast<unsigned long>(std::labs(p)));
    Rational want = p >= 0 ? Rational(n * p10) : Rational(n, p10);
    want.canonicalize();
    if (neg) want = -want;
    const Rational got = parse_rational(text);
    ASSERT_EQ(got, want) << text;
    mpz_class g;  // in lowest terms, with a positive denominator
    mpz_gcd(g.get_mpz_t(), got.get_num_mpz_t(), got.get_den_mpz_t());
    ASSERT_EQ(g, 1) << text;
    ASSERT_GT(got.get_den(), 0) << text;
  }
}

// The decimal parser reads eight digits at a time: one non-digit anywhere in a long run (the
// bytes next to '0' and '9', others that share a digit's low nibble, a high bit) refuses the
// token, and runs that cross the point or end at the exponent read as digit by digit (more
// than 19 digits go to the general parser, exact as well).
TEST(Number, EveryByteOfALongDigitRunIsChecked) {
  std::mt19937_64 rng(20261206);
  const std::string bad = std::string(":;<=>?@`x ") + static_cast<char>(0xB5) + static_cast<char>(0x7F) + static_cast<char>(0x10);
  for (int i = 0; i < 20000; ++i) {
    std::string ds;
    const int digits = 9 + static_cast<int>(rng() % 16);  // past the fast path's 19 too
    for (int k = 0; k < digits; ++k) ds += static_cast<char>('0' + rng() % 10);
    const std::size_t at = rng() % ds.size();
    std::string text = ds;
    text[at] = bad[rng() % bad.size()];
    if (rng() % 2) text += "e-0" + std::to_string(rng() % 10);
    EXPECT_THROW(parse_rational(text), hlr::NumberError) << text;
    const std::size_t point = rng() % (ds.size() + 1);  // the same digits with a point anywhere
    const std::string good = ds.substr(0, point) + "." + ds.substr(point) + "e-3";
    mpz_class p10;
    mpz_ui_pow_ui(p10.get_mpz_t(), 10, static_cast<unsigned long>(ds.size() - point + 3));
    Rational want(mpz_class(ds, 10), p10);
    want.canonicalize();
    ASSERT_EQ(parse_rational(good), want) << good;
  }
}

TEST(Number, BadTokensNameTheToken) {
  for (const char* bad : {"nan",   "NaN",  "-inf", "inf",      "Infinity", "abc", "1/0", "1/-2", "--1", "",
                          "1.2.3", "0x10", "1e",   "1e999999", "1e4001",   "3/",  "/3",  "1 2",  "e5",  "."}) {
    try {
      parse_rational(bad);
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const hlr::NumberError& e) {
      EXPECT_EQ(e.token(), bad);
      EXPECT_NE(std::string(e.what()).find(std::string("'") + bad + "'"), std::string::npos) << e.what();
    }
  }
  EXPECT_EQ(parse_rational("1e4000").get_num().get_str().size(), 4001u);
}

TEST(Number, NanMessageSaysNotFinite) {
  try {
    parse_rational("nan");
    FAIL();
  } catch (const hlr::NumberError& e) {
    EXPECT_NE(std::string(e.what()).find("not a finite number"), std::string::npos);
  }
}

TEST(Number, DoublesConvertExactly) {
  EXPECT_EQ(hlr::rational_from_double(0.5), Rational(1, 2));
  // 0.1 as a double is 3602879701896397 / 2^55, not 1/10.
  EXPECT_EQ(hlr::rational_from_double(0.1), Rational(mpz_class("3602879701896397"), mpz_class("36028797018963968")));
  EXPECT_THROW(hlr::rational_from_double(std::nan("")), hlr::NumberError);
}

TEST(Number, ToDoubleRoundsToNearest) {
  EXPECT_EQ(hlr::to_double(Rational(1, 10)), 0.1);
  EXPECT_EQ(hlr::to_double(Rational(1, 3)), 1.0 / 3.0);
  EXPECT_EQ(hlr::to_double(Rational(-2, 3)), -2.0 / 3.0);
}

// The reference: the nearest double by comparing exact distances to the truncated value and
// its two neighbours (ties toward zero), as to_double did before its one-division path.
double nearest_by_comparison(const Rational& q) {
  double d = q.get_d();
  if (!std::isfinite(d)) return d;
  Rational best(d), err = abs(q - best);
  for (double c : {std::nextafter(d, HUGE_VAL), std::nextafter(d, -HUGE_VAL)}) {
    if (!std::isfinite(c)) continue;
    Rational e = abs(q - Rational(c));
    if (e < err) err = e, d = c;
  }
  return d;
}

TEST(Number, ToDoubleEqualsTheExactComparisonOnRandomAndTiedValues) {
  std::mt19937_64 rng(2026);
  auto big = [&](int bits) {
    mpz_class z = 0;
    for (int b = 0; b < bits; b += 32) z = (z << 32) + static_cast<unsigned long>(rng() & 0xffffffffu);
    z >>= (bits + 31) / 32 * 32 - bits;
    return z == 0 ? mpz_class(1) : z;
  };
  for (int i = 0; i < 20000; ++i) {
    const int nb = 1 + static_cast<int>(rng() % 200), db = 1 + static_cast<int>(rng() % 200);
    Rational q(big(nb), big(db));
    q.canonicalize();
    if (rng() % 2) q = -q;
    if (rng() % 8 == 0) q *= Rational(mpz_class(1) << static_cast<unsigned long>(rng() % 2000), 1) / Rational(mpz_class(1) << 1000, 1);
    ASSERT_EQ(hlr::to_double(q), nearest_by_comparison(q)) << q.get_str();
  }
  // Exact ties between two doubles go toward zero; one above or below a tie goes to its side.
  for (const char* t : {"9007199254740993", "9007199254740995", "-9007199254740995", "18014398509481990", "18014398509481994"}) {
    const Rational q{mpz_class(t)};
    EXPECT_EQ(hlr::to_double(q), nearest_by_comparison(q)) << t;
    EXPECT_EQ(hlr::to_double(Rational(q + Rational(1, 3))), nearest_by_comparison(Rational(q + Rational(1, 3)))) << t;
    EXPECT_EQ(hlr::to_double(Rational(q - Rational(1, 3))), nearest_by_comparison(Rational(q - Rational(1, 3)))) << t;
  }
  // Subnormal and beyond the range: the comparison path.
  const Rational tiny(mpz_class(3), mpz_class(1) << 1070), huge(mpz_class(1) << 1100, mpz_class(7));
  EXPECT_EQ(hlr::to_double(tiny), nearest_by_comparison(tiny));
  EXPECT_EQ(hlr::to_double(huge), nearest_by_comparison(huge));
}

// in_lowest_terms against GMP's gcd on fractions built without canonicalising: decimal
// denominators 2^a·5^b, an odd part of one limb, long odd parts, numerators sharing factors.
TEST(Number, InLowestTermsAgreesWithTheGcd) {
  std::mt19937_64 rng(45);
  auto big = [&](int limbs) {
    mpz_class v = 0;
    for (int i = 0; i < limbs; ++i) v = (v << 64) + mpz_class(std::to_string(rng()));
    return v;
  };
  auto pow = [](unsigned long b, unsigned long e) {
    mpz_class r;
    mpz_ui_pow_ui(r.get_mpz_t(), b, e);
    return r;
  };
  int decided = 0, canonical = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    mpz_class den;
    switch (trial % 5) {
      case 0:
        den = pow(2, rng() % 80) * pow(5, rng() % 30);
        break;
      case 1:
        den = pow(2, rng() % 130) * mpz_class(std::to_string(rng() | 1));
        break;
      case 2:
        den = big(1 + static_cast<int>(rng() % 3));
        break;
      case 3:
        den = pow(10, rng() % 25);
        break;
      default:
        den = mpz_class(std::to_string(rng() % 1000 + 1));
        break;
    }
    if (den == 0) den = 1;
    mpz_class num = big(1 + static_cast<int>(rng() % 2)) >> (rng() % 100);
    if (rng() % 3 == 0) num *= pow(rng() % 2 ? 5 : 2, rng() % 4);
    if (rng() % 7 == 0) num *= mpz_class(std::to_string(rng() % 1000 + 1));
    if (rng() % 11 == 0) num = 0;
    if (rng() % 2) num = -num;
    if (trial % 97 == 0) den = -den;  // not canonical: a negative denominator
    Rational q;
    mpz_set(q.get_num_mpz_t(), num.get_mpz_t());
    mpz_set(q.get_den_mpz_t(), den.get_mpz_t());
    const mpz_class g = gcd(num, den);
    const bool expected = sgn(den) > 0 && g == 1;
    ASSERT_EQ(hlr::in_lowest_terms(q), expected) << num << " / " << den;
    ++decided;
    canonical += expected;
  }
  EXPECT_EQ(decided, 20000);
  EXPECT_GT(canonical, 3000);
  EXPECT_LT(canonical, 17000);
}

// Parsing into an existing number (a reader's vertex storage) gives what parsing anew gives,
// whatever the number held before, and refuses what parse_rational refuses.
TEST(Number, ParseIntoAnExistingNumberIsParseAnew) {
  const char* texts[] = {
      "0",     "-0.0", "12", "-3/7", "6/8", "1e-3", "2.5E+2", "-8.506508000000000402e-01", "6.123233995736766e-17", "123456789012345678901234567890",
      "1e400", ".5",   "5."};
  const Rational before[] = {Rational(0), hlr::rational(-22, 7), Rational(mpz_class("98765432109876543210987654321") << 300), hlr::rational(1, 1024)};
  for (const char* t : texts)
    for (const Rational& b : before) {
      Rational q = b;
      hlr::parse_rational_into(t, q);
      EXPECT_EQ(q, parse_rational(t)) << t;
      EXPECT_EQ(hlr::to_string(q), hlr::to_string(parse_rational(t))) << t;  // lowest terms, the same text
    }
  Rational q = 5;
  EXPECT_THROW(hlr::parse_rational_into("nan", q), hlr::NumberError);
  EXPECT_THROW(hlr::parse_rational_into("1/0", q), hlr::NumberError);
}
