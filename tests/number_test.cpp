// Exact numbers from text (kernel/number.hpp).
#include <gtest/gtest.h>

#include <cmath>

#include "kernel/number.hpp"

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

TEST(Number, BadTokensNameTheToken) {
  for (const char* bad : {"nan", "NaN", "-inf", "inf", "Infinity", "abc", "1/0", "1/-2", "--1", "", "1.2.3",
                          "0x10", "1e", "1e999999", "1e4001", "3/", "/3", "1 2", "e5", "."}) {
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
