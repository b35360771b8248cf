#pragma once
// A measured speed figure with its uncertainty, and the verdict that follows from it (issue 11): the figure
// (a ratio of medians, or one median) from the repetitions of a Google Benchmark run, its 95% percentile
// bootstrap interval (bootstrap.hpp), and the band of values the claim's wording allows. The verdict is
// reproduced when the interval lies in the band, not-reproduced when it lies outside, inconclusive when it
// straddles an edge or when fewer than kMinRepetitions repetitions were recorded.
#include "experiments/claims/bench_results.hpp"
#include "experiments/claims/bootstrap.hpp"
#include "experiments/claims/verdict.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <limits>
#include <optional>
#include <string_view>

namespace affinterp::claims {

/// The repetitions a benchmark needs for an interval (the benchmarks run this many, bench_context.hpp).
inline constexpr std::size_t kMinRepetitions = 10;
/// The seed of every bootstrap of a measured figure (fixed: the same file gives the same interval).
inline constexpr std::uint64_t kBootstrapSeed = 2015;
inline constexpr double kUnbounded = std::numeric_limits<double>::infinity();

struct Measured {
  double value = 0;              ///< the figure from the medians
  std::optional<Interval> ci95;  ///< nullopt with fewer than kMinRepetitions repetitions
  std::size_t repetitions = 0;   ///< the fewest repetitions among the benchmarks it reads
};

/// median(slow) / median(fast), a speed-up, with the bootstrap interval over both benchmarks' repetitions.
Measured measured_ratio(const BenchResults& results, std::string_view slow, std::string_view fast);
/// f(median(name)) for a monotone f (increasing or decreasing), with the interval mapped through f.
Measured measured_median(const BenchResults& results, std::string_view name, double (*f)(double));

/// reproduced / not-reproduced / inconclusive from where the interval lies against `band`.
Verdict verdict_of(const Measured& m, Interval band);
/// The verdict of several figures read together: reproduced if all are, not-reproduced if any is, else
/// inconclusive.
Verdict all_of(std::initializer_list<Verdict> verdicts);

/// {"ratio" (or `name`), "ratio_ci95": [lo, hi] (null without enough repetitions), "band": [lo, hi] (null for
/// an unbounded side), "repetitions", "verdict"}.
nlohmann::json to_json(const Measured& m, Interval band, std::string_view name = "ratio");

}  // namespace affinterp::claims
