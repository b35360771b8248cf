#include "theory/origin/equal_energy_locus.hpp"
#include "theory/origin/symbols.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace equal_energy_locus_test {

using namespace affinterp::origin;

namespace {
GiNaC::ex x() { return symbols().x; }
GiNaC::ex y() { return symbols().y; }
}  // namespace

TEST(LocusPolynomial, IsThePrimitiveNumeratorWithPositiveLeadingCoefficient) {
  const GiNaC::ex difference = (-GiNaC::numeric(2, 3) * x() * x() + 4 * x() * y() - 2) / (x() * x() + 1);
  EXPECT_TRUE((locus_polynomial(difference) - (x() * x() - 6 * x() * y() + 3)).expand().is_zero());
}

TEST(Proportional, AcceptsNonzeroConstantMultiplesOnly) {
  const GiNaC::ex P = x() * x() - 4 * x() * y() + y() * y() + x() + y();
  EXPECT_TRUE(proportional(P, (-3 * P).expand()));
  EXPECT_FALSE(proportional(P, P - GiNaC::numeric(1, 4)));
  EXPECT_FALSE(proportional(P, x() * P));
  EXPECT_FALSE(proportional(P, 0));
}

TEST(TotalDegree, CountsTheLargestMonomial) {
  EXPECT_EQ(total_degree(x() * y() * y() + x()), 3);
  EXPECT_EQ(total_degree(x() * x() - 4 * x() * y()), 2);
  EXPECT_EQ(total_degree(GiNaC::ex(5)), 0);
  EXPECT_EQ(total_degree(GiNaC::ex(0)), -1);
}

TEST(PositiveQuadratic, DecidesPositivityOnThePlane) {
  EXPECT_TRUE(positive_quadratic(x() * x() + y() * y() + 1));
  EXPECT_TRUE(positive_quadratic(GiNaC::pow(x() + y() - 1, 2) + 2));  // degenerate quadratic part
  EXPECT_TRUE(positive_quadratic(GiNaC::ex(1)));
  EXPECT_FALSE(positive_quadratic(GiNaC::pow(x() + y(), 2)));  // vanishes on a line
  EXPECT_FALSE(positive_quadratic(x() * x() - y() * y() + 5));
  EXPECT_FALSE(positive_quadratic(GiNaC::pow(x() + y(), 2) + x() + 3));  // unbounded below along x = −y
  EXPECT_FALSE(positive_quadratic(x() + 1));
  EXPECT_FALSE(positive_quadratic(x() * x() * x() + 1));
}

TEST(SmallRationalPoints, FindsPointsThatLieOnTheCurve) {
  const GiNaC::ex circle = x() * x() + y() * y() - 1;
  const auto points = small_rational_points(circle, 10);
  ASSERT_FALSE(points.empty());
  for (const auto& [px, py] : points) EXPECT_TRUE(circle.subs(GiNaC::lst{x() == px, y() == py}).is_zero());
  EXPECT_TRUE(small_rational_points(x() * x() + y() * y() + 1, 10).empty());
  EXPECT_THROW(small_rational_points(y() * y() * y(), 1), std::invalid_argument);
}

}  // namespace equal_energy_locus_test
