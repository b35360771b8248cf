#include "experiments/claims/runner.hpp"

#include "experiments/claims/kernel_checks.hpp"

#include <algorithm>
#include <chrono>
#include <iomanip>
#include <iostream>
#include <ostream>
#include <sstream>
#include <stdexcept>

#include <unistd.h>

namespace affinterp::claims {

std::vector<ClaimResult> run_claims(const ClaimRegistry& registry, const RunContext& context,
                                    const std::vector<std::string>& ids, std::ostream& progress) {
  for (const auto& id : ids)
    if (registry.find(id) == nullptr) throw std::invalid_argument("unknown claim ID '" + id + "' (see --list)");

  std::vector<const Claim*> selected;
  for (const Claim& claim : registry.claims())
    if (ids.empty() || std::find(ids.begin(), ids.end(), claim.id) != ids.end()) selected.push_back(&claim);

  // On a terminal the line shows "..." while a check runs and is then completed in place; in a log each
  // claim gets one line, written when its check ends.
  const bool terminal = &progress == &std::cerr && isatty(STDERR_FILENO) == 1;
  const KernelChecks kernel = read_kernel_checks(context.answer_dir / "coq" / "MANIFEST.json");
  std::vector<ClaimResult> results;
  std::size_t index = 0;
  for (const Claim* claim : selected) {
    ++index;
    ClaimResult result{claim, {}, 0, {}};
    std::ostringstream line;
    line << "[" << std::setw(2) << index << "/" << selected.size() << "] " << claim->id << " ... ";
    if (terminal) progress << line.str() << std::flush;
    if (claim->check) {
      const auto start = std::chrono::steady_clock::now();
      try {
        result.outcome = claim->check(context.for_claim(claim->id));
        if (result.outcome.strength == Strength::unstated) result.outcome.strength = claim->strength;
        apply_kernel_checks(std::string(claim->id), result.outcome, kernel);
      } catch (const std::exception& e) {
        result.error = e.what();
      }
      result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    } else {
      result.outcome.summary = "no check implemented yet";
    }
    progress << (terminal ? "\r" : "") << line.str();  // a check's Progress may have overwritten the line
    if (result.error.empty())
      progress << to_string(result.outcome.verdict) << " (" << std::fixed << std::setprecision(2) << result.seconds
               << " s)\n";
    else
      progress << "FAILED TO RUN: " << result.error << "\n";
    results.push_back(std::move(result));
  }
  return results;
}

}  // namespace affinterp::claims
