#include "theory/logic/condition_parser.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

namespace condition_parser_test {

using namespace affinterp::logic;

namespace {

const std::vector<std::string> vars = {"a", "b", "c", "d"};
const Polynomial a = Polynomial::variable("a"), b = Polynomial::variable("b"), c = Polynomial::variable("c"),
                 d = Polynomial::variable("d");
const std::map<std::string, Polynomial> macros = {{"tr", a + d}, {"det", a* d - b* c}};

bool at(std::string_view text, int va, int vb, int vc, int vd) {
  return holds(parse_condition(text, vars, macros), {{"a", va}, {"b", vb}, {"c", vc}, {"d", vd}});
}

std::string error_of(std::string_view text) {
  try {
    parse_condition(text, vars, macros);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(ConditionParser, TheGrammarOfIssue10) {
  EXPECT_TRUE(at("(2*det <= tr and tr <= 2) or (2 <= tr and tr <= 2*det)", 1, 0, 0, 1));
  EXPECT_FALSE(at("(2*det <= tr and tr <= 2) or (2 <= tr and tr <= 2*det)", 3, 1, -1, 0));
  EXPECT_TRUE(at("a^2 + 1/2 >= 0.25 && !(b != 0) || false", -1, 0, 0, 0));
  EXPECT_TRUE(at("0 < a <= 1 < d", 1, 0, 0, 2));
  EXPECT_FALSE(at("0 < a <= 1 < d", 1, 0, 0, 1));
  EXPECT_TRUE(at("not true or det == 4 - 0", 2, 0, 0, 2));
  EXPECT_TRUE(at("(a + b) * (c - d) = a*c - a*d + b*c - b*d", 3, -7, 2, 5));
  EXPECT_TRUE(at("a^-2 = 1/4", 2, 0, 0, 0));
  EXPECT_TRUE(at(".5 * a = -(-1)", 2, 0, 0, 0));
}

TEST(ConditionParser, DivisionByAVanishingDenominatorMakesTheComparisonFalse) {
  EXPECT_TRUE(at("1/a > 0", 2, 0, 0, 0));
  EXPECT_FALSE(at("1/a > 0", -2, 0, 0, 0));
  EXPECT_FALSE(at("1/a > 0", 0, 0, 0, 0));
  EXPECT_FALSE(at("1/a <= 0", 0, 0, 0, 0));
  EXPECT_TRUE(at("not 1/a > 0", 0, 0, 0, 0));
  EXPECT_TRUE(at("b/a + c/d = 1", 2, 1, 1, 2));
}

TEST(ConditionParser, OneLineErrors) {
  EXPECT_EQ(error_of("x > 0"), "unknown variable 'x' (allowed: a, b, c, d, det, tr) (column 1)");
  EXPECT_EQ(error_of("a^(1/2) > 0"), "exponents must be integers (column 3)");
  EXPECT_EQ(error_of("a^0.5 > 0"), "exponents must be integers (column 3)");
  EXPECT_EQ(error_of("a > 1/0"), "division by zero (column 8)");
  EXPECT_NE(error_of("a + > 0"), "");
  EXPECT_NE(error_of("(a > 0"), "");
  EXPECT_NE(error_of("a > 0)"), "");
  EXPECT_NE(error_of("a $ 0"), "");
  EXPECT_NE(error_of("a + b"), "");
  EXPECT_NE(error_of(""), "");
  for (const char* text : {"x > 0", "a^(1/2) > 0", "(a > 0", "a $ 0", ""})
    EXPECT_EQ(error_of(text).find('\n'), std::string::npos) << text;
}

RC_GTEST_PROP(ConditionParser, AgreesWithDirectEvaluation, (int va, int vb, int vc, int vd)) {
  const Rational det = Rational(va) * vd - Rational(vb) * vc, tr = Rational(va) + vd;
  RC_ASSERT(at("det > tr^2/4 - 1", va, vb, vc, vd) == (det > tr * tr / 4 - 1));
  RC_ASSERT(at("a*d - b*c = det and tr = a + d", va, vb, vc, vd));
}

}  // namespace condition_parser_test
