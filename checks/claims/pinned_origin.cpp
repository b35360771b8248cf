#include "checks/claims/pinned.hpp"

#include <vector>

namespace affinterp::claims {
namespace {

const std::vector<Pin> pins = {
    {"thesis.sec-2.3.matrices", Verdict::refuted},     // A1, A2 disagree on the shared edge p2 p3
    {"thesis.sec-2.3.minimiser", Verdict::confirmed},  // printed v1 … v4 = exact minimiser over Q(x, y)
    {"thesis.sec-2.3.min-energy", Verdict::confirmed},
    {"thesis.sec-2.3.conic", Verdict::corrected},      // locus x² − 4xy + y² + x + y = 0 (no −1/4)
};

}  // namespace

GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(PinnedVerdict);
INSTANTIATE_TEST_SUITE_P(Origin, PinnedVerdict, testing::ValuesIn(pins), pin_name);

}  // namespace affinterp::claims
