// The local claims' first-order encodings (experiments/proofs/goodness_formulas.hpp, experiments/claims/local/
// printed_conditions.hpp) against the suite's exact evaluators (theory/local/goodness.hpp,
// thesis_conditions.hpp, svd_norm_goodness.hpp) at rational points: the printed conditions by exact evaluation
// (logic::holds) at random points; quantified levels by QEPCAD B and Z3 on the sentence with the point substituted,
// at points on both sides of each property. The quantifier-free levels: checks/proofs/goodness_formulas_test.cpp.
#include "experiments/claims/local/printed_conditions.hpp"
#include "experiments/proofs/decide_sentence.hpp"
#include "experiments/proofs/goodness_formulas.hpp"
#include "theory/local/goodness.hpp"
#include "theory/local/svd_norm_goodness.hpp"
#include "theory/local/thesis_conditions.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

namespace affinterp::claims::local::local_formulas_test {
namespace {

using affinterp::local::Mat2;
using exact::Rational;
using proofs::area_property;
using proofs::norm_property;
using proofs::PolyMat2;
using proofs::svd_norm_property;
using proofs::var;

const PolyMat2 generic_B{{{var("a"), var("b")}, {var("c"), var("d")}}};

logic::Point point_of(const Mat2<Rational>& B) {
  return {{"a", B(0, 0)}, {"b", B(0, 1)}, {"c", B(1, 0)}, {"d", B(1, 1)}};
}

Mat2<Rational> matrix(Rational a, Rational b, Rational c, Rational d) {
  Mat2<Rational> B;
  B << a, b, c, d;
  return B;
}

rc::Gen<Rational> quarter(int lo, int hi) {
  return rc::gen::map(rc::gen::inRange(lo, hi + 1), [](int k) { return Rational(k) / 4; });
}

RC_GTEST_PROP(LocalFormulas, ConditionsAreTheThesisConditions, ()) {
  const Rational x = *quarter(-4, 16), y = *quarter(-4, 16), h = *quarter(-8, 8);
  const logic::Point p{{"x", x}, {"y", y}, {"h", h}};
  const Polynomial X = var("x"), Y = var("y"), H = var("h");
  RC_ASSERT(logic::holds(thm_2_2_1_formula(X, Y), p) == affinterp::local::thm_2_2_1_condition(x, y));
  RC_ASSERT(logic::holds(corrected_area_formula(X, Y), p) == affinterp::local::corrected_area_condition(x, y));
  RC_ASSERT(logic::holds(thm_2_2_3_formula(X, Y), p) == affinterp::local::thm_2_2_3_condition(x, y));
  RC_ASSERT(logic::holds(thm_2_2_5_formula(X, Y, H), p) == affinterp::local::thm_2_2_5_condition(x, y, h));
}

std::string text(const Mat2<Rational>& B) {
  return "[[" + exact::to_string(B(0, 0)) + ", " + exact::to_string(B(0, 1)) + "], [" + exact::to_string(B(1, 0)) +
         ", " + exact::to_string(B(1, 1)) + "]]";
}

/// Whether the closed sentence `f` is true, by both deciders (they must agree and decide).
bool decided_true(const std::string& name, const Formula& f) {
  const proofs::SentenceDecision d = proofs::decide_sentence({name, "test", f, {}}, {}, {});
  EXPECT_FALSE(d.disagreement) << name;
  EXPECT_NE(d.result, proofs::SetResult::unknown) << name << ": " << d.reasons();
  return d.result == proofs::SetResult::non_empty;
}

/// `f` with the matrix entries of `B` put in.
Formula at(const Formula& f, const Mat2<Rational>& B) {
  Formula g = f;
  for (const auto& [name, value] : point_of(B)) g = logic::substitute(g, name, Polynomial(value));
  return g;
}

TEST(LocalFormulas, QuantifiedLevelsAgreeWithTheExactDecidersAtRationalPoints) {
  // Good and not good for area (A = [[1/2, 0], [0, 2]] is Thm 2.2.1's counterexample), then for norm.
  const std::vector<Mat2<Rational>> area_points{matrix(Rational(1, 2), 0, 0, 2), matrix(2, 0, 0, 3),
                                                matrix(-1, 0, 0, -1)};
  const std::vector<Mat2<Rational>> norm_points{matrix(2, 0, 0, Rational(1, 2)), matrix(1, 1, -1, 1),
                                                matrix(0, -1, 1, 0)};
  for (const auto& B : area_points)
    for (const std::string level : {"D", "L"})
      EXPECT_EQ(decided_true("area-" + level, at(area_property(generic_B, level), B)),
                affinterp::local::good_for_area(B))
          << "level " << level << " at " << text(B);
  for (const auto& B : norm_points)
    for (const std::string level : {"D", "E", "N"})
      EXPECT_EQ(decided_true("norm-" + level, at(norm_property(generic_B, level), B)),
                affinterp::local::good_for_norm(B))
          << "level " << level << " at " << text(B);
  // Lemma L9's level G against the exact SVD decider (Lemmas L9 + L12).
  for (const auto& [x, y, beta] :
       std::vector<std::tuple<Rational, Rational, Rational>>{{2, 1, 1}, {2, 3, Rational(1, 4)}, {2, Rational(1, 2), 0}})
    EXPECT_EQ(decided_true("svd-G", svd_norm_property(Polynomial(x), Polynomial(y), Polynomial(beta))),
              affinterp::local::svd_good_for_norm<Rational>(x, y, beta * beta))
        << x << ", " << y << ", " << beta;
}

TEST(LocalFormulas, ThePointsCoverBothOutcomes) {
  // The quantified comparison above is worth something only if each property is met and missed among its points.
  EXPECT_FALSE(affinterp::local::good_for_area(matrix(Rational(1, 2), 0, 0, 2)));
  EXPECT_TRUE(affinterp::local::good_for_area(matrix(2, 0, 0, 3)));
  EXPECT_FALSE(affinterp::local::good_for_norm(matrix(2, 0, 0, Rational(1, 2))));
  EXPECT_TRUE(affinterp::local::good_for_norm(matrix(1, 1, -1, 1)));
  EXPECT_FALSE(affinterp::local::svd_good_for_norm<Rational>(2, 1, 1));
  EXPECT_TRUE(affinterp::local::svd_good_for_norm<Rational>(2, 3, Rational(1, 16)));
}

}  // namespace
}  // namespace affinterp::claims::local::local_formulas_test
