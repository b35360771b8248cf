#pragma once
// Confidence intervals for measured speeds: the percentile bootstrap (Efron & Tibshirani, An Introduction
// to the Bootstrap, 1993, §13.3) over the repetitions of Google Benchmark runs. When a benchmark ran in several
// whole processes, the resampling has two stages (Davison & Hinkley, Bootstrap Methods and their Application,
// 1997, §3.8, "Hierarchical data"): the processes are drawn with replacement, the same draw for every sample
// (their benchmarks ran side by side in each process), then the repetitions within each drawn process; so slow
// phases of a shared machine that last a whole process widen the interval. With one process the first stage is
// skipped: the plain bootstrap, each sample resampled with replacement, independently of the others. Every
// resampling runs `resamples` times from a seeded source (the same interval on every platform for a seed); the
// interval runs from the (1 − level)/2 to the (1 + level)/2 quantile of the statistic over the resamples (linear
// interpolation between order statistics).
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace affinterp::bench {

struct Interval {
  double lo = 0, hi = 0;
};

/// The median (mean of the two middle values for an even count). Requires a non-empty sample.
double median(std::span<const double> x);

/// One benchmark's repetitions, grouped by the process that ran them (in process order).
using ByProcess = std::vector<std::vector<double>>;

/// Every repetition of `x`, process after process.
std::vector<double> pooled(const ByProcess& x);

/// The percentile bootstrap interval of statistic(pooled samples) at `level`. Every sample has the same number
/// of processes, each with at least one repetition; the statistic sees each sample's resampled repetitions
/// pooled over its processes.
/// Throws std::invalid_argument otherwise.
Interval bootstrap_interval(const std::vector<ByProcess>& samples,
                            const std::function<double(const std::vector<std::vector<double>>&)>& statistic,
                            std::uint64_t seed, double level = 0.95, std::size_t resamples = 10000);

/// The 95% bootstrap interval of median(slow) / median(fast): a speed-up from repeated timings.
Interval ratio_of_medians_ci95(const ByProcess& slow, const ByProcess& fast, std::uint64_t seed);

/// The 95% bootstrap interval of median(x).
Interval median_ci95(const ByProcess& x, std::uint64_t seed);

/// Where a confidence interval lies against the band of values a claim allows.
enum class Placement {
  inside,     ///< the whole interval lies in the band
  outside,    ///< the interval and the band do not meet
  straddles,  ///< the interval crosses an edge of the band
};

Placement placement(Interval ci, Interval band);

}  // namespace affinterp::bench
