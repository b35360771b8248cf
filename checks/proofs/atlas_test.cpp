// The atlas conditions against the suite's own exact deciders (theory/local/goodness.hpp) at random rational
// points: the encoder and the exact evaluators agree.
#include "experiments/proofs/atlas.hpp"
#include "theory/local/goodness.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

namespace atlas_test {

using namespace affinterp::proofs;
using affinterp::exact::Rational;

namespace {

/// A small rational p/q with lo ≤ p ≤ 32 and q ≤ 8, often a "boundary" value (0, ±1, 1/2, 2).
rc::Gen<Rational> small_rational(int lo) {
  return rc::gen::map(rc::gen::pair(rc::gen::inRange(lo, 33), rc::gen::inRange(1, 9)),
                      [](const std::pair<int, int>& pq) { return Rational(pq.first) / pq.second; });
}

void check_cell(Homotopy h, Notion n) {
  const AtlasCell& cell = atlas_cell(h, n);
  const affinterp::logic::Formula condition = cell.condition_formula();
  affinterp::logic::Point p;
  // x and y are positive in every cell that has them (D = diag(x, y), S = [[x, h], [h, y]] ≻ 0)
  for (const std::string& v : cell.variables) p[v] = *small_rational(v == "x" || v == "y" ? 1 : -32);
  // |h| < min(x, y), so that S is positive definite
  if (p.contains("h")) p["h"] = Rational(*rc::gen::inRange(-7, 8), 8) * std::min(p["x"], p["y"]);
  RC_PRE(affinterp::logic::holds(cell.domain, p));
  const std::optional<bool> good = suite_says_good(cell, p);
  RC_ASSERT(good.has_value());
  RC_ASSERT(affinterp::logic::holds(condition, p) == *good);
}

}  // namespace

RC_GTEST_PROP(Atlas, LinearAreaAgreesWithTheSuite, ()) { check_cell(Homotopy::linear, Notion::area); }
RC_GTEST_PROP(Atlas, LinearNormAgreesWithTheSuite, ()) { check_cell(Homotopy::linear, Notion::norm); }
RC_GTEST_PROP(Atlas, SvdAreaAgreesWithTheSuite, ()) { check_cell(Homotopy::svd, Notion::area); }
RC_GTEST_PROP(Atlas, PolarAreaAgreesWithTheSuite, ()) { check_cell(Homotopy::polar, Notion::area); }
RC_GTEST_PROP(Atlas, PolarNormAgreesWithTheSuite, ()) { check_cell(Homotopy::polar, Notion::norm); }

TEST(Atlas, EightCellsWithTheirVariables) {
  ASSERT_EQ(atlas_cells().size(), 8u);
  EXPECT_EQ(atlas_cell(Homotopy::svd, Notion::norm).variables, (std::vector<std::string>{"x", "y", "beta"}));
  EXPECT_EQ(atlas_cell(Homotopy::exp_log, Notion::area).id(), "exp-log.area");
  EXPECT_FALSE(suite_says_good(atlas_cell(Homotopy::svd, Notion::norm), {{"x", 1}, {"y", 2}, {"beta", 0}}));
}

}  // namespace atlas_test
