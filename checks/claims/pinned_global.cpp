#include "checks/claims/pinned.hpp"

#include <vector>

namespace affinterp::claims {
namespace {

const std::vector<Pin> pins = {
};

}  // namespace

GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(PinnedVerdict);
INSTANTIATE_TEST_SUITE_P(Global, PinnedVerdict, testing::ValuesIn(pins), pin_name);

}  // namespace affinterp::claims
