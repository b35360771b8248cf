#pragma once
// Shared set-up of the Google Benchmark executables: the machine in the JSON context, and a counter
// that states the time per processed item explicitly.
#include <benchmark/benchmark.h>

#include <cstdint>

namespace affinterp::bench {

/// Repetitions of every benchmark a verdict reads (the speed claims and the engine's targets): their 95%
/// bootstrap intervals need at least 10 (experiments/bench/measured.hpp). Set in code, so that it overrides
/// --benchmark_repetitions; the benchmarks display only the aggregates on the console but keep every
/// repetition in the JSON file (DisplayAggregatesOnly).
inline constexpr int kRepetitions = 10;

/// Adds the CPU model and feature flags, compiler, flags and library versions to the benchmark JSON's "context", so
/// that speed verdicts can name the machine that measured them.
void add_machine_context();

/// A counter whose value is the CPU time in nanoseconds per item, for `items` items per iteration:
/// (CPU seconds) / (items · iterations · 10⁻⁹), through Google Benchmark's inverted iteration rate.
inline benchmark::Counter ns_per_item(std::int64_t items) {
  return benchmark::Counter(static_cast<double>(items) * 1e-9,
                            benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

/// Runs the registered benchmarks with the command line's options (after add_machine_context()).
int run_benchmarks(int argc, char** argv);

}  // namespace affinterp::bench
