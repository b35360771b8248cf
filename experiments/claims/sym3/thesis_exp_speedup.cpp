#include "experiments/claims/claim.hpp"
#include "experiments/claims/sym3/speed_claim.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <string_view>
#include <variant>

namespace affinterp::claims::sym3 {
namespace {

Outcome check(const ClaimContext& ctx);

const ClaimDeclaration claim{{
    .id = "thesis.exp.speedup",
    .chapter = Chapter::sym3,
    .where = "thesis §3.4, Fig 3.2",
    .statement = "Improved SD is about 4.2× faster than diagonalisation, with plain SD in between.",
    .strength = Strength::measured,
    .check = check,
}};

// Reading: Diag = Eigen's QR-based SelfAdjointEigenSolver with eigenvectors (§3.1.1); plain SD = §3.1.2 on the
//   eigenvalues of that solver (the thesis names no solver for SD; improved SD differs from it only by Viète's
//   eigenvalues, §3.2). "About 4.2×" allows [max(1, 4.2 / 1.5), 4.2 · 1.5] = [2.80, 6.30] (speed_claim.hpp);
//   "plain SD in between" allows time(Diag) / time(SD) > 1 and time(SD) / time(improved SD) > 1.
// Method: measured, not decided: Google Benchmark bench_exp3 (CPU time per matrix over 4096 S = MᵀM, 10
//   repetitions); each ratio of medians with its 95% bootstrap interval against its band (measured.hpp):
//   reproduced iff all three intervals lie in their bands, not-reproduced iff one lies outside, else
//   inconclusive. The suite's own exponential against its speed targets is recorded alongside, by the same
//   rule. Inconclusive without the benchmark file. Draws thesis Fig 3.2 for this machine.
// Sizes: the benchmark's own; the same at either size.

// The benchmarks standing for the thesis's algorithms (names from theory/sym3/algorithms.hpp), and ours.
constexpr std::string_view kDiag = "exp3/eigen-qr-diag";             // Algorithm 1, diagonalisation (Diag)
constexpr std::string_view kSd = "exp3/thesis-sd-corrected";         // Algorithm 2, SD with Eigen's eigenvalues
constexpr std::string_view kImprovedSd = "exp3/thesis-improved-sd";  // SD with Viète's eigenvalues
constexpr std::string_view kOurs = "exp3/affinterp";
constexpr std::string_view kOursBatched = "exp3/affinterp-batched";
constexpr std::string_view kDirectDiag = "exp3/eigen-direct-diag";
constexpr std::string_view kPade = "exp3/eigen-pade";

Outcome check(const ClaimContext& ctx) {
  const std::string method =
      "Google Benchmark bench_exp3: CPU time per matrix (median of 10 repetitions) over 4096 matrices S = MᵀM, "
      "M uniform in [−1, 1], cycled; Diag = eigen-qr-diag, SD = thesis-sd-corrected, improved SD = "
      "thesis-improved-sd";
  auto loaded = load(ctx, "bench_exp3", "ns_per_matrix", method, {kDiag, kSd, kImprovedSd});
  if (auto* outcome = std::get_if<Outcome>(&loaded)) return *outcome;
  const auto& results = std::get<BenchResults>(loaded);

  constexpr double paper = 4.2;
  const Interval faster{1, kUnbounded};  // "in between": strictly faster on each side
  const Measured over_sd = measured_ratio(results, kDiag, kSd), sd_over = measured_ratio(results, kSd, kImprovedSd);
  const Verdict sd_between = all_of({verdict_of(over_sd, faster), verdict_of(sd_over, faster)});
  Outcome outcome = about_ratio_outcome(results, kDiag, kImprovedSd, paper, method, 4096);
  const Verdict speedup = outcome.verdict;
  outcome.verdict = all_of({speedup, sd_between});
  outcome.summary = "improved SD is " + ratio_text(measured_ratio(results, kDiag, kImprovedSd)) +
                    " faster than Diag here (" + band_text(paper) + "); plain SD " +
                    (sd_between == Verdict::reproduced       ? "lies"
                     : sd_between == Verdict::not_reproduced ? "does not lie"
                                                             : "may or may not lie") +
                    " in between (Diag / SD = " + ratio_text(over_sd) + ", SD / improved SD = " + ratio_text(sd_over) +
                    ")";
  outcome.evidence.details["benchmarks"] = {kDiag, kSd, kImprovedSd};
  outcome.evidence.details["reading"] =
      "Diag = Eigen's QR-based SelfAdjointEigenSolver with eigenvectors (§3.1.1); plain SD = §3.1.2 on the "
      "eigenvalues of that solver (the thesis names no solver for SD; improved SD differs from it only by Viète's "
      "eigenvalues, §3.2); 'in between' allows time(Diag) / time(SD) > 1 and time(SD) / time(improved SD) > 1";
  outcome.evidence.details["rule"] =
      outcome.evidence.details["rule"].get<std::string>() +
      ". The claim needs three figures: Diag / improved SD in the 'about' band, and Diag / SD and SD / improved "
      "SD each in (1, ∞); reproduced iff all three are, not-reproduced iff one is not, else inconclusive";
  nlohmann::json ns = nlohmann::json::object();
  for (const auto& [name, value] : results.median)
    if (name.starts_with("exp3/")) ns[name] = value;
  // The top-level "verdict" of the measurements is the speed-up's alone: name it so beside SD's.
  outcome.evidence.measurements["speedup_verdict"] = outcome.evidence.measurements["verdict"];
  outcome.evidence.measurements.erase("verdict");
  outcome.evidence.measurements["sd_between"] = {{"diag_over_sd", to_json(over_sd, faster)},
                                                 {"sd_over_improved_sd", to_json(sd_over, faster)},
                                                 {"verdict", to_string(sd_between)}};
  outcome.evidence.measurements["ns_per_matrix"] = ns;
  // The suite's own exponential against its speed targets, by the same rule.
  if (missing(results, {kOurs, kOursBatched, kDirectDiag, kPade}).empty()) {
    const Measured vs_direct = measured_ratio(results, kDirectDiag, kOurs);
    const Measured vs_pade = measured_ratio(results, kPade, kOurs);
    const Measured batched = measured_median(results, kOursBatched, [](double ns) { return ns; });
    const Measured batched_vs_direct = measured_ratio(results, kDirectDiag, kOursBatched);
    const Interval at_least_1_5{1.5, kUnbounded}, at_least_4{4, kUnbounded}, at_most_15_ns{0, 15};
    outcome.evidence.measurements["affinterp_targets"] = {
        {"speedup_vs_eigen_direct_diag", to_json(vs_direct, at_least_1_5)},
        {"speedup_vs_eigen_pade", to_json(vs_pade, at_least_1_5)},
        {"batched_ns_per_matrix", to_json(batched, at_most_15_ns, "ns")},
        {"batched_speedup_vs_scalar_eigen_direct_diag", to_json(batched_vs_direct, at_least_4)},
        {"targets",
         "scalar ≥ 1.5× vs eigen-direct-diag and eigen-pade; batched ≤ 15 ns and ≥ 4× vs scalar "
         "eigen-direct-diag; each met (reproduced) iff its 95% bootstrap interval lies in its band"},
        {"verdict", to_string(all_of({verdict_of(vs_direct, at_least_1_5), verdict_of(vs_pade, at_least_1_5),
                                      verdict_of(batched, at_most_15_ns), verdict_of(batched_vs_direct, at_least_4)}))},
    };
  }
  outcome.figures = bar_chart(ctx, results, "exp3/", {kDiag, kSd, kImprovedSd}, "thesis-fig3-2",
                              "Fig. 3.2: exp of 3×3 symmetric S = MᵀM (" + results.machine + ")", "ns per matrix", 1.0);
  return outcome;
}

}  // namespace
}  // namespace affinterp::claims::sym3
