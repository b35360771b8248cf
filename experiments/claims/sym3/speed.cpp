#include "experiments/claims/sym3/speed.hpp"

#include "experiments/claims/bench_results.hpp"
#include "experiments/inputs/sym3/demo_mesh.hpp"
#include "plots/figure.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <variant>
#include <string>
#include <vector>

namespace affinterp::claims::sym3 {

namespace {

// The benchmarks standing for the thesis's algorithms (names from theory/sym3/algorithms.hpp).
constexpr std::string_view kQr = "eig3/eigen-qr";          // Eigen's QR-based eigenvalue solver
constexpr std::string_view kViete = "eig3/viete";           // thesis §3.2
constexpr std::string_view kDiag = "exp3/eigen-qr-diag";    // Algorithm 1, diagonalisation (Diag)
constexpr std::string_view kSd = "exp3/thesis-sd-corrected";     // Algorithm 2, SD with Eigen's eigenvalues
constexpr std::string_view kImprovedSd = "exp3/thesis-improved-sd";  // SD with Viète's eigenvalues
constexpr std::string_view kOurs = "exp3/affinterp";
constexpr std::string_view kOursBatched = "exp3/affinterp-batched";
constexpr std::string_view kDirectDiag = "exp3/eigen-direct-diag";
constexpr std::string_view kPade = "exp3/eigen-pade";
constexpr std::string_view kAppDiag = "app/eigen-qr-diag";
constexpr std::string_view kAppImprovedSd = "app/thesis-improved-sd";

constexpr std::string_view kAboutReading =
    "'about r×' = measured ratio within a factor 1.5 of r and above 1: the thesis measured on a 2013 Intel Core "
    "i7 with MSVC 2010 /O2 and an older Eigen; CPU generation, compiler and library version move such ratios by "
    "tens of percent, while a factor 1.5 still tells 3.2× from 2× or 5×";

constexpr std::string_view kPaperMachine =
    "Intel Core i7 1.9 GHz, 4 GB RAM, Windows 8 (64 bit), Visual Studio 2010 /O2 (thesis §3.4)";

std::string fixed(double x, int digits = 2) {
  std::ostringstream out;
  out.precision(digits);
  out << std::fixed << x;
  return out.str();
}

Outcome inconclusive(std::string summary, const std::string& method) {
  Outcome outcome;
  outcome.verdict = Verdict::inconclusive;
  outcome.summary = std::move(summary);
  outcome.evidence.method = method;
  return outcome;
}

/// The missing benchmarks among `names`, as "a, b (error message)"; empty when all ran.
std::string missing(const BenchResults& results, std::initializer_list<std::string_view> names) {
  std::string list;
  for (auto name : names) {
    if (results[name]) continue;
    if (!list.empty()) list += ", ";
    list += name;
    if (const auto error = results.errors.find(name); error != results.errors.end())
      list += " (" + error->second + ")";
  }
  return list;
}

/// The results of bench_<name>.json, or the inconclusive outcome saying why they cannot be used: no
/// benchmark folder, an absent or unreadable file, or one of `needed` missing from it (`hint` appended).
std::variant<BenchResults, Outcome> load(const RunContext& ctx, const std::string& bench, const std::string& counter,
                                         const std::string& method, std::initializer_list<std::string_view> needed,
                                         const std::string& hint = "") {
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

bool about(double measured, double paper) {
  return measured > 1 && measured >= paper / kAboutFactor && measured <= paper * kAboutFactor;
}

nlohmann::json machine_of(const BenchResults& results) {
  return {{"cpu", results.machine}, {"compiler", results.compiler}, {"flags", results.flags},
          {"benchmark_file", results.file.filename().string()}};
}

/// The part every "about N× faster" outcome shares: the verdict for time(slow) / time(fast) against the
/// thesis's `paper` ratio, and the evidence fields; callers add the summary and their own details.
Outcome about_ratio_outcome(const BenchResults& results, std::string_view slow, std::string_view fast, double paper,
                            const std::string& method, std::uint64_t sample_size) {
  const double ratio = *results[slow] / *results[fast];
  Outcome outcome;
  outcome.verdict = about(ratio, paper) ? Verdict::reproduced : Verdict::not_reproduced;
  outcome.evidence.method = method;
  outcome.evidence.sample_size = sample_size;
  outcome.evidence.tolerance = kAboutFactor;
  outcome.evidence.details = {
      {"paper_ratio", paper},
      {"paper_machine", kPaperMachine},
      {"benchmarks", {slow, fast}},
      {"about", kAboutReading},
      {"rule", "reproduced iff the measured ratio lies in [paper / 1.5, paper · 1.5] and exceeds 1"},
  };
  outcome.evidence.measurements = {{"measured_ratio", ratio}, {"machine", machine_of(results)}};
  return outcome;
}

/// A bar chart of the benchmarks whose names start with `prefix` (all of them, in name order), with
/// the ones the thesis compares highlighted; returns the figure's file for the report.
std::vector<std::string> bar_chart(const RunContext& ctx, const BenchResults& results, std::string_view prefix,
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
                         .script("set title '" + title + "'\n"
                                 "set ylabel '" + unit + "'\n"
                                 "set xtics (" + tics.str() + ") rotate by -30 left\n"
                                 "set style fill solid 0.85 border -1\n"
                                 "set boxwidth 0.6\n"
                                 "set yrange [0:*]\n"
                                 "set offsets 0, 0, graph 0.1, 0\n"
                                 "set label 1 'orange: the algorithms the thesis compares' at graph 0.02, graph 0.95 "
                                 "tc rgb '#d55e00'\n"
                                 "set xrange [-0.6:" + std::to_string(bars.size() - 0.4) + "]\n"
                                 "set bmargin 7\n"
                                 "plot $bars using 1:2:($3 > 0 ? 0xd55e00 : 0x0072b2) with boxes lc rgb variable, "
                                 "$bars using 1:2:(sprintf('%.3g', $2)) with labels offset 0,0.8\n")
                         .render();
  std::vector<std::string> refs;
  for (const auto& f : files) refs.push_back(RunContext::figure_ref(f));
  return refs;
}

}  // namespace

Outcome check_eig_speedup(const RunContext& ctx) {
  const std::string method =
      "Google Benchmark bench_exp3: CPU time per matrix (median of repetitions) over 4096 matrices S = MᵀM, "
      "M uniform in [−1, 1], cycled; ratio = time(eigen-qr) / time(viete)";
  auto loaded = load(ctx, "bench_exp3", "ns_per_matrix", method, {kQr, kViete});
  if (auto* outcome = std::get_if<Outcome>(&loaded)) return *outcome;
  const auto& results = std::get<BenchResults>(loaded);

  constexpr double paper = 3.2;
  Outcome outcome = about_ratio_outcome(results, kQr, kViete, paper, method, 4096);
  const double ratio = outcome.evidence.measurements["measured_ratio"];
  outcome.summary = "Viète eigenvalues are " + fixed(ratio) + "× faster than Eigen's QR solver here (thesis: about " +
                    fixed(paper, 1) + "×; 'about' = within a factor " + fixed(kAboutFactor, 1) + ")";
  outcome.evidence.measurements["ns_per_matrix"] = {{kQr, *results[kQr]}, {kViete, *results[kViete]}};
  outcome.figures = bar_chart(ctx, results, "eig3/", {kQr, kViete}, "thesis-fig3-1",
                              "Fig. 3.1: eigenvalues of 3×3 symmetric S = MᵀM (" + results.machine + ")",
                              "ns per matrix", 1.0);
  return outcome;
}

Outcome check_exp_speedup(const RunContext& ctx) {
  const std::string method =
      "Google Benchmark bench_exp3: CPU time per matrix (median of repetitions) over 4096 matrices S = MᵀM, "
      "M uniform in [−1, 1], cycled; Diag = eigen-qr-diag, SD = thesis-sd-corrected, improved SD = "
      "thesis-improved-sd";
  auto loaded = load(ctx, "bench_exp3", "ns_per_matrix", method, {kDiag, kSd, kImprovedSd});
  if (auto* outcome = std::get_if<Outcome>(&loaded)) return *outcome;
  const auto& results = std::get<BenchResults>(loaded);

  constexpr double paper = 4.2;
  const double diag = *results[kDiag], sd = *results[kSd], improved = *results[kImprovedSd];
  // "In between" must show beyond run-to-run noise: SD at least kMargin faster than Diag and slower than
  // improved SD (medians of repeated runs on a shared machine moved by several percent between runs).
  constexpr double kMargin = 1.05;
  const bool sd_between = improved * kMargin < sd && sd * kMargin < diag;
  Outcome outcome = about_ratio_outcome(results, kDiag, kImprovedSd, paper, method, 4096);
  const double ratio = outcome.evidence.measurements["measured_ratio"];
  if (!sd_between) outcome.verdict = Verdict::not_reproduced;
  outcome.summary = "improved SD is " + fixed(ratio) + "× faster than Diag here (thesis: about " + fixed(paper, 1) +
                    "×; 'about' = within a factor " + fixed(kAboutFactor, 1) + "); plain SD " +
                    (sd_between ? "lies" : "does not lie") + " in between (time of Diag / time of SD = " + fixed(diag / sd) + ")";
  outcome.evidence.details["benchmarks"] = {kDiag, kSd, kImprovedSd};
  outcome.evidence.details["reading"] =
      "Diag = Eigen's QR-based SelfAdjointEigenSolver with eigenvectors (§3.1.1); plain SD = §3.1.2 on the "
      "eigenvalues of that solver (the thesis names no solver for SD; improved SD differs from it only by Viète's "
      "eigenvalues, §3.2)";
  outcome.evidence.details["rule"] =
      "reproduced iff time(Diag)/time(improved SD) lies in [paper / 1.5, paper · 1.5] and exceeds 1, and "
      "time(improved SD) < time(SD) < time(Diag) with 5% to spare on each side (beyond run-to-run noise)";
  nlohmann::json ns = nlohmann::json::object();
  for (const auto& [name, value] : results.median)
    if (name.starts_with("exp3/")) ns[name] = value;
  outcome.evidence.measurements["sd_ratio"] = diag / sd;
  outcome.evidence.measurements["sd_between"] = sd_between;
  outcome.evidence.measurements["ns_per_matrix"] = ns;
  // The suite's own exponential against its speed targets.
  if (missing(results, {kOurs, kOursBatched, kDirectDiag, kPade}).empty()) {
    const double ours = *results[kOurs], batched = *results[kOursBatched];
    const double vs_direct = *results[kDirectDiag] / ours, vs_pade = *results[kPade] / ours;
    const double batched_vs_direct = *results[kDirectDiag] / batched;
    outcome.evidence.measurements["affinterp_targets"] = {
        {"speedup_vs_eigen_direct_diag", vs_direct},
        {"speedup_vs_eigen_pade", vs_pade},
        {"batched_ns_per_matrix", batched},
        {"batched_speedup_vs_scalar_eigen_direct_diag", batched_vs_direct},
        {"targets", "scalar ≥ 1.5× vs eigen-direct-diag and eigen-pade; batched ≤ 15 ns and ≥ 4× vs scalar "
                    "eigen-direct-diag"},
        {"met", vs_direct >= 1.5 && vs_pade >= 1.5 && batched <= 15 && batched_vs_direct >= 4},
    };
  }
  outcome.figures = bar_chart(ctx, results, "exp3/", {kDiag, kSd, kImprovedSd}, "thesis-fig3-2",
                              "Fig. 3.2: exp of 3×3 symmetric S = MᵀM (" + results.machine + ")", "ns per matrix",
                              1.0);
  return outcome;
}

Outcome check_app_speedup(const RunContext& ctx) {
  const std::string method =
      "Google Benchmark bench_app3: CPU time per frame (median of repetitions) of the 3D deformation pipeline "
      "(theory/deformation/deformation.hpp) on ChineseDragon-10kv (libcgal-demo) subdivided once, 79,976 "
      "triangles, towards a twisted pose; Diag = eigen-qr-diag, improved SD = thesis-improved-sd; ratio = "
      "time(Diag) / time(improved SD)";
  auto loaded = load(ctx, "bench_app3", "ns_per_frame", method, {kAppDiag, kAppImprovedSd},
                     "; bench_app3 needs the CGAL demo data " + std::string(affinterp::sym3::cgal_demo_archive) +
                         " (Debian package libcgal-demo)");
  if (auto* outcome = std::get_if<Outcome>(&loaded)) return *outcome;
  const auto& results = std::get<BenchResults>(loaded);

  constexpr double paper = 1.2;
  Outcome outcome = about_ratio_outcome(results, kAppDiag, kAppImprovedSd, paper, method, 79976);
  const double ratio = outcome.evidence.measurements["measured_ratio"];
  outcome.summary = "a deformation frame of the 79,976-triangle dragon is " + fixed(ratio) +
                    "× faster with improved SD than with Diag here (thesis: about " + fixed(paper, 1) +
                    "× on its cage-based deformer; 'about' = within a factor " + fixed(kAboutFactor, 1) +
                    " and above 1)";
  outcome.evidence.details["paper_model"] = "dragon, 50,000 vertices, 100,000 triangles, cage-based deformer of Kaji et al. [6]";
  outcome.evidence.details["reading"] =
      "the thesis's cage-based deformer is not available; the pipeline here swaps only the per-triangle symmetric "
      "exponential, as the thesis did";
  nlohmann::json ms = nlohmann::json::object();
  for (const auto& [name, value] : results.median) ms[name] = value * 1e-6;
  outcome.evidence.measurements["ms_per_frame"] = ms;
  outcome.figures = bar_chart(ctx, results, "app/", {kAppDiag, kAppImprovedSd}, "thesis-fig3-3",
                              "Fig. 3.3: one deformation frame of the dragon, 79,976 triangles (" + results.machine +
                                  ")",
                              "ms per frame", 1e-6);
  return outcome;
}

}  // namespace affinterp::claims::sym3
