#include "theory/logic/formula.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

namespace formula_test {

using namespace affinterp::logic;

namespace {

const Polynomial x = Polynomial::variable("x"), y = Polynomial::variable("y"), t = Polynomial::variable("t");

}  // namespace

TEST(Formula, EvaluatesQuantifierFreeFormulasExactly) {
  const Formula f = (greater(x, 0) && less_equal(x * x, Polynomial(2))) || equal(y, Polynomial(Rational(1, 3)));
  EXPECT_TRUE(holds(f, {{"x", Rational(7, 5)}, {"y", 0}}));
  EXPECT_FALSE(holds(f, {{"x", Rational(3, 2)}, {"y", 0}}));
  EXPECT_TRUE(holds(f, {{"x", -1}, {"y", Rational(1, 3)}}));
  EXPECT_TRUE(holds(!f, {{"x", -1}, {"y", 1}}));
  EXPECT_THROW(holds(exists({"x"}, f), {{"y", 0}}), std::invalid_argument);
}

TEST(Formula, NegationNormalFormFlipsRelationsAndQuantifiers) {
  const Formula f = !(forall({"t"}, less(t, x)) && !greater_equal(x, 1));
  const Formula g = negation_normal_form(f);
  ASSERT_EQ(g.kind, Formula::Kind::disjunction);
  EXPECT_EQ(g.parts[0].kind, Formula::Kind::exists);
  EXPECT_EQ(g.parts[0].parts[0].relation, Relation::greater_equal);
  EXPECT_EQ(g.parts[1].relation, Relation::greater_equal);
}

TEST(Formula, SubstitutesCoordinates) {
  const Formula f = greater(x * y, 1) && !equal(x, 0);
  const Formula g = substitute(f, "x", y + Polynomial(1));
  EXPECT_EQ(free_variables(g), (std::set<std::string>{"y"}));
  EXPECT_TRUE(holds(g, {{"y", 1}}));
  EXPECT_FALSE(holds(g, {{"y", Rational(1, 2)}}));
}

TEST(Formula, SimplifiesConstantsAway) {
  EXPECT_EQ(simplify_constants(greater(x, 0) && truth(true)).kind, Formula::Kind::atom);
  const Formula f = simplify_constants(greater(x, 0) || less(Polynomial(1), Polynomial(2)));
  EXPECT_EQ(f.kind, Formula::Kind::constant);
  EXPECT_TRUE(f.value);
}

TEST(Formula, PrenexRenamesApartAndPutsExistentialBlocksFirst) {
  // (∀t: t·x ≥ 0) ∧ (∃t: t > y) ∧ (∃x: x < 0): the bound x and the second t get fresh names
  const Formula f = forall({"t"}, greater_equal(t * x, 0)) && exists({"t"}, greater(t, y)) && exists({"x"}, less(x, 0));
  const Prenex p = prenex(f);
  ASSERT_EQ(p.prefix.size(), 2u);
  EXPECT_FALSE(p.prefix[0].universal);
  EXPECT_EQ(p.prefix[0].variables, (std::vector<std::string>{"t1", "x1"}));
  EXPECT_TRUE(p.prefix[1].universal);
  EXPECT_EQ(p.prefix[1].variables, (std::vector<std::string>{"t"}));
  EXPECT_EQ(free_variables(f), (std::set<std::string>{"x", "y"}));
  EXPECT_TRUE(is_quantifier_free(p.matrix));
  EXPECT_FALSE(p.existential());
  EXPECT_TRUE(prenex(exists({"x"}, greater(x, 0))).existential());
}

RC_GTEST_PROP(Formula, NegationNormalFormKeepsTheTruthValue, (int a, int b, int p, int q)) {
  const Formula f = !((greater(x * y, Polynomial(a % 7)) || !equal(x, Polynomial(b % 5))) && !less_equal(y, x));
  const Point at{{"x", Rational(p % 11, 1 + std::abs(q % 4))}, {"y", Rational(q % 13)}};
  RC_ASSERT(holds(negation_normal_form(f), at) == holds(f, at));
  RC_ASSERT(holds(prenex(f).matrix, at) == holds(f, at));
}

}  // namespace formula_test
