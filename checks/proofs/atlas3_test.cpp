// The 3D goodness deciders (theory/local/goodness3.hpp) on worked examples, and each 3D atlas condition
// (experiments/proofs/atlas3.hpp) against them at random rational points.
#include "experiments/proofs/atlas3.hpp"
#include "experiments/proofs/goodness3_formulas.hpp"
#include "theory/local/goodness3.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

namespace atlas3_test {

using namespace affinterp::proofs;
using affinterp::exact::Rational;
namespace local = affinterp::local;

namespace {

/// p/q with lo ≤ p ≤ 32 and 1 ≤ q ≤ 8.
rc::Gen<Rational> small_rational(int lo) {
  return rc::gen::map(rc::gen::pair(rc::gen::inRange(lo, 33), rc::gen::inRange(1, 9)),
                      [](const std::pair<int, int>& pq) { return Rational(pq.first) / pq.second; });
}

/// The cell's condition and the exact decider at one random point of the domain; false when the decider has no
/// answer there (the linear norm's certificates may both be missing).
bool agrees_at_random_point(const AtlasCell& cell) {
  affinterp::logic::Point p;
  const bool eigenvalues = cell.variables.front() == "l1";
  for (const std::string& v : cell.variables) p[v] = *small_rational(eigenvalues ? 1 : -32) / (eigenvalues ? 8 : 4);
  // det A = 1 + c1 + c2 + c3 > 0 drawn directly
  if (p.contains("c3")) p["c3"] = *small_rational(1) / 4 - 1 - p["c1"] - p["c2"];
  RC_PRE(affinterp::logic::holds(cell.domain, p));
  const std::optional<bool> good = suite_says_good3(cell, p);
  const bool inside = affinterp::logic::holds(cell.condition_formula(), p);
  RC_TAG(inside ? "condition true" : "condition false");
  RC_ASSERT(!good || inside == *good);
  return good.has_value();
}

void check_cell(Homotopy h, Notion n) { agrees_at_random_point(atlas3_cell(h, n)); }

local::Mat3<Rational> diag(Rational a, Rational b, Rational c) { return local::diagonal3(a, b, c); }

}  // namespace

TEST(Goodness3, DeterminantOfTheBlendFromFourValues) {
  // det((1−t)I + t diag(2, 3, 4)) = (1 + t)(1 + 2t)(1 + 3t) = 1 + 6t + 11t² + 6t³
  const local::Cubic<Rational> p = local::blend_determinant3(diag(2, 3, 4));
  EXPECT_EQ(p.c0, 1);
  EXPECT_EQ(p.c1, 6);
  EXPECT_EQ(p.c2, 11);
  EXPECT_EQ(p.c3, 6);
}

TEST(Goodness3, VolumeExamples) {
  EXPECT_TRUE(local::good_for_volume(diag(2, 3, 4)));
  EXPECT_TRUE(local::good_for_volume(diag(Rational(1, 2), Rational(1, 3), 1)));
  // one factor shrinks fast, two grow: p = (1 − (9/10)t)(1 + 2t)² rises, then falls to 9/10 — not monotone
  EXPECT_FALSE(local::good_for_volume(diag(Rational(1, 10), 3, 3)));
  // M with invariants (−1, 0, 1): p = 1 − t + t³, p′ = −1 + 3t² changes sign at 1/√3
  local::Mat3<Rational> B;
  B << 1, 0, 1, 1, 1, 0, 0, 1, 0;
  EXPECT_FALSE(local::good_for_volume(B));
}

TEST(Goodness3, NormExamples) {
  EXPECT_TRUE(local::good_for_norm_polar<Rational>(2, 3, 1));
  EXPECT_TRUE(local::good_for_norm_polar<Rational>(Rational(1, 2), Rational(1, 3), 1));
  EXPECT_FALSE(local::good_for_norm_polar<Rational>(2, Rational(1, 2), 1));
  EXPECT_TRUE(local::good_for_norm_exp_log<Rational>(2, 3, 1));
  EXPECT_FALSE(local::good_for_norm_exp_log<Rational>(Rational(9, 10), 1, Rational(11, 10)));
  EXPECT_EQ(local::good_for_norm_certified(diag(2, 2, 3)), std::optional<bool>(true));
  EXPECT_EQ(local::good_for_norm_certified(diag(Rational(1, 2), Rational(1, 3), Rational(2, 3))),
            std::optional<bool>(true));
  const std::optional<std::array<Rational, 3>> v = local::dipping_direction(diag(2, Rational(1, 2), 1), 8);
  ASSERT_TRUE(v.has_value());
  EXPECT_TRUE(local::norm_dips3(diag(2, Rational(1, 2), 1), *v));
  EXPECT_EQ(local::good_for_norm_certified(diag(2, Rational(1, 2), 1)), std::optional<bool>(false));
}

TEST(Atlas3, SevenCellsAndTheOpenOne) {
  EXPECT_EQ(atlas3_cells().size(), 7u);
  EXPECT_EQ(atlas3_cell(Homotopy::polar, Notion::volume).id(), "polar.volume");
  EXPECT_THROW(atlas3_cell(Homotopy::svd, Notion::norm), std::invalid_argument);
  // the companion map realises the invariants: (c1, c2, c3) = (3, 3, 1) is M = I, A = 2I, good
  EXPECT_EQ(suite_says_good3(atlas3_cell(Homotopy::linear, Notion::volume), {{"c1", 3}, {"c2", 3}, {"c3", 1}}),
            std::optional<bool>(true));
  // the 2D reading (p′ at t = 0 and 1 only) fails in 3D: c = (1, −3, 2), p′ = 1 − 6t + 6t² is 1 at both ends and
  // −1/2 at t = 1/2 (det A = 1)
  const AtlasCell& linear = atlas3_cell(Homotopy::linear, Notion::volume);
  const affinterp::logic::Point c{{"c1", 1}, {"c2", -3}, {"c3", 2}};
  EXPECT_EQ(suite_says_good3(linear, c), std::optional<bool>(false));
  EXPECT_FALSE(affinterp::logic::holds(linear.condition_formula(), c));
}

RC_GTEST_PROP(Atlas3, LinearVolumeAgreesWithTheDecider, ()) { check_cell(Homotopy::linear, Notion::volume); }
RC_GTEST_PROP(Atlas3, PolarVolumeAgreesWithTheDecider, ()) { check_cell(Homotopy::polar, Notion::volume); }
RC_GTEST_PROP(Atlas3, SvdVolumeAgreesWithTheDecider, ()) { check_cell(Homotopy::svd, Notion::volume); }
RC_GTEST_PROP(Atlas3, PolarNormAgreesWithTheDecider, ()) { check_cell(Homotopy::polar, Notion::norm); }
RC_GTEST_PROP(Atlas3, ExpLogNormAgreesWithTheDecider, ()) { check_cell(Homotopy::exp_log, Notion::norm); }

// Where the certificates are both missing the point is skipped: agreement where the decider answers.
RC_GTEST_PROP(Atlas3, LinearNormAgreesWhereTheDeciderAnswers, ()) {
  RC_TAG(agrees_at_random_point(atlas3_cell(Homotopy::linear, Notion::norm)) ? "answered" : "no certificate");
}

// The level-C formulas the sentences decide (goodness3_formulas.hpp) against the exact deciders, which evaluate the
// same per-axis slopes from the forms P, Q (polar) or from signs (exp-log).
RC_GTEST_PROP(Atlas3, ConeFormulasAgreeWithTheDeciders, ()) {
  using affinterp::logic::Polynomial;
  const Rational l1 = *small_rational(1) / 8, l2 = *small_rational(1) / 8, l3 = *small_rational(1) / 8;
  const Eigenvalues l{Polynomial::variable("l1"), Polynomial::variable("l2"), Polynomial::variable("l3")};
  const affinterp::logic::Point p{{"l1", l1}, {"l2", l2}, {"l3", l3}};
  RC_ASSERT(affinterp::logic::holds(polar_norm_cone_property(l), p) == local::good_for_norm_polar(l1, l2, l3));
  RC_ASSERT(affinterp::logic::holds(exp_log_norm_property(l), p) == local::good_for_norm_exp_log(l1, l2, l3));
}

}  // namespace atlas3_test
