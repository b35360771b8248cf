// The local claims at the report's full sweep sizes (label `heavy`): each must reach the verdict it
// reaches at the quick size, which the pinned-verdict test fixes.
#include "experiments/claims/registry.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace affinterp::claims::full_size_test {
namespace {

/// The IDs of the local chapter's claims.
std::vector<std::string> local_claims() {
  std::vector<std::string> ids;
  for (const Claim& claim : registered_claims().claims())
    if (claim.chapter == Chapter::local) ids.emplace_back(claim.id);
  return ids;
}

class FullSize : public testing::TestWithParam<std::string> {};

TEST_P(FullSize, AgreesWithQuickSize) {
  const Claim& claim = *registered_claims().find(GetParam());
  RunContext quick, full;
  quick.size = Size::quick, full.size = Size::full;
  quick.threads = full.threads = 2;
  const Outcome at_quick = claim.check(quick.for_claim(claim.id)), at_full = claim.check(full.for_claim(claim.id));
  EXPECT_EQ(to_string(at_full.verdict), to_string(at_quick.verdict)) << at_full.summary;
}

INSTANTIATE_TEST_SUITE_P(Local, FullSize, testing::ValuesIn(local_claims()),
                         [](const testing::TestParamInfo<std::string>& info) { return file_stem(info.param); });

}  // namespace
}  // namespace affinterp::claims::full_size_test
