#pragma once
// Pinned verdicts: what the evidence showed when a claim was first decided. Each pin reruns the claim's
// check at the quick size and fails, naming the claim, when the verdict differs. A pin records a
// finding; it is never chosen to make a check pass.
#include "experiments/claims/verdict.hpp"

#include <gtest/gtest.h>

#include <ostream>
#include <string_view>

namespace affinterp::claims {

struct Pin {
  std::string_view id;
  Verdict verdict;
};

inline void PrintTo(const Pin& pin, std::ostream* os) { *os << pin.id << " = " << to_string(pin.verdict); }

class PinnedVerdict : public testing::TestWithParam<Pin> {};

/// Test names from claim IDs ("kaji.polar.det" -> "kaji_polar_det").
std::string pin_name(const testing::TestParamInfo<Pin>& info);

}  // namespace affinterp::claims
