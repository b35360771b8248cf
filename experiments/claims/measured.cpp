#include "experiments/claims/measured.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace affinterp::claims {

namespace {

const std::vector<double>& repetitions_of(const BenchResults& results, std::string_view name) {
  static const std::vector<double> none;
  const auto it = results.repetitions.find(name);
  return it == results.repetitions.end() ? none : it->second;
}

double median_of(const BenchResults& results, std::string_view name) {
  if (const auto value = results[name]) return *value;
  throw std::invalid_argument("benchmark " + std::string(name) + " did not run");
}

nlohmann::json bound(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(); }

}  // namespace

Measured measured_ratio(const BenchResults& results, std::string_view slow, std::string_view fast) {
  const auto& s = repetitions_of(results, slow);
  const auto& f = repetitions_of(results, fast);
  Measured m{median_of(results, slow) / median_of(results, fast), std::nullopt, std::min(s.size(), f.size())};
  if (m.repetitions >= kMinRepetitions) m.ci95 = ratio_of_medians_ci95(s, f, kBootstrapSeed);
  return m;
}

Measured measured_median(const BenchResults& results, std::string_view name, double (*f)(double)) {
  const auto& x = repetitions_of(results, name);
  Measured m{f(median_of(results, name)), std::nullopt, x.size()};
  if (m.repetitions >= kMinRepetitions) {
    const Interval ci = median_ci95(x, kBootstrapSeed);
    const double a = f(ci.lo), b = f(ci.hi);
    m.ci95 = Interval{std::min(a, b), std::max(a, b)};
  }
  return m;
}

Verdict verdict_of(const Measured& m, Interval band) {
  if (!m.ci95) return Verdict::inconclusive;
  switch (placement(*m.ci95, band)) {
    case Placement::inside:
      return Verdict::reproduced;
    case Placement::outside:
      return Verdict::not_reproduced;
    case Placement::straddles:
      return Verdict::inconclusive;
  }
  return Verdict::inconclusive;
}

Verdict all_of(std::initializer_list<Verdict> verdicts) {
  if (std::ranges::any_of(verdicts, [](Verdict v) { return v == Verdict::not_reproduced; }))
    return Verdict::not_reproduced;
  if (std::ranges::all_of(verdicts, [](Verdict v) { return v == Verdict::reproduced; })) return Verdict::reproduced;
  return Verdict::inconclusive;
}

nlohmann::json to_json(const Measured& m, Interval band, std::string_view name) {
  const std::string key(name);
  return {
      {key, m.value},
      {key + "_ci95", m.ci95 ? nlohmann::json{m.ci95->lo, m.ci95->hi} : nlohmann::json()},
      {"band", {bound(band.lo), bound(band.hi)}},
      {"repetitions", m.repetitions},
      {"verdict", to_string(verdict_of(m, band))},
  };
}

}  // namespace affinterp::claims
