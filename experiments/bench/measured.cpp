#include "experiments/bench/measured.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace affinterp::bench {

namespace {

const ByProcess& repetitions_of(const BenchResults& results, std::string_view name) {
  static const ByProcess none;
  const auto it = results.repetitions.find(name);
  return it == results.repetitions.end() ? none : it->second;
}

double median_of(const BenchResults& results, std::string_view name) {
  if (const auto value = results[name]) return *value;
  throw std::invalid_argument("benchmark " + std::string(name) + " did not run");
}

}  // namespace

Measured measured_ratio(const BenchResults& results, std::string_view slow, std::string_view fast) {
  const ByProcess& s = repetitions_of(results, slow);
  const ByProcess& f = repetitions_of(results, fast);
  Measured m{median_of(results, slow) / median_of(results, fast), std::nullopt,
             std::min(pooled(s).size(), pooled(f).size()), std::max<std::size_t>(1, s.size())};
  if (m.repetitions >= kMinRepetitions && s.size() == f.size()) m.ci95 = ratio_of_medians_ci95(s, f, kBootstrapSeed);
  return m;
}

Measured measured_median(const BenchResults& results, std::string_view name, double (*f)(double)) {
  const ByProcess& x = repetitions_of(results, name);
  Measured m{f(median_of(results, name)), std::nullopt, pooled(x).size(), std::max<std::size_t>(1, x.size())};
  if (m.repetitions >= kMinRepetitions) {
    const Interval ci = median_ci95(x, kBootstrapSeed);
    const double a = f(ci.lo), b = f(ci.hi);
    m.ci95 = Interval{std::min(a, b), std::max(a, b)};
  }
  return m;
}

}  // namespace affinterp::bench
