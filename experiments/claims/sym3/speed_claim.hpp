#pragma once
// What the measured speed claims of thesis §3.4 (Figs 3.1–3.3) share: reading the benchmark JSON that
// experiments/reproduce.sh writes before the claims run, the verdict on an "about r× faster" from the ratio's
// bootstrap interval against the band the wording allows (measured.hpp), and the bar chart.
#include "experiments/claims/bench_results.hpp"
#include "experiments/claims/context.hpp"
#include "experiments/claims/measured.hpp"
#include "experiments/claims/outcome.hpp"

#include <cstdint>
#include <initializer_list>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace affinterp::claims::sym3 {

/// "About r×" allows the ratios within a factor kAboutFactor of r and above 1 (the claimed direction):
/// the band [max(1, r / 1.5), 1.5 r]. The thesis measured on an Intel Core i7 1.9 GHz with MSVC 2010 /O2
/// and a 2013 Eigen; a different CPU generation, compiler and Eigen version move such ratios by tens
/// of percent, while a factor of 1.5 still separates e.g. 3.2× from 2× or 5×.
inline constexpr double kAboutFactor = 1.5;

/// The band of ratios "about r×" allows.
Interval about_band(double paper);

/// "thesis: about 3.2×, which allows [2.13, 4.80]".
std::string band_text(double paper);

/// "2.10× (95% CI 2.01–2.18)", or "2.10× (no interval: n repetitions)".
std::string ratio_text(const Measured& m);

/// x with `digits` digits after the point.
std::string fixed(double x, int digits = 2);

/// The missing benchmarks among `names`, as "a, b (error message)"; empty when all ran.
std::string missing(const BenchResults& results, std::initializer_list<std::string_view> names);

/// The results of bench_<name>.json, or the inconclusive outcome saying why they cannot be used: no
/// benchmark folder, an absent or unreadable file, or one of `needed` missing from it (`hint` appended).
std::variant<BenchResults, Outcome> load(const RunSettings& ctx, const std::string& bench, const std::string& counter,
                                         const std::string& method, std::initializer_list<std::string_view> needed,
                                         const std::string& hint = "");

/// The part every "about N× faster" outcome shares: the verdict for time(slow) / time(fast) (medians of the
/// repetitions, with the bootstrap interval) against about_band(paper), and the evidence fields
/// (measurements: ratio, ratio_ci95, band, repetitions); callers add the summary and their own details.
Outcome about_ratio_outcome(const BenchResults& results, std::string_view slow, std::string_view fast, double paper,
                            const std::string& method, std::uint64_t sample_size);

/// A bar chart of the benchmarks whose names start with `prefix` (all of them, in name order), with
/// the ones the thesis compares highlighted; returns the figure's file for the report.
std::vector<std::string> bar_chart(const RunSettings& ctx, const BenchResults& results, std::string_view prefix,
                                   std::initializer_list<std::string_view> thesis_names, const std::string& stem,
                                   const std::string& title, const std::string& unit, double scale);

}  // namespace affinterp::claims::sym3
