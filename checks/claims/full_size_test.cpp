// The local claims at the report's full sweep sizes (label `heavy`): each must reach the verdict it
// reaches at the quick size, which the pinned-verdict test fixes.
#include "experiments/claims/registry.hpp"

#include <gtest/gtest.h>

#include <string>

namespace affinterp::claims {
namespace {

class FullSize : public testing::TestWithParam<std::string> {};

TEST_P(FullSize, AgreesWithQuickSize) {
  static const CheckRegistry registry = build_registry();
  const Check* check = registry.find(GetParam());
  ASSERT_NE(check, nullptr);
  RunContext quick, full;
  quick.size = Size::quick, full.size = Size::full;
  quick.threads = full.threads = 2;
  const Outcome at_quick = (*check)(quick), at_full = (*check)(full);
  EXPECT_EQ(to_string(at_full.verdict), to_string(at_quick.verdict)) << at_full.summary;
}

INSTANTIATE_TEST_SUITE_P(Local, FullSize,
                         testing::Values("kaji.eq1.affine-map", "kaji.polar.det", "kaji.polar.degenerate", "kaji.svd.degenerate",
                                         "kaji.exp.endpoints", "kaji.exp.det-positive", "kaji.exp.det-monotone",
                                         "kaji.appendix.polar-from-svd", "thesis.thm-2.2.1", "thesis.thm-2.2.2",
                                         "thesis.thm-2.2.3", "thesis.thm-2.2.4", "thesis.thm-2.2.5", "thesis.thm-2.2.6"),
                         [](const testing::TestParamInfo<std::string>& info) {
                           std::string name = info.param;
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });

}  // namespace
}  // namespace affinterp::claims
