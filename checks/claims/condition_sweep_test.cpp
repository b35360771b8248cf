// The sweep machinery of the local claims (experiments/claims/local/condition_sweep.hpp): it must catch a
// deliberately wrong predicate, keep the simplest disagreement, and give the same tally on any number of
// threads.
#include "experiments/claims/local/condition_sweep.hpp"
#include "experiments/claims/local/simple_values.hpp"
#include "theory/local/goodness.hpp"
#include "theory/local/thesis_conditions.hpp"

#include <gtest/gtest.h>

#include <tuple>

namespace affinterp::claims::local::condition_sweep_test {
namespace {

using affinterp::local::Mat2;
using Case = std::tuple<Rational, Rational, Rational>;  // S = [[x, h], [h, y]]

std::vector<Case> spd_grid() {
  std::vector<Case> cases;
  const Rational step = Rational(1) / 4;
  for (const Rational& x : grid(step, 4, step))
    for (const Rational& y : grid(step, 4, step))
      for (const Rational& h : grid(-3, 3, step))
        if (x * y > h * h) cases.emplace_back(x, y, h);
  return cases;
}

Mat2<Rational> S_of(const Case& c) {
  Mat2<Rational> S;
  S << std::get<0>(c), std::get<2>(c), std::get<2>(c), std::get<1>(c);
  return S;
}

double cost(const Case& c) { return height(std::get<0>(c)) + height(std::get<1>(c)) + height(std::get<2>(c)); }

bool good_for_norm(const Case& c) { return affinterp::local::good_for_norm(S_of(c)); }

TEST(ConditionSweep, CatchesAMutatedBoundary) {
  // Thm 2.2.5 with (x−1)(y−1) > h² instead of ≥: wrong exactly on the boundary, e.g. x = 2, y = 5, h = 2.
  const auto mutated = [](const Case& c) {
    const auto& [x, y, h] = c;
    return (x - 1) * (y - 1) > h * h && (x + y >= 2 || (x <= 1 && y <= 1));
  };
  const auto tally = compare_over(spd_grid(), 2, mutated, good_for_norm, cost);
  EXPECT_EQ(tally.condition_only.count, 0u);
  EXPECT_GT(tally.property_only.count, 0u);
  ASSERT_TRUE(tally.property_only.simplest.has_value());
  EXPECT_FALSE(mutated(*tally.property_only.simplest));
  EXPECT_TRUE(good_for_norm(*tally.property_only.simplest));
}

TEST(ConditionSweep, CatchesAMutatedAreaCondition) {
  // The corrected area condition with "tr ≤ 2" weakened to "tr < 2" misses every good S with tr S = 2.
  const auto mutated = [](const Case& c) {
    const Mat2<Rational> S = S_of(c);
    const Rational trace = S.trace(), det = affinterp::local::det2(S);
    return (2 * det <= trace && trace < 2) || (2 < trace && trace <= 2 * det);
  };
  const auto property = [](const Case& c) { return affinterp::local::good_for_area(S_of(c)); };
  const auto tally = compare_over(spd_grid(), 2, mutated, property, cost);
  EXPECT_GT(tally.property_only.count, 0u);
  EXPECT_EQ(S_of(*tally.property_only.simplest).trace(), 2);
}

TEST(ConditionSweep, PrintedThm225AgreesAndIsThreadIndependent) {
  const auto printed = [](const Case& c) {
    return affinterp::local::thm_2_2_5_condition(std::get<0>(c), std::get<1>(c), std::get<2>(c));
  };
  const auto one = compare_over(spd_grid(), 1, printed, good_for_norm, cost);
  const auto two = compare_over(spd_grid(), 2, printed, good_for_norm, cost);
  EXPECT_EQ(one.disagreements(), 0u);
  EXPECT_EQ(one.summary(), two.summary());
}

TEST(ConditionSweep, KeepsTheSimplestDisagreement) {
  const std::vector<Case> cases{{3, 3, 1}, {Rational(1) / 2, 1, 0}, {2, 2, 0}};
  const auto tally = compare_over(
      cases, 2, [](const Case&) { return true; }, [](const Case&) { return false; }, cost);
  EXPECT_EQ(tally.condition_only.count, 3u);
  EXPECT_EQ(std::get<0>(*tally.condition_only.simplest), Rational(1) / 2);  // height 2 + 1 + 1
}

}  // namespace
}  // namespace affinterp::claims::local::condition_sweep_test
