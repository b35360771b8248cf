#pragma once
// The verdict on a measured figure and on the machines that measured it. One interval: reproduced when it (a
// figure's 95% bootstrap interval, experiments/bench/measured.hpp, or one machine's pooled interval,
// experiments/bench/pooled.hpp) lies in the band of values the claim's wording allows, not-reproduced when it lies
// outside, inconclusive when it straddles an edge or when fewer than kMinRepetitions repetitions were recorded.
// Several machines: across_machines.
#include "experiments/bench/measured.hpp"
#include "experiments/claims/verdict.hpp"

#include <nlohmann/json.hpp>

#include <initializer_list>
#include <optional>
#include <span>
#include <string_view>

namespace affinterp::claims {

using bench::BenchResults;
using bench::Interval;
using bench::kUnbounded;
using bench::Measured;
using bench::measured_median;
using bench::measured_ratio;

/// reproduced / not-reproduced / inconclusive from where `interval` lies against `band` (inconclusive without one).
Verdict verdict_of(const std::optional<Interval>& interval, Interval band);
/// verdict_of the figure's 95% interval.
inline Verdict verdict_of(const Measured& m, Interval band) { return verdict_of(m.ci95, band); }
/// The verdict of several figures read together: reproduced if all are, not-reproduced if any is, else
/// inconclusive.
Verdict all_of(std::initializer_list<Verdict> verdicts);
Verdict all_of(std::span<const Verdict> verdicts);

/// The rule across machines, as the report states it (kAcrossMachinesRule): each machine (one machine_key:
/// CPU model, widest vector extension, compiler, build flags) decided on its runs pooled; the verdict every machine
/// gives when they all give the same; machine-dependent when one machine is reproduced and another not-reproduced;
/// otherwise (the machines that decide agree, some do not decide) inconclusive, as is an empty history.
Verdict across_machines(std::span<const Verdict> machines);
inline constexpr std::string_view kAcrossMachinesRule =
    "the recorded runs (reports/bench/history/, one entry per run of the benchmarks) are grouped by machine (same "
    "CPU model, widest vector extension among its flags, compiler and version, and build flags but warnings: another "
    "build is another machine); each machine is decided by the "
    "interval rule on its pooled interval: the same statistic over the repetitions of all its runs, its 95% "
    "percentile interval from a hierarchical bootstrap that draws the machine's runs with replacement, then each "
    "drawn run's processes, then each drawn process's repetitions (10,000 resamples, seed 2015; a machine of one "
    "run keeps that run's interval); the claim is reproduced (not-reproduced) iff every machine is, "
    "machine-dependent iff one machine is reproduced and another not-reproduced, else inconclusive (some machines "
    "undecided, none contradicting another)";

/// The figure's 95% interval as [lo, hi], null without enough repetitions.
nlohmann::json ci95_json(const Measured& m);

/// {"ratio" (or `name`), "ratio_ci95": [lo, hi] (null without enough repetitions), "band": [lo, hi] (null for
/// an unbounded side), "repetitions", "processes", "verdict"}.
nlohmann::json to_json(const Measured& m, Interval band, std::string_view name = "ratio");

}  // namespace affinterp::claims
