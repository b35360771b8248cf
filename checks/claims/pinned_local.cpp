#include "checks/claims/pinned.hpp"

#include <vector>

namespace affinterp::claims {
namespace {

// Verdicts of the local claims (Kaji §3, Appendix; thesis §2.2) as first established by
// experiments/claims/local/ (see each check's evidence for the numbers).
const std::vector<Pin> pins = {
    {"kaji.eq1.affine-map", Verdict::confirmed},
    {"kaji.linear.collapse", Verdict::confirmed},
    {"kaji.polar.det", Verdict::confirmed},
    {"kaji.polar.degenerate", Verdict::corrected},  // never negative when λ1 = λ2 ≠ 1; it still vanishes
    {"kaji.svd.degenerate", Verdict::confirmed},
    {"kaji.exp.endpoints", Verdict::confirmed},
    {"kaji.exp.det-positive", Verdict::confirmed},
    {"kaji.exp.det-monotone", Verdict::confirmed},
    {"kaji.appendix.polar-from-svd", Verdict::confirmed},
    {"thesis.thm-2.2.1", Verdict::corrected},  // branch tr A ≥ det A + 1 is wrong, e.g. A = [[2, -1], [-1, 1]]
    {"thesis.thm-2.2.2", Verdict::corrected},  // same error, D = diag(2, 1/2)
    {"thesis.thm-2.2.3", Verdict::refuted},    // the proof drops R_{tβ}: x = 1, y = 1/2, β = π fails
    {"thesis.thm-2.2.4", Verdict::corrected},  // same error as Thm 2.2.1, for S
    {"thesis.thm-2.2.5", Verdict::confirmed},
    {"thesis.thm-2.2.6", Verdict::confirmed},
    {"thesis.ex-2.2.4", Verdict::confirmed},
};

}  // namespace

GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(PinnedVerdict);
INSTANTIATE_TEST_SUITE_P(Local, PinnedVerdict, testing::ValuesIn(pins), pin_name);

}  // namespace affinterp::claims
