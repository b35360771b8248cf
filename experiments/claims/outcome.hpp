#pragma once
// What a check returns: the verdict on one claim and the evidence behind it.
#include "experiments/claims/verdict.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace affinterp::claims {

/// How a verdict was reached. Everything here except `measurements` must be deterministic for a seed.
struct Evidence {
  std::string method;                                      ///< e.g. "exact rational computation", "grid sweep"
  std::uint64_t sample_size = 0;                           ///< cases examined (grid points, random draws, ...)
  std::optional<std::uint64_t> seed;                       ///< RNG seed of the sample, when random
  std::optional<double> tolerance;                         ///< numerical tolerance of the comparison, when inexact
  std::optional<double> worst_deviation;                   ///< largest deviation seen from the claimed statement
  nlohmann::json details = nlohmann::json::object();       ///< further deterministic numbers
  nlohmann::json measurements = nlohmann::json::object();  ///< timings and speeds: vary run to run
};

struct Outcome {
  Verdict verdict = Verdict::pending;
  std::string summary;  ///< one line: what was found
  Evidence evidence;
  /// Every input needed to re-verify independently: matrices as arrays of rows, exact values as
  /// "p/q" strings, parameters under the paper's own names (x, y, h, alpha, beta, A, v, t).
  nlohmann::json counterexample = nullptr;
  std::optional<std::string> correction;  ///< the corrected statement, for `corrected`
  std::vector<std::string> figures;       ///< paths relative to the report's folder
};

}  // namespace affinterp::claims
