#pragma once
// A measured speed figure with its uncertainty: the figure (a ratio of medians, or one median) from the
// repetitions of Google Benchmark runs, and its 95% bootstrap interval over repetitions and whole processes
// (bootstrap.hpp). experiments/claims/speed_verdict.hpp decides claims from it.
#include "experiments/bench/bench_results.hpp"
#include "experiments/bench/bootstrap.hpp"

#include <cstdint>
#include <limits>
#include <optional>
#include <string_view>

namespace affinterp::bench {

/// The repetitions a benchmark needs for an interval (the benchmarks run this many per process,
/// experiments/apps/bench/bench_context.hpp).
inline constexpr std::size_t kMinRepetitions = 10;
/// The seed of every bootstrap of a measured figure (fixed: the same file gives the same interval).
inline constexpr std::uint64_t kBootstrapSeed = 2015;
inline constexpr double kUnbounded = std::numeric_limits<double>::infinity();

struct Measured {
  double value = 0;              ///< the figure from the medians
  std::optional<Interval> ci95;  ///< nullopt with fewer than kMinRepetitions repetitions
  std::size_t repetitions = 0;   ///< the fewest repetitions among the benchmarks it reads (over all processes)
  std::size_t processes = 1;     ///< the whole processes they ran in
};

/// median(slow) / median(fast), a speed-up, with the bootstrap interval over both benchmarks' repetitions and
/// processes. Throws std::invalid_argument when one did not run.
Measured measured_ratio(const BenchResults& results, std::string_view slow, std::string_view fast);
/// f(median(name)) for a monotone f (increasing or decreasing), with the interval mapped through f.
Measured measured_median(const BenchResults& results, std::string_view name, double (*f)(double));

}  // namespace affinterp::bench
