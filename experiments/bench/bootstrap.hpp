#pragma once
// Confidence intervals for measured speeds: the percentile bootstrap (Efron & Tibshirani, An Introduction
// to the Bootstrap, 1993, §13.3) over the repetitions of Google Benchmark runs, resampled by the levels the data
// was taken at (Davison & Hinkley, Bootstrap Methods and their Application, 1997, §3.8, "Hierarchical data"):
// the runs of one machine are drawn with replacement, then within each drawn run its whole processes, then
// within each drawn process its repetitions. Every sample (the benchmarks a figure compares, which ran side by
// side) takes the same draw of runs and of processes, so slow phases of a shared machine that last a whole
// process, and drifts that last a whole run, widen the interval. A level with one member is not drawn: one run
// of one process is the plain bootstrap, each sample resampled with replacement, independently of the others.
// Every resampling runs `resamples` times from a seeded source (random.hpp: the same interval on every
// platform for a seed); the interval runs from the (1 − level)/2 to the (1 + level)/2 quantile of the statistic
// over the resamples (linear interpolation between order statistics).
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

/// The samples of one run: per benchmark a figure reads, its repetitions by process.
using RunSamples = std::vector<ByProcess>;

/// A statistic of the samples, each sample's repetitions pooled (over its drawn processes and runs).
using Statistic = std::function<double(const std::vector<std::vector<double>>&)>;

/// The number of resamples of every interval, unless a caller asks for another.
inline constexpr std::size_t kResamples = 10000;

/// The percentile bootstrap interval of statistic(pooled samples) at `level` over one run. Every sample has the
/// same number of processes, each with at least one repetition. Throws std::invalid_argument otherwise.
Interval bootstrap_interval(const RunSamples& samples, const Statistic& statistic, std::uint64_t seed,
                            double level = 0.95, std::size_t resamples = kResamples);

/// The hierarchical percentile bootstrap interval over several runs of one machine: runs, then processes within
/// each drawn run, then repetitions within each drawn process; the statistic sees each sample's repetitions
/// pooled over everything drawn. Every run has the same samples (count), each run's samples the same number of
/// processes. With one run it is bootstrap_interval, draw for draw. Throws std::invalid_argument otherwise.
Interval hierarchical_interval(const std::vector<RunSamples>& runs, const Statistic& statistic, std::uint64_t seed,
                               double level = 0.95, std::size_t resamples = kResamples);

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
