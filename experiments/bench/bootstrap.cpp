#include "experiments/bench/bootstrap.hpp"

#include "experiments/support/random.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace affinterp::bench {

namespace {

/// The q-quantile of sorted values, interpolating linearly between order statistics (Hyndman–Fan type 7).
double quantile(const std::vector<double>& sorted, double q) {
  const double position = q * static_cast<double>(sorted.size() - 1);
  const auto below = static_cast<std::size_t>(std::floor(position));
  const std::size_t above = std::min(below + 1, sorted.size() - 1);
  return sorted[below] + (position - static_cast<double>(below)) * (sorted[above] - sorted[below]);
}

std::size_t draw(Rng& rng, std::size_t n) {
  return static_cast<std::size_t>(rng.integer(0, static_cast<std::int64_t>(n) - 1));
}

/// Throws std::invalid_argument unless every run has the same number of samples, each run's samples the same
/// number of processes, and every process a repetition.
void check_levels(const std::vector<RunSamples>& runs) {
  if (runs.empty() || runs.front().empty()) throw std::invalid_argument("bootstrap of no sample");
  for (const RunSamples& samples : runs) {
    if (samples.size() != runs.front().size()) throw std::invalid_argument("bootstrap of runs with other samples");
    const std::size_t processes = samples.front().size();
    for (const ByProcess& sample : samples) {
      if (sample.size() != processes || processes == 0)
        throw std::invalid_argument("bootstrap of samples from different processes");
      for (const auto& process : sample)
        if (process.empty()) throw std::invalid_argument("bootstrap of an empty sample");
    }
  }
}

/// Appends to each sample of `resample` one resample of `run`: its processes drawn with replacement (the same
/// draw for every sample, whose benchmarks ran side by side in each process), then the repetitions within each.
void add_run_resample(Rng& rng, const RunSamples& run, std::vector<std::vector<double>>& resample) {
  const std::size_t processes = run.front().size();
  std::vector<std::size_t> chosen(processes);
  for (std::size_t p = 0; p < processes; ++p) chosen[p] = processes > 1 ? draw(rng, processes) : p;
  for (std::size_t s = 0; s < run.size(); ++s)
    for (const std::size_t p : chosen) {
      const std::vector<double>& process = run[s][p];
      for (std::size_t i = 0; i < process.size(); ++i) resample[s].push_back(process[draw(rng, process.size())]);
    }
}

}  // namespace

double median(std::span<const double> x) {
  if (x.empty()) throw std::invalid_argument("median of an empty sample");
  std::vector<double> sorted(x.begin(), x.end());
  std::sort(sorted.begin(), sorted.end());
  const std::size_t n = sorted.size();
  return n % 2 ? sorted[n / 2] : (sorted[n / 2 - 1] + sorted[n / 2]) / 2;
}

std::vector<double> pooled(const ByProcess& x) {
  std::vector<double> all;
  for (const auto& process : x) all.insert(all.end(), process.begin(), process.end());
  return all;
}

Interval bootstrap_interval(const RunSamples& samples, const Statistic& statistic, std::uint64_t seed, double level,
                            std::size_t resamples) {
  return hierarchical_interval({samples}, statistic, seed, level, resamples);
}

Interval hierarchical_interval(const std::vector<RunSamples>& runs, const Statistic& statistic, std::uint64_t seed,
                               double level, std::size_t resamples) {
  check_levels(runs);
  Rng rng(seed);
  std::vector<std::vector<double>> resample(runs.front().size());
  std::vector<std::size_t> drawn_runs(runs.size());
  std::vector<double> statistics(resamples);
  for (double& value : statistics) {
    for (auto& sample : resample) sample.clear();
    for (std::size_t k = 0; k < runs.size(); ++k) drawn_runs[k] = runs.size() > 1 ? draw(rng, runs.size()) : k;
    for (const std::size_t r : drawn_runs) add_run_resample(rng, runs[r], resample);
    value = statistic(resample);
  }
  std::sort(statistics.begin(), statistics.end());
  return {quantile(statistics, (1 - level) / 2), quantile(statistics, (1 + level) / 2)};
}

Interval ratio_of_medians_ci95(const ByProcess& slow, const ByProcess& fast, std::uint64_t seed) {
  return bootstrap_interval(
      {slow, fast}, [](const auto& s) { return median(s[0]) / median(s[1]); }, seed);
}

Interval median_ci95(const ByProcess& x, std::uint64_t seed) {
  return bootstrap_interval(
      {x}, [](const auto& s) { return median(s[0]); }, seed);
}

Placement placement(Interval ci, Interval band) {
  if (band.lo <= ci.lo && ci.hi <= band.hi) return Placement::inside;
  if (ci.hi < band.lo || band.hi < ci.lo) return Placement::outside;
  return Placement::straddles;
}

}  // namespace affinterp::bench
