// Same seed ⇒ the same claims.json, apart from timings: every check is run twice, on 1 and on 2
// threads, and the two entries must be identical once `seconds` and `measurements` are removed.
#include "experiments/claims/claims_json.hpp"
#include "experiments/claims/runner.hpp"

#include <gtest/gtest.h>

#include <sstream>

using namespace affinterp::claims;

namespace {

/// The entry as claims.json writes it, less its timings. (Text, not JSON values: a NaN in the evidence
/// is written as null, and compares unequal to itself as a value.)
std::string without_timings(const ClaimResult& result) {
  nlohmann::json entry = to_json(result);
  entry.erase("seconds");
  entry["evidence"].erase("measurements");
  if (entry["proof"].is_object())
    for (auto& sentence : entry["proof"]["sentences"]) {
      sentence.erase("seconds");
      for (auto& run : sentence["runs"]) run.erase("seconds");
    }
  return entry.dump(1);
}

std::vector<ClaimResult> run_all(unsigned threads) {
  RunContext context;
  context.size = Size::quick;
  context.threads = threads;
  std::ostringstream progress;
  return run_claims(registered_claims(), context, {}, progress);
}

}  // namespace

TEST(Determinism, SameSeedGivesTheSameVerdictsAndEvidenceOnAnyThreadCount) {
  const auto one = run_all(1);
  const auto two = run_all(2);
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t i = 0; i < one.size(); ++i) {
    EXPECT_EQ(one[i].error, "") << one[i].claim->id;
    EXPECT_EQ(without_timings(one[i]), without_timings(two[i])) << one[i].claim->id << " is not deterministic";
  }
}
