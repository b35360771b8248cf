#include "theory/exact/rational.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>

using namespace affinterp::exact;

TEST(Rational, PrintsAsPOverQ) {
  EXPECT_EQ(to_string(Rational(3, 6)), "1/2");
  EXPECT_EQ(to_string(Rational(-4, 2)), "-2");
}

TEST(Rational, ParsesWhatItPrintsAndRejectsGarbage) {
  EXPECT_EQ(parse_rational("-7/21"), Rational(-1, 3));
  EXPECT_EQ(parse_rational("5"), Rational(5));
  EXPECT_THROW(parse_rational("1/0"), std::invalid_argument);
  EXPECT_THROW(parse_rational("0.5"), std::invalid_argument);
  EXPECT_THROW(parse_rational("1/2x"), std::invalid_argument);
}

TEST(Rational, FromDoubleIsExact) {
  EXPECT_EQ(from_double(0.1), Rational(3602879701896397, Integer(1) << 55));
  EXPECT_EQ(from_double(-3.0), Rational(-3));
  EXPECT_THROW(from_double(std::nan("")), std::invalid_argument);
}

RC_GTEST_PROP(Rational, RoundTripsThroughText, (int p, int q)) {
  RC_PRE(q != 0);
  const Rational r = Rational(p) / q;  // Boost 1.74 throws on Rational(p, q) with q < 0
  RC_ASSERT(parse_rational(to_string(r)) == r);
}

RC_GTEST_PROP(Rational, FromDoubleConvertsBackExactly, (double x)) {
  RC_PRE(std::isfinite(x));
  RC_ASSERT(static_cast<double>(from_double(x)) == x);
}
