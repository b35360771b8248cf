#include "theory/logic/polynomial.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

namespace polynomial_test {

using namespace affinterp::logic;

namespace {

const Polynomial x = Polynomial::variable("x"), y = Polynomial::variable("y");

Rational small_rational(int p, int q) { return Rational(p % 50) / Rational(1 + std::abs(q % 9)); }

}  // namespace

TEST(Polynomial, ArithmeticCancelsExactly) {
  EXPECT_TRUE((x * y - y * x).is_zero());
  EXPECT_EQ(pow(x + y, 2), x * x + Polynomial(2) * x * y + y * y);
  EXPECT_EQ(to_string(pow(x - Polynomial(1), 2)), "1 - 2*x + x^2");
  EXPECT_EQ((x * y + Polynomial(Rational(1, 2))).variables(), (std::set<std::string>{"x", "y"}));
  EXPECT_EQ(pow(x, 3).degree_in("x"), 3u);
  EXPECT_TRUE(Polynomial(Rational(3, 4)).is_constant());
}

TEST(Polynomial, EvaluatesAndSubstitutes) {
  const Polynomial p = x * x * y - Polynomial(3);
  EXPECT_EQ(p.evaluate({{"x", Rational(1, 2)}, {"y", Rational(8)}}), Rational(-1));
  EXPECT_THROW(p.evaluate({{"x", Rational(1)}}), std::invalid_argument);
  // b = s − k, c = s + k (the symmetric/skew coordinates of decide's linear norm queries)
  const Polynomial s = Polynomial::variable("s"), k = Polynomial::variable("k");
  EXPECT_EQ((x * y).substitute("x", s - k).substitute("y", s + k), s * s - k * k);
  EXPECT_EQ(p.rename({{"x", "u"}}).variables(), (std::set<std::string>{"u", "y"}));
  EXPECT_EQ(p.derivative("x"), Polynomial(2) * x * y);
  EXPECT_TRUE(p.derivative("z").is_zero());
}

RC_GTEST_PROP(Polynomial, EvaluationIsARingHomomorphism, (int a, int b, int c, int d, int e, int f)) {
  const Polynomial p = x * x + Polynomial(small_rational(a, b)) * y, q = x * y - Polynomial(small_rational(c, d));
  const Point at{{"x", small_rational(e, f)}, {"y", small_rational(f, e)}};
  RC_ASSERT((p * q).evaluate(at) == p.evaluate(at) * q.evaluate(at));
  RC_ASSERT((p - q).evaluate(at) == p.evaluate(at) - q.evaluate(at));
  RC_ASSERT(pow(p, 3).evaluate(at) == p.evaluate(at) * p.evaluate(at) * p.evaluate(at));
}

}  // namespace polynomial_test
