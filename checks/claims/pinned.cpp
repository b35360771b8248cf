#include "checks/claims/pinned.hpp"

#include "experiments/claims/catalogue.hpp"
#include "experiments/claims/registry.hpp"

namespace affinterp::claims {

std::string pin_name(const testing::TestParamInfo<Pin>& info) {
  std::string name(info.param.id);
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

TEST_P(PinnedVerdict, StillHolds) {
  static const CheckRegistry registry = build_registry();
  const Pin pin = GetParam();
  ASSERT_NE(find_claim(pin.id), nullptr) << pin.id << " is not in the catalogue";
  const Check* check = registry.find(pin.id);
  ASSERT_NE(check, nullptr) << pin.id << " is pinned but has no check";
  RunContext context;
  context.size = Size::quick;
  context.threads = 2;
  const Outcome outcome = (*check)(context);
  EXPECT_EQ(to_string(outcome.verdict), to_string(pin.verdict))
      << "the verdict on " << pin.id << " changed from its pinned value: " << outcome.summary;
}

}  // namespace affinterp::claims
