#include "experiments/claims/bootstrap.hpp"

#include "experiments/support/random.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace affinterp::claims {

namespace {

/// The q-quantile of sorted values, interpolating linearly between order statistics (Hyndman–Fan type 7).
double quantile(const std::vector<double>& sorted, double q) {
  const double position = q * static_cast<double>(sorted.size() - 1);
  const auto below = static_cast<std::size_t>(std::floor(position));
  const std::size_t above = std::min(below + 1, sorted.size() - 1);
  return sorted[below] + (position - static_cast<double>(below)) * (sorted[above] - sorted[below]);
}

}  // namespace

double median(std::span<const double> x) {
  if (x.empty()) throw std::invalid_argument("median of an empty sample");
  std::vector<double> sorted(x.begin(), x.end());
  std::sort(sorted.begin(), sorted.end());
  const std::size_t n = sorted.size();
  return n % 2 ? sorted[n / 2] : (sorted[n / 2 - 1] + sorted[n / 2]) / 2;
}

Interval bootstrap_interval(const std::vector<std::vector<double>>& samples,
                            const std::function<double(const std::vector<std::vector<double>>&)>& statistic,
                            std::uint64_t seed, double level, std::size_t resamples) {
  for (const auto& sample : samples)
    if (sample.empty()) throw std::invalid_argument("bootstrap of an empty sample");
  Rng rng(seed);
  std::vector<std::vector<double>> resample = samples;
  std::vector<double> statistics(resamples);
  for (double& value : statistics) {
    for (std::size_t s = 0; s < samples.size(); ++s)
      for (double& x : resample[s])
        x = samples[s][static_cast<std::size_t>(rng.integer(0, static_cast<std::int64_t>(samples[s].size()) - 1))];
    value = statistic(resample);
  }
  std::sort(statistics.begin(), statistics.end());
  return {quantile(statistics, (1 - level) / 2), quantile(statistics, (1 + level) / 2)};
}

Interval ratio_of_medians_ci95(const std::vector<double>& slow, const std::vector<double>& fast, std::uint64_t seed) {
  return bootstrap_interval(
      {slow, fast}, [](const auto& s) { return median(s[0]) / median(s[1]); }, seed);
}

Interval median_ci95(const std::vector<double>& x, std::uint64_t seed) {
  return bootstrap_interval(
      {x}, [](const auto& s) { return median(s[0]); }, seed);
}

Placement placement(Interval ci, Interval band) {
  if (band.lo <= ci.lo && ci.hi <= band.hi) return Placement::inside;
  if (ci.hi < band.lo || band.hi < ci.lo) return Placement::outside;
  return Placement::straddles;
}

}  // namespace affinterp::claims
