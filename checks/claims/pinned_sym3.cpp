#include "checks/claims/pinned.hpp"

#include <vector>

namespace affinterp::claims {
namespace {

const std::vector<Pin> pins = {
    {"thesis.eq-3.charpoly", Verdict::confirmed},
    {"thesis.viete", Verdict::confirmed},
    {"thesis.sd.case1", Verdict::confirmed},
    {"thesis.sd.case2", Verdict::confirmed},
    {"thesis.sd.case3", Verdict::corrected},
    // Measured speed verdicts (thesis.*.speedup) depend on the machine and are never pinned.
    {"thesis.exp.accuracy", Verdict::refuted},
};

}  // namespace

GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(PinnedVerdict);
INSTANTIATE_TEST_SUITE_P(Sym3, PinnedVerdict, testing::ValuesIn(pins), pin_name);

}  // namespace affinterp::claims
