// Same seed ⇒ the same claims.json, apart from timings: every check is run twice, on 1 and on 2
// threads, and the two entries must be identical once `seconds` and `measurements` are removed.
#include "experiments/claims/claims_json.hpp"
#include "experiments/claims/registry.hpp"
#include "experiments/claims/runner.hpp"

#include <gtest/gtest.h>

#include <sstream>

using namespace affinterp::claims;

namespace {

nlohmann::json without_timings(nlohmann::json entry) {
  entry.erase("seconds");
  entry["evidence"].erase("measurements");
  return entry;
}

std::vector<ClaimResult> run_all(unsigned threads) {
  RunContext context;
  context.size = Size::quick;
  context.threads = threads;
  std::ostringstream progress;
  return run_claims(build_registry(), context, {}, progress);
}

}  // namespace

TEST(Determinism, SameSeedGivesTheSameVerdictsAndEvidenceOnAnyThreadCount) {
  const auto one = run_all(1);
  const auto two = run_all(2);
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t i = 0; i < one.size(); ++i) {
    EXPECT_EQ(one[i].error, "") << one[i].info->id;
    EXPECT_EQ(without_timings(to_json(one[i])), without_timings(to_json(two[i])))
        << one[i].info->id << " is not deterministic";
  }
}
