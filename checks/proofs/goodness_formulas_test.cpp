// The goodness formulas (experiments/proofs/goodness_formulas.hpp), which the local claims and the atlas build
// their sentences from, against the suite's exact evaluators (theory/local/goodness.hpp) at random rational
// points: the blend's polynomials, and the quantifier-free area property (level E, Lemmas L1, L2). The quantified
// levels are compared by QEPCAD B and Z3 in checks/claims/local_formulas_test.cpp.
#include "experiments/proofs/goodness_formulas.hpp"
#include "theory/local/goodness.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

namespace affinterp::proofs::goodness_formulas_test {
namespace {

using affinterp::local::Mat2;
using exact::Rational;

const PolyMat2 generic_B{{{var("a"), var("b")}, {var("c"), var("d")}}};

rc::Gen<Rational> quarter(int lo, int hi) {
  return rc::gen::map(rc::gen::inRange(lo, hi + 1), [](int k) { return Rational(k) / 4; });
}

/// B with entries in [−3, 3] in steps of 1/4, and the point that puts it into generic_B.
std::pair<Mat2<Rational>, logic::Point> quarter_matrix() {
  Mat2<Rational> B;
  B << *quarter(-12, 12), *quarter(-12, 12), *quarter(-12, 12), *quarter(-12, 12);
  return {B, {{"a", B(0, 0)}, {"b", B(0, 1)}, {"c", B(1, 0)}, {"d", B(1, 1)}}};
}

RC_GTEST_PROP(GoodnessFormulas, BlendPolynomialsAreTheSuitesOwn, ()) {
  auto [B, p] = quarter_matrix();
  const Rational t = *quarter(-8, 8), v1 = *quarter(-8, 8), v2 = *quarter(-8, 8);
  p["t"] = t;
  p["v1"] = v1;
  p["v2"] = v2;
  RC_ASSERT(det_of_blend(generic_B, "t").evaluate(p) == affinterp::local::blend_determinant(B)(t));
  const Mat2<Rational> A_t = affinterp::local::scaled(Rational(1 - t), affinterp::local::identity2<Rational>()) +
                             affinterp::local::scaled(t, B);
  const affinterp::local::Vec2<Rational> w = A_t.lazyProduct(affinterp::local::Vec2<Rational>(v1, v2));
  RC_ASSERT(norm_squared_of_blend(generic_B, var("v1"), var("v2"), "t").evaluate(p) == w(0) * w(0) + w(1) * w(1));
}

RC_GTEST_PROP(GoodnessFormulas, AreaLevelEIsDefinition221, ()) {
  const auto [B, p] = quarter_matrix();
  RC_ASSERT(logic::holds(area_property(generic_B, "E"), p) == affinterp::local::good_for_area(B));
}

}  // namespace
}  // namespace affinterp::proofs::goodness_formulas_test
