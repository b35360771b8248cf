#pragma once
// Confidence intervals for measured speeds: the percentile bootstrap (Efron & Tibshirani, An Introduction
// to the Bootstrap, 1993, §13.3) over the repetitions of a Google Benchmark run. Each sample is resampled
// with replacement, independently of the others, `resamples` times from a seeded source (the same interval
// on every platform for a seed); the interval runs from the (1 − level)/2 to the (1 + level)/2 quantile of
// the statistic over the resamples (linear interpolation between order statistics).
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace affinterp::claims {

struct Interval {
  double lo = 0, hi = 0;
};

/// The median (mean of the two middle values for an even count). Requires a non-empty sample.
double median(std::span<const double> x);

/// The percentile bootstrap interval of statistic(samples) at `level`.
Interval bootstrap_interval(const std::vector<std::vector<double>>& samples,
                            const std::function<double(const std::vector<std::vector<double>>&)>& statistic,
                            std::uint64_t seed, double level = 0.95, std::size_t resamples = 10000);

/// The 95% percentile bootstrap interval of median(slow) / median(fast): a speed-up from repeated timings.
Interval ratio_of_medians_ci95(const std::vector<double>& slow, const std::vector<double>& fast, std::uint64_t seed);

/// The 95% percentile bootstrap interval of median(x).
Interval median_ci95(const std::vector<double>& x, std::uint64_t seed);

/// Where a confidence interval lies against the band of values a claim allows.
enum class Placement {
  inside,     ///< the whole interval lies in the band
  outside,    ///< the interval and the band do not meet
  straddles,  ///< the interval crosses an edge of the band
};

Placement placement(Interval ci, Interval band);

}  // namespace affinterp::claims
