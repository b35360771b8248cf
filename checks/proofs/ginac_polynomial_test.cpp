#include "experiments/proofs/ginac_polynomial.hpp"

#include <gtest/gtest.h>

namespace affinterp::proofs::ginac_polynomial_test {
namespace {

TEST(GinacPolynomial, ExpandsWithTheoryLogicsArithmetic) {
  const GiNaC::symbol x("x"), y("y");
  const logic::Polynomial p = to_polynomial(GiNaC::pow(x - y, 2) * GiNaC::numeric(1, 2) + 3);
  const logic::Polynomial X = logic::Polynomial::variable("x"), Y = logic::Polynomial::variable("y");
  EXPECT_EQ(p, exact::Rational(1, 2) * X * X - X * Y + exact::Rational(1, 2) * Y * Y + 3);
  EXPECT_EQ(p.evaluate({{"x", 3}, {"y", 1}}), 5);
}

TEST(GinacPolynomial, RefusesWhatIsNotAPolynomial) {
  const GiNaC::symbol x("x");
  EXPECT_THROW(to_polynomial(1 / x), std::invalid_argument);
  EXPECT_THROW(to_polynomial(GiNaC::exp(x)), std::invalid_argument);
  EXPECT_THROW(to_polynomial(GiNaC::sqrt(x)), std::invalid_argument);
}

}  // namespace
}  // namespace affinterp::proofs::ginac_polynomial_test
