// `decide` end to end with QEPCAD B and Z3 (label `proof`): controls — a deliberately wrong condition comes out
// not equivalent with a re-verified counterexample, the right one equivalent.
#include "experiments/proofs/decide_condition.hpp"
#include "theory/logic/condition_parser.hpp"

#include <gtest/gtest.h>

namespace decide_test {

using namespace affinterp::proofs;
using affinterp::exact::Rational;

namespace {

ConditionVerdict decide(Homotopy h, Notion n, const std::string& text) {
  const AtlasCell& cell = atlas_cell(h, n);
  return decide_condition(cell, affinterp::logic::parse_condition(text, cell.variables, cell.macros), {.seconds = 25});
}

}  // namespace

TEST(Decide, TheCorrectedTheorem221IsEquivalent) {
  const ConditionVerdict v = decide(Homotopy::linear, Notion::area, "(2*det <= tr and tr <= 2) or (2 <= tr <= 2*det)");
  EXPECT_EQ(v.verdict, ConditionVerdict::Verdict::equivalent) << v.reason;
}

TEST(Decide, ThePrintedTheorem221IsNotEquivalent) {
  const ConditionVerdict v =
      decide(Homotopy::linear, Notion::area, "tr >= det + 1 or (2*det <= tr and tr < 2) or (2 <= tr and tr < 2*det)");
  ASSERT_EQ(v.verdict, ConditionVerdict::Verdict::not_equivalent) << v.reason;
  ASSERT_TRUE(v.counterexample);
  const Counterexample& c = *v.counterexample;
  EXPECT_TRUE(c.condition);
  EXPECT_FALSE(c.property);
  EXPECT_TRUE(c.checked_by_suite);
  // small: every coordinate's denominator at most 8
  for (const auto& [name, value] : c.point) EXPECT_LE(boost::multiprecision::denominator(value), 8) << name;
}

TEST(Decide, PolarNormThm225AsPrintedIsEquivalentAndAWrongOneIsNot) {
  EXPECT_EQ(
      decide(Homotopy::polar, Notion::norm, "(x - 1)*(y - 1) >= h^2 and (x + y >= 2 or (0 < x <= 1 and 0 < y <= 1))")
          .verdict,
      ConditionVerdict::Verdict::equivalent);
  const ConditionVerdict wrong = decide(Homotopy::polar, Notion::norm, "x >= 1 and y >= 1");
  ASSERT_EQ(wrong.verdict, ConditionVerdict::Verdict::not_equivalent);
  ASSERT_TRUE(wrong.counterexample);
  EXPECT_TRUE(wrong.counterexample->checked_by_suite);
}

TEST(Decide, SvdNormWithBeta) {
  EXPECT_EQ(decide(Homotopy::svd, Notion::norm, "(x >= 1 and y >= 1) or (x <= 1 and y <= 1)").verdict,
            ConditionVerdict::Verdict::not_equivalent);
}

TEST(Decide, LinearNormInSymmetricSkewCoordinates) {
  const ConditionVerdict v = decide(Homotopy::linear, Notion::norm, "a >= 1 and d >= 1 and 4*(a-1)*(d-1) >= (b+c)^2");
  ASSERT_EQ(v.verdict, ConditionVerdict::Verdict::not_equivalent) << v.reason;
  EXPECT_FALSE(v.counterexample->condition);
  EXPECT_TRUE(v.counterexample->property);
  EXPECT_TRUE(v.counterexample->checked_by_suite);
}

namespace {

ConditionVerdict decide3(const std::string& homotopy, const std::string& notion, const std::string& text) {
  const AtlasCell& cell = decide_cell(3, homotopy, notion);
  return decide_condition(cell, affinterp::logic::parse_condition(text, cell.variables, cell.macros), {.seconds = 25});
}

}  // namespace

TEST(Decide3, PolarNormSemidefiniteIsEquivalentAndOneSidedIsNot) {
  EXPECT_EQ(decide3("polar", "norm", "(l1 >= 1 and l2 >= 1 and l3 >= 1) or (l1 <= 1 and l2 <= 1 and l3 <= 1)").verdict,
            ConditionVerdict::Verdict::equivalent);
  const ConditionVerdict wrong = decide3("polar", "norm", "l1 >= 1 and l2 >= 1");
  ASSERT_EQ(wrong.verdict, ConditionVerdict::Verdict::not_equivalent) << wrong.reason;
  EXPECT_TRUE(wrong.counterexample->checked_by_suite);
}

TEST(Decide3, TheTwoDimensionalEndpointTestIsNotTheLinearVolume) {
  // In 2D p′ is affine and its signs at t = 0 and 1 decide (Lemma L2); in 3D p′ is quadratic and can dip between
  // two positive ends, e.g. (c1, c2, c3) = (1, −3, 2): p′ = 1 − 6t + 6t² < 0 at t = 1/2.
  const ConditionVerdict v = decide3("linear", "volume", "c1*(c1 + 2*c2 + 3*c3) >= 0");
  ASSERT_EQ(v.verdict, ConditionVerdict::Verdict::not_equivalent) << v.reason;
  EXPECT_TRUE(v.counterexample->condition);
  EXPECT_FALSE(v.counterexample->property);
  EXPECT_TRUE(v.counterexample->checked_by_suite);
}

TEST(Decide3, BadCellsAreRefusedWithAReason) {
  EXPECT_THROW(decide_cell(3, "svd", "norm"), std::invalid_argument);
  EXPECT_THROW(decide_cell(3, "polar", "area"), std::invalid_argument);
  EXPECT_THROW(decide_cell(2, "polar", "volume"), std::invalid_argument);
  EXPECT_THROW(decide_cell(4, "polar", "norm"), std::invalid_argument);
}

}  // namespace decide_test
