#include "checks/claims/pinned.hpp"

#include <vector>

namespace affinterp::claims {
namespace {

const std::vector<Pin> pins = {
    {"kaji.er.closed-form", Verdict::confirmed},
    {"kaji.er.positive-definite", Verdict::refuted},
    {"kaji.er.similarity-invariant", Verdict::confirmed},
    {"kaji.ef.translation-invariant", Verdict::confirmed},
    {"kaji.acol.constraint", Verdict::corrected},
    {"kaji.global.G-time-independent", Verdict::refuted},
    {"kaji.symmetrization", Verdict::confirmed},
    {"kaji.fig2-vs-fig4", Verdict::confirmed},
    {"kaji.fig3-vs-fig5", Verdict::confirmed},
    {"kaji.fig6-vs-fig7", Verdict::confirmed},
    {"kaji.blend.suppresses", Verdict::confirmed},
    {"kaji.global.flips", Verdict::confirmed},
};

}  // namespace

GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(PinnedVerdict);
INSTANTIATE_TEST_SUITE_P(Global, PinnedVerdict, testing::ValuesIn(pins), pin_name);

}  // namespace affinterp::claims
