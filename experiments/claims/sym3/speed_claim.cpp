#include "experiments/claims/sym3/speed_claim.hpp"

#include "plots/figure.hpp"

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
    "ratio_ci95 = the 95% percentile bootstrap interval (10,000 resamples of each benchmark's repetitions with "
    "replacement, independently, seed 2015; experiments/claims/bootstrap.hpp). Reproduced iff ratio_ci95 lies "
    "in the band, not-reproduced iff it lies outside it, inconclusive iff it straddles an edge (or fewer than 10 "
    "repetitions were recorded). The interval covers the run-to-run spread within one benchmark run, not the "
    "drift between runs on a shared machine";

constexpr std::string_view kPaperMachine =
    "Intel Core i7 1.9 GHz, 4 GB RAM, Windows 8 (64 bit), Visual Studio 2010 /O2 (thesis §3.4)";

Outcome inconclusive(std::string summary, const std::string& method) {
  Outcome outcome;
  outcome.verdict = Verdict::inconclusive;
  outcome.summary = std::move(summary);
  outcome.evidence.method = method;
  return outcome;
}

nlohmann::json machine_of(const BenchResults& results) {
  return {{"cpu", results.machine},
          {"compiler", results.compiler},
          {"flags", results.flags},
          {"benchmark_file", results.file.filename().string()}};
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
    results = read_bench_results(ctx.bench_dir / (bench + ".json"), counter);
  } catch (const std::runtime_error& e) {
    return inconclusive(std::string("unreadable benchmark output: ") + e.what() + "; " + run, method);
  }
  if (!results) return inconclusive((ctx.bench_dir / (bench + ".json")).string() + " is absent: " + run, method);
  if (auto absent = missing(*results, needed); !absent.empty())
    return inconclusive("benchmarks missing from " + bench + ".json: " + absent + hint, method);
  return *results;
}

Outcome about_ratio_outcome(const BenchResults& results, std::string_view slow, std::string_view fast, double paper,
                            const std::string& method, std::uint64_t sample_size) {
  const Measured ratio = measured_ratio(results, slow, fast);
  const Interval band = about_band(paper);
  Outcome outcome;
  outcome.verdict = verdict_of(ratio, band);
  outcome.evidence.method = method;
  outcome.evidence.sample_size = sample_size;
  outcome.evidence.tolerance = kAboutFactor;
  outcome.evidence.details = {
      {"paper_ratio", paper},   {"paper_machine", kPaperMachine}, {"benchmarks", {slow, fast}},
      {"about", kAboutReading}, {"rule", kIntervalRule},
  };
  outcome.evidence.measurements = to_json(ratio, band);
  outcome.evidence.measurements["machine"] = machine_of(results);
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
