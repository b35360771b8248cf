#include "experiments/claims/speed_verdict.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace affinterp::claims {

namespace {

nlohmann::json bound(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(); }

}  // namespace

Verdict verdict_of(const std::optional<Interval>& interval, Interval band) {
  if (!interval) return Verdict::inconclusive;
  switch (bench::placement(*interval, band)) {
    case bench::Placement::inside:
      return Verdict::reproduced;
    case bench::Placement::outside:
      return Verdict::not_reproduced;
    case bench::Placement::straddles:
      return Verdict::inconclusive;
  }
  return Verdict::inconclusive;
}

Verdict all_of(std::initializer_list<Verdict> verdicts) { return all_of(std::span(verdicts.begin(), verdicts.size())); }

Verdict all_of(std::span<const Verdict> verdicts) {
  if (std::ranges::any_of(verdicts, [](Verdict v) { return v == Verdict::not_reproduced; }))
    return Verdict::not_reproduced;
  if (std::ranges::all_of(verdicts, [](Verdict v) { return v == Verdict::reproduced; })) return Verdict::reproduced;
  return Verdict::inconclusive;
}

Verdict across_machines(std::span<const Verdict> machines) {
  const auto any = [&](Verdict v) { return std::ranges::find(machines, v) != machines.end(); };
  if (any(Verdict::reproduced) && any(Verdict::not_reproduced)) return Verdict::machine_dependent;
  if (!machines.empty() && std::ranges::all_of(machines, [&](Verdict v) { return v == machines.front(); }))
    return machines.front();
  return Verdict::inconclusive;
}

nlohmann::json ci95_json(const Measured& m) {
  return m.ci95 ? nlohmann::json{m.ci95->lo, m.ci95->hi} : nlohmann::json();
}

nlohmann::json to_json(const Measured& m, Interval band, std::string_view name) {
  const std::string key(name);
  return {
      {key, m.value},
      {key + "_ci95", ci95_json(m)},
      {"band", {bound(band.lo), bound(band.hi)}},
      {"repetitions", m.repetitions},
      {"processes", m.processes},
      {"verdict", to_string(verdict_of(m, band))},
  };
}

}  // namespace affinterp::claims
