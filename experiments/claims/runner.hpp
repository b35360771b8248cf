#pragma once
// Runs checks and collects their outcomes, reporting progress as it goes.
#include "experiments/claims/registry.hpp"

#include <iosfwd>
#include <string>
#include <vector>

namespace affinterp::claims {

struct ClaimResult {
  const Claim* claim = nullptr;
  Outcome outcome;
  double seconds = 0;  ///< wall time of the check (a timing: varies run to run)
  std::string error;   ///< non-empty when the check failed to run
};

/// Runs the checks of `ids` (every claim of `registry` when empty) in run order, each under
/// context.for_claim(its ID); progress lines go to `progress`. A claim with no check gets verdict
/// `pending`. Unknown IDs throw std::invalid_argument before anything runs.
std::vector<ClaimResult> run_claims(const ClaimRegistry& registry, const RunContext& context,
                                    const std::vector<std::string>& ids, std::ostream& progress);

}  // namespace affinterp::claims
