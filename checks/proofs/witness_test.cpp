// Shrinking sample points to small rationals while an exact predicate holds.
#include "experiments/proofs/witness.hpp"

#include <gtest/gtest.h>

namespace witness_test {

using namespace affinterp::proofs;
using affinterp::exact::Rational;
using affinterp::logic::Point;

TEST(SimpleRationals, OrderedByDenominatorThenNumerator) {
  const std::vector<Rational> c = simple_rationals(Rational(7, 3));
  ASSERT_GE(c.size(), 4u);
  EXPECT_EQ(c[0], Rational(0));
  EXPECT_EQ(c[1], Rational(1));  // 1 before -1: the same size, closer to 7/3
  EXPECT_EQ(c[2], Rational(-1));
}

TEST(ShrinkWitness, MovesEachCoordinateToTheSimplestRationalThatKeepsThePredicate) {
  // x > 1/3 and y < x - 5/2
  const auto holds = [](const Point& p) {
    return p.at("x") > Rational(1, 3) && p.at("y") < p.at("x") - Rational(5, 2);
  };
  const auto shrunk = shrink_witness({{"x", Rational(12345, 1001)}, {"y", Rational(-77, 13)}}, holds);
  ASSERT_TRUE(shrunk);
  EXPECT_TRUE(holds(*shrunk));
  EXPECT_EQ(shrunk->at("x"), Rational(1));
  EXPECT_EQ(shrunk->at("y"), Rational(-2));
}

TEST(ShrinkWitness, ApproximatePointsAreRationalisedOrRejected) {
  // x² < 2 + 1/10⁶ and x² > 2 − 1/10⁶: a thin set around √2, reached from a decimal approximation
  const auto near_root = [](const Point& p) {
    const Rational s = p.at("x") * p.at("x");
    return s < Rational(2) + Rational(1, 1000000) && s > Rational(2) - Rational(1, 1000000);
  };
  const auto shrunk = shrink_witness({{"x", Rational(14142135, 10000000)}}, near_root);
  ASSERT_TRUE(shrunk);
  EXPECT_TRUE(near_root(*shrunk));
  EXPECT_EQ(shrink_witness({{"x", Rational(3)}}, [](const Point& p) { return p.at("x") * p.at("x") == 2; }),
            std::nullopt);
}

TEST(ShrinkWitness, SimplePointsFirst) {
  const auto holds = [](const Point& p) { return p.at("a") * p.at("d") == 1; };
  const auto shrunk = shrink_witness({{"a", Rational(3, 7)}, {"d", Rational(7, 3)}}, holds, {{{"a", 1}, {"d", 1}}});
  EXPECT_EQ(shrunk, (Point{{"a", 1}, {"d", 1}}));
}

}  // namespace witness_test
