#pragma once
// What the measured speed claims of thesis §3.4 (Figs 3.1–3.3) share: reading the benchmark JSON that
// experiments/reproduce.sh writes before the claims run and the history of recorded runs (bench/history.hpp),
// the verdict on each run from its figures' bootstrap intervals against the bands the wording allows and on the
// runs together (speed_verdict.hpp), the per-run table and plot, and the bar chart of the latest run.
#include "experiments/bench/history.hpp"
#include "experiments/claims/context.hpp"
#include "experiments/claims/outcome.hpp"
#include "experiments/claims/speed_verdict.hpp"

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
/// ratio_text of the figure `key` of `run`, or "not measured".
std::string ratio_text(const bench::RecordedRun& run, const std::string& key);

/// x with `digits` digits after the point.
std::string fixed(double x, int digits = 2);

/// The missing benchmarks among `names`, as "a, b (error message)"; empty when all ran.
std::string missing(const BenchResults& results, std::initializer_list<std::string_view> names);

/// The results of bench_<name>.json, or the inconclusive outcome saying why they cannot be used: no
/// benchmark folder, an absent or unreadable file, or one of `needed` missing from it (`hint` appended).
std::variant<BenchResults, Outcome> load(const RunSettings& ctx, const std::string& bench, const std::string& counter,
                                         const std::string& method, std::initializer_list<std::string_view> needed,
                                         const std::string& hint = "");

/// The recorded runs of `program` (bench::runs_of: the history, and the benchmark files when no entry records
/// them and they hold `needed`), oldest first, or the inconclusive outcome saying why there are none (as load).
std::variant<std::vector<bench::RecordedRun>, Outcome> load_runs(const RunSettings& ctx, const bench::Program& program,
                                                                 const std::string& method,
                                                                 std::initializer_list<std::string_view> needed,
                                                                 const std::string& hint = "");

/// One figure a verdict reads from every run (bench/speed_figures.hpp key), the band it must lie in, and its name
/// in the table.
struct Reading {
  std::string key;
  Interval band;
  std::string label;
};

/// Each machine decided on `readings` together (all_of of each reading's pooled interval against its band,
/// bench/pooled.hpp; a reading no run measured is inconclusive), the machines together (across_machines), and
/// each run alone by the same rule, shown beside its machine.
struct RunsDecision {
  Verdict verdict = Verdict::inconclusive;
  std::vector<Verdict> per_run;
  std::vector<Verdict> per_machine;
  /// {"title", "columns", "rows"}: a row per machine (its key, its runs, each reading's pooled figure with its
  /// interval, verdict), then a row per run (machine, date, each reading with its own interval, verdict), for
  /// evidence.details.tables.
  nlohmann::json machine_table, run_table;
  /// [{"machine", "runs": [ids], "figures": {label: to_json(pooled figure, band)}, "verdict"}].
  nlohmann::json machines;
  /// [{"run", "machine_key", "recorded", "date", "machine", "note", "figures": {label: to_json(figure, band)},
  /// "verdict"}].
  nlohmann::json runs;
};
RunsDecision decide_runs(const std::vector<bench::RecordedRun>& runs, const std::vector<Reading>& readings,
                         const std::string& title);

/// "<yyyy-mm-dd> AMD EPYC, avx2": a run's date and its machine (bench::machine_label) without trademark signs.
std::string run_label(const bench::RecordedRun& run);

/// "reproduced over 2 machines (AMD EPYC, avx2, g++ 12.2.0, 3 runs: reproduced; …)": what the machines together
/// say, naming each machine's verdict on its pooled runs.
std::string machines_summary(const std::vector<bench::RecordedRun>& runs, const RunsDecision& decision);

/// Each run's readings with their intervals against their bands (plots/runs_against_band.hpp), one panel per
/// reading; returns the figure's files for the report.
std::vector<std::string> runs_chart(const RunSettings& ctx, const std::vector<bench::RecordedRun>& runs,
                                    const std::vector<Reading>& readings, const std::string& stem,
                                    const std::string& title);

/// The part every "about N× faster" outcome shares: the ratio key (bench/speed_figures.hpp) against
/// about_band(paper), plus `more` readings, decided per machine and across machines (decide_runs), and the
/// evidence fields (measurements: the latest run's ratio, ratio_ci95, band, repetitions, processes, machine,
/// "machines", "runs", "across_machines"; details: paper, rule, the pooled bootstrap's settings, the machine and
/// run tables); callers add the summary and their own details.
Outcome about_ratio_outcome(const std::vector<bench::RecordedRun>& runs, const std::string& key, double paper,
                            const std::string& method, std::uint64_t sample_size,
                            const std::vector<Reading>& more = {});

/// A bar chart of the benchmarks whose names start with `prefix` (all of them, in name order), with
/// the ones the thesis compares highlighted; returns the figure's file for the report.
std::vector<std::string> bar_chart(const RunSettings& ctx, const BenchResults& results, std::string_view prefix,
                                   std::initializer_list<std::string_view> thesis_names, const std::string& stem,
                                   const std::string& title, const std::string& unit, double scale);

}  // namespace affinterp::claims::sym3
