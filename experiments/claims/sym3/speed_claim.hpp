#pragma once
// What the measured speed claims of thesis §3.4 (Figs 3.1–3.3) share: reading the benchmark JSON that
// experiments/reproduce.sh writes before the claims run, the verdict on an "about r× faster", and the bar chart.
#include "experiments/claims/bench_results.hpp"
#include "experiments/claims/context.hpp"
#include "experiments/claims/outcome.hpp"

#include <cstdint>
#include <initializer_list>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace affinterp::claims::sym3 {

/// "About r×" is read as: the measured ratio lies within a factor kAboutFactor of r (and above 1, so
/// the claimed direction holds). The thesis measured on an Intel Core i7 1.9 GHz with MSVC 2010 /O2
/// and a 2013 Eigen; a different CPU generation, compiler and Eigen version move such ratios by tens
/// of percent, while a factor of 1.5 still separates e.g. 3.2× from 2× or 5×.
inline constexpr double kAboutFactor = 1.5;

/// x with `digits` digits after the point.
std::string fixed(double x, int digits = 2);

/// The missing benchmarks among `names`, as "a, b (error message)"; empty when all ran.
std::string missing(const BenchResults& results, std::initializer_list<std::string_view> names);

/// The results of bench_<name>.json, or the inconclusive outcome saying why they cannot be used: no
/// benchmark folder, an absent or unreadable file, or one of `needed` missing from it (`hint` appended).
std::variant<BenchResults, Outcome> load(const RunSettings& ctx, const std::string& bench, const std::string& counter,
                                         const std::string& method, std::initializer_list<std::string_view> needed,
                                         const std::string& hint = "");

/// The part every "about N× faster" outcome shares: the verdict for time(slow) / time(fast) against the
/// thesis's `paper` ratio, and the evidence fields; callers add the summary and their own details.
Outcome about_ratio_outcome(const BenchResults& results, std::string_view slow, std::string_view fast, double paper,
                            const std::string& method, std::uint64_t sample_size);

/// A bar chart of the benchmarks whose names start with `prefix` (all of them, in name order), with
/// the ones the thesis compares highlighted; returns the figure's file for the report.
std::vector<std::string> bar_chart(const RunSettings& ctx, const BenchResults& results, std::string_view prefix,
                                   std::initializer_list<std::string_view> thesis_names, const std::string& stem,
                                   const std::string& title, const std::string& unit, double scale);

}  // namespace affinterp::claims::sym3
