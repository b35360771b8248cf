#include "experiments/claims/sym3/speed_claim.hpp"

#include "experiments/bench/machine_label.hpp"
#include "experiments/bench/pooled.hpp"
#include "plots/figure.hpp"
#include "plots/runs_against_band.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>

namespace affinterp::claims::sym3 {

namespace {

constexpr std::string_view kAboutReading =
    "'about r×' allows the ratios in the band [max(1, r / 1.5), 1.5 r]: within a factor 1.5 of r and above 1 (the "
    "claimed direction). The thesis measured on a 2013 Intel Core i7 with MSVC 2010 /O2 and an older Eigen; CPU "
    "generation, compiler and library version move such ratios by tens of percent, while a factor 1.5 still tells "
    "3.2× from 2× or 5×";

constexpr std::string_view kIntervalRule =
    "ratio = median(time of slow) / median(time of fast) over the benchmark's repetitions (at least 10); "
    "ratio_ci95 = the 95% percentile bootstrap interval (10,000 resamples, seed 2015; with one process each "
    "benchmark's repetitions are resampled with replacement, independently; experiments/bench/bootstrap.hpp). "
    "Reproduced iff ratio_ci95 lies "
    "in the band, not-reproduced iff it lies outside it, inconclusive iff it straddles an edge (or fewer than 10 "
    "repetitions were recorded). Each benchmark program runs in several whole processes, interleaved with the "
    "other programs (A B A B ...; experiments/reproduce.sh): the bootstrap then draws the processes first and the "
    "repetitions within them second (experiments/bench/bootstrap.hpp), so the interval covers the drift between "
    "processes on a shared machine as well as the spread within one";

constexpr std::string_view kPooling =
    "hierarchical percentile bootstrap over one machine's runs (runs, then processes, then repetitions), "
    "experiments/bench/pooled.hpp and experiments/bench/bootstrap.hpp";

constexpr std::string_view kPaperMachine =
    "Intel Core i7 1.9 GHz, 4 GB RAM, Windows 8 (64 bit), Visual Studio 2010 /O2 (thesis §3.4)";

Outcome inconclusive(std::string summary, const std::string& method) {
  Outcome outcome;
  outcome.verdict = Verdict::inconclusive;
  outcome.summary = std::move(summary);
  outcome.evidence.method = method;
  return outcome;
}

/// The widest vector extension among a run's CPU flags, or that they were not recorded.
std::string vector_isa(const nlohmann::json& machine) {
  const nlohmann::json flags = machine.value("cpu_flags", nlohmann::json());
  return flags.is_string() ? bench::widest_vector_isa(flags.get<std::string>()) : "CPU flags not recorded";
}

std::string text_of(const nlohmann::json& value) {
  return value.is_string() ? value.get<std::string>() : value.is_null() ? "?" : value.dump();
}

/// "Intel Xeon, 2 cores, avx512f; g++ 12.2.0 -O3 -DNDEBUG -Wall -Wextra -march=native".
std::string machine_text(const nlohmann::json& machine) {
  std::string flags = text_of(machine.value("flags", nlohmann::json()));
  flags.erase(0, flags.find_first_not_of(' '));
  return text_of(machine.value("cpu", nlohmann::json())) + ", " + text_of(machine.value("cores", nlohmann::json())) +
         " cores, " + vector_isa(machine) + "; " + text_of(machine.value("compiler", nlohmann::json())) + " " + flags;
}

}  // namespace

Interval about_band(double paper) { return {std::max(1.0, paper / kAboutFactor), paper * kAboutFactor}; }

std::string band_text(double paper) {
  const Interval band = about_band(paper);
  return "thesis: about " + fixed(paper, 1) + "×, which allows [" + fixed(band.lo) + ", " + fixed(band.hi) + "]";
}

std::string ratio_text(const Measured& m) {
  if (!m.ci95) return fixed(m.value) + "× (no interval: " + std::to_string(m.repetitions) + " repetitions)";
  return fixed(m.value) + "× (95% CI " + fixed(m.ci95->lo) + "–" + fixed(m.ci95->hi) + ")";
}

std::string ratio_text(const bench::RecordedRun& run, const std::string& key) {
  const auto figure = run.figures.find(key);
  return figure == run.figures.end() ? "not measured" : ratio_text(figure->second.measured);
}

std::string fixed(double x, int digits) {
  std::ostringstream out;
  out.precision(digits);
  out << std::fixed << x;
  return out.str();
}

std::string missing(const BenchResults& results, std::initializer_list<std::string_view> names) {
  std::string list;
  for (auto name : names) {
    if (results[name]) continue;
    if (!list.empty()) list += ", ";
    list += name;
    if (const auto error = results.errors.find(name); error != results.errors.end()) list += " (" + error->second + ")";
  }
  return list;
}

std::variant<BenchResults, Outcome> load(const RunSettings& ctx, const std::string& bench, const std::string& counter,
                                         const std::string& method, std::initializer_list<std::string_view> needed,
                                         const std::string& hint) {
  const std::string run = "run build/bin/" + bench + " --benchmark_out=reports/bench/" + bench +
                          ".json --benchmark_out_format=json (experiments/reproduce.sh does)";
  if (ctx.bench_dir.empty()) return inconclusive("no benchmark folder given: " + run, method);
  std::optional<BenchResults> results;
  try {
    results = bench::read_bench_results(ctx.bench_dir / (bench + ".json"), counter);
  } catch (const std::runtime_error& e) {
    return inconclusive(std::string("unreadable benchmark output: ") + e.what() + "; " + run, method);
  }
  if (!results) return inconclusive((ctx.bench_dir / (bench + ".json")).string() + " is absent: " + run, method);
  if (auto absent = missing(*results, needed); !absent.empty())
    return inconclusive("benchmarks missing from " + bench + ".json: " + absent + hint, method);
  return *results;
}

std::variant<std::vector<bench::RecordedRun>, Outcome> load_runs(const RunSettings& ctx, const bench::Program& program,
                                                                 const std::string& method,
                                                                 std::initializer_list<std::string_view> needed,
                                                                 const std::string& hint) {
  const std::string name(program.name);
  auto latest = load(ctx, name, std::string(program.counter), method, needed, hint);
  if (ctx.bench_dir.empty()) return std::get<Outcome>(latest);
  std::vector<bench::RecordedRun> runs;
  try {
    runs = bench::runs_of(ctx.bench_dir);
  } catch (const std::runtime_error& e) {
    return inconclusive(std::string("unreadable benchmark output: ") + e.what(), method);
  }
  // A run counts when it ran the program; the benchmark files not recorded yet only when they hold `needed`.
  std::erase_if(runs, [&](const bench::RecordedRun& run) {
    return !run.programs.contains(name) || (!run.recorded && std::holds_alternative<Outcome>(latest));
  });
  if (runs.empty()) {
    if (auto* outcome = std::get_if<Outcome>(&latest)) return *outcome;
    return inconclusive("no recorded run of " + name + " (reports/bench/history/)", method);
  }
  return runs;
}

std::string run_label(const bench::RecordedRun& run) {
  std::string cpu = bench::machine_label(run.machine);
  for (const char* noise : {"(R)", "(TM)", " Processor", " CPU"})
    for (std::size_t at; (at = cpu.find(noise)) != std::string::npos;) cpu.erase(at, std::string_view(noise).size());
  return run.date.substr(0, 10) + " " + cpu;
}

namespace {

/// "2.10 [2.01, 2.18]: reproduced": a figure, its interval and its verdict against `band`, for a table's cell.
std::string cell_of(const Measured& m, Interval band) {
  return fixed(m.value) + (m.ci95 ? " [" + fixed(m.ci95->lo) + ", " + fixed(m.ci95->hi) + "]" : "") + ": " +
         std::string(to_string(verdict_of(m, band)));
}

/// The readings' figures of one run or one machine (each nullopt where not measured) decided together: their
/// cells, their JSON (to_json against the band) and all_of their verdicts (not measured: inconclusive).
struct ReadingsDecision {
  std::vector<std::string> cells;
  nlohmann::json figures = nlohmann::json::object();
  Verdict verdict = Verdict::reproduced;
};
ReadingsDecision decide_readings(const std::vector<Reading>& readings,
                                 const std::vector<std::optional<Measured>>& figures) {
  ReadingsDecision decision;
  for (std::size_t i = 0; i < readings.size(); ++i) {
    const Reading& reading = readings[i];
    if (!figures[i]) {
      decision.verdict = all_of({decision.verdict, Verdict::inconclusive});
      decision.cells.push_back("not measured");
      continue;
    }
    decision.verdict = all_of({decision.verdict, verdict_of(*figures[i], reading.band)});
    decision.figures[reading.label] = to_json(*figures[i], reading.band, "value");
    decision.cells.push_back(cell_of(*figures[i], reading.band));
  }
  return decision;
}

nlohmann::json table(const std::string& title, nlohmann::json columns, const std::vector<Reading>& readings) {
  for (const Reading& reading : readings) columns.push_back(reading.label + " (95% CI)");
  columns.push_back("verdict");
  return {{"title", title}, {"columns", std::move(columns)}, {"rows", nlohmann::json::array()}};
}

/// One run decided alone by the interval rule: its row in the run table and its entry in "runs".
void add_run(RunsDecision& decision, const bench::RecordedRun& run, const std::vector<Reading>& readings) {
  std::vector<std::optional<Measured>> figures;
  std::size_t processes = 0;
  for (const Reading& reading : readings) {
    const auto figure = run.figures.find(reading.key);
    figures.push_back(figure == run.figures.end() ? std::nullopt : std::optional(figure->second.measured));
    if (figures.back()) processes = std::max(processes, figures.back()->processes);
  }
  const ReadingsDecision decided = decide_readings(readings, figures);
  nlohmann::json row = {run.id + (run.recorded ? "" : " (not recorded yet)"), machine_text(run.machine), processes};
  for (const std::string& cell : decided.cells) row.push_back(cell);
  row.push_back(to_string(decided.verdict));
  decision.run_table["rows"].push_back(row);
  decision.per_run.push_back(decided.verdict);
  decision.runs.push_back({{"run", run.id},
                           {"machine_key", bench::machine_key(run.machine)},
                           {"recorded", run.recorded},
                           {"date", run.date},
                           {"machine", run.machine},
                           {"note", run.note},
                           {"figures", decided.figures},
                           {"verdict", to_string(decided.verdict)}});
}

/// One machine decided on its runs pooled (bench::pooled_figure): its row in the machine table and its entry in
/// "machines".
void add_machine(RunsDecision& decision, const bench::MachineRuns& machine, const std::vector<Reading>& readings) {
  std::vector<std::optional<Measured>> figures;
  for (const Reading& reading : readings) figures.push_back(bench::pooled_figure(machine, reading.key));
  const ReadingsDecision decided = decide_readings(readings, figures);
  nlohmann::json ids = nlohmann::json::array();
  for (const bench::RecordedRun* run : machine.runs) ids.push_back(run->id);
  nlohmann::json row = {machine.key, std::to_string(machine.runs.size()) + " (" +
                                         machine.runs.front()->date.substr(0, 10) + " to " +
                                         machine.runs.back()->date.substr(0, 10) + ")"};
  for (const std::string& cell : decided.cells) row.push_back(cell);
  row.push_back(to_string(decided.verdict));
  decision.machine_table["rows"].push_back(row);
  decision.per_machine.push_back(decided.verdict);
  decision.machines.push_back(
      {{"machine", machine.key}, {"runs", ids}, {"figures", decided.figures}, {"verdict", to_string(decided.verdict)}});
}

}  // namespace

RunsDecision decide_runs(const std::vector<bench::RecordedRun>& runs, const std::vector<Reading>& readings,
                         const std::string& title) {
  RunsDecision decision;
  decision.machine_table =
      table(title + ": each machine, its runs pooled (the claim's verdict)", {"machine", "runs"}, readings);
  decision.run_table = table(title + ": each run alone", {"run", "machine", "processes"}, readings);
  decision.machines = decision.runs = nlohmann::json::array();
  for (const bench::MachineRuns& machine : bench::by_machine(runs)) add_machine(decision, machine, readings);
  for (const bench::RecordedRun& run : runs) add_run(decision, run, readings);
  decision.verdict = across_machines(decision.per_machine);
  return decision;
}

std::string machines_summary(const std::vector<bench::RecordedRun>& runs, const RunsDecision& decision) {
  const std::vector<bench::MachineRuns> machines = bench::by_machine(runs);
  std::string text = std::string(to_string(decision.verdict)) + " over " + std::to_string(machines.size()) +
                     (machines.size() == 1 ? " machine" : " machines") + ", their runs pooled (";
  for (std::size_t m = 0; m < machines.size(); ++m) {
    const std::size_t n = machines[m].runs.size();
    text += (m ? "; " : "") + machines[m].key + ", " + std::to_string(n) + (n == 1 ? " run: " : " runs: ") +
            std::string(to_string(decision.per_machine[m]));
  }
  return text + ")";
}

std::vector<std::string> runs_chart(const RunSettings& ctx, const std::vector<bench::RecordedRun>& runs,
                                    const std::vector<Reading>& readings, const std::string& stem,
                                    const std::string& title) {
  if (!ctx.draws_figures()) return {};
  std::vector<plots::BandPanel> panels;
  for (const Reading& reading : readings) {
    plots::BandPanel& panel =
        panels.emplace_back(plots::BandPanel{reading.label, "×", reading.band.lo, reading.band.hi, {}});
    for (const bench::RecordedRun& run : runs) {
      const auto figure = run.figures.find(reading.key);
      if (figure == run.figures.end()) continue;
      const Measured& m = figure->second.measured;
      panel.unit = figure->second.unit;
      panel.runs.push_back(
          {run_label(run), m.value, m.ci95 ? std::optional(std::pair{m.ci95->lo, m.ci95->hi}) : std::nullopt});
    }
  }
  return RunSettings::figure_refs(plots::draw_runs_against_band(ctx.figure_stem(stem), title, panels));
}

Outcome about_ratio_outcome(const std::vector<bench::RecordedRun>& runs, const std::string& key, double paper,
                            const std::string& method, std::uint64_t sample_size, const std::vector<Reading>& more) {
  const Interval band = about_band(paper);
  std::vector<Reading> readings{{key, band, key}};
  readings.insert(readings.end(), more.begin(), more.end());
  const RunsDecision decision = decide_runs(runs, readings, "The recorded runs (reports/bench/history/)");
  Outcome outcome;
  outcome.verdict = decision.verdict;
  outcome.evidence.method = method;
  outcome.evidence.sample_size = sample_size;
  outcome.evidence.tolerance = kAboutFactor;
  outcome.evidence.details = {
      {"paper_ratio", paper},
      {"paper_machine", kPaperMachine},
      {"about", kAboutReading},
      {"rule", std::string(kIntervalRule) + ". Across machines: " + std::string(kAcrossMachinesRule)},
      {"pooled_bootstrap",
       {{"seed", bench::kPooledSeed}, {"resamples", bench::kPooledResamples}, {"level", 0.95}, {"source", kPooling}}},
      {"tables", nlohmann::json::array({decision.machine_table, decision.run_table})},
  };
  const bench::RecordedRun& latest = runs.back();
  if (const auto figure = latest.figures.find(key); figure != latest.figures.end())
    outcome.evidence.measurements = to_json(figure->second.measured, band);
  outcome.evidence.measurements["latest_run"] = latest.id;
  outcome.evidence.measurements["machine"] = latest.machine;
  outcome.evidence.measurements["machines"] = decision.machines;
  outcome.evidence.measurements["runs"] = decision.runs;
  outcome.evidence.measurements["across_machines"] = machines_summary(runs, decision);
  return outcome;
}

std::vector<std::string> bar_chart(const RunSettings& ctx, const BenchResults& results, std::string_view prefix,
                                   std::initializer_list<std::string_view> thesis_names, const std::string& stem,
                                   const std::string& title, const std::string& unit, double scale) {
  if (!ctx.draws_figures()) return {};
  plots::Table bars;
  std::ostringstream tics;
  for (const auto& [name, value] : results.median) {
    if (!name.starts_with(prefix)) continue;
    bool thesis = false;
    for (auto t : thesis_names) thesis = thesis || name == t;
    tics << (bars.empty() ? "" : ", ") << '"' << name.substr(prefix.size()) << "\" " << bars.size();
    bars.push_back({static_cast<double>(bars.size()), value * scale, thesis ? 1.0 : 0.0});
  }
  if (bars.empty()) return {};
  const auto files = plots::Figure(ctx.figure_stem(stem))
                         .size(900, 520)
                         .data("bars", bars)
                         .script("set title '" + title +
                                 "'\n"
                                 "set ylabel '" +
                                 unit +
                                 "'\n"
                                 "set xtics (" +
                                 tics.str() +
                                 ") rotate by -30 left\n"
                                 "set style fill solid 0.85 border -1\n"
                                 "set boxwidth 0.6\n"
                                 "set yrange [0:*]\n"
                                 "set offsets 0, 0, graph 0.1, 0\n"
                                 "set label 1 'orange: the algorithms the thesis compares' at graph 0.02, graph 0.95 "
                                 "tc rgb '#d55e00'\n"
                                 "set xrange [-0.6:" +
                                 std::to_string(bars.size() - 0.4) +
                                 "]\n"
                                 "set bmargin 7\n"
                                 "plot $bars using 1:2:($3 > 0 ? 0xd55e00 : 0x0072b2) with boxes lc rgb variable, "
                                 "$bars using 1:2:(sprintf('%.3g', $2)) with labels offset 0,0.8\n")
                         .render();
  std::vector<std::string> refs;
  for (const auto& f : files) refs.push_back(RunSettings::figure_ref(f));
  return refs;
}

}  // namespace affinterp::claims::sym3
