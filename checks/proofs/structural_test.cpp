// Structural sentences: empty for propositional reasons alone.
#include "experiments/proofs/structural.hpp"

#include <gtest/gtest.h>

namespace structural_test {

using namespace affinterp::logic;
using affinterp::proofs::is_structural;

namespace {
const Polynomial x = Polynomial::variable("x"), y = Polynomial::variable("y");
const Polynomial p = x * x - y;
}  // namespace

TEST(Structural, AnAtomAndItsNegationIs) {
  EXPECT_TRUE(is_structural(exists({"x", "y"}, greater(p, 0) && !greater(p, 0))));
  EXPECT_TRUE(is_structural(exists({"x", "y"}, greater(p, 0) && less_equal(p, 0))));
  // The same sign condition written on −p.
  EXPECT_TRUE(is_structural(exists({"x", "y"}, greater(p, 0) && greater_equal(-p, 0))));
  EXPECT_TRUE(is_structural(
      exists({"x"}, forall({"y"}, (equal(p, 0) || less(x, 1)) && not_equal(p, 0) && greater_equal(x, 1)))));
}

TEST(Structural, ASentenceEmptyForItsPolynomialsIsNot) {
  // p > 0 and p < 0 are independent booleans: the emptiness rests on the polynomial.
  EXPECT_FALSE(is_structural(exists({"x", "y"}, greater(p, 0) && less(p, 0))));
  EXPECT_FALSE(is_structural(exists({"x"}, less(x * x, 0))));
  EXPECT_FALSE(is_structural(exists({"x", "y"}, greater(p, 0) && (less_equal(p, 0) || greater(x, 2)))));
}

}  // namespace structural_test
