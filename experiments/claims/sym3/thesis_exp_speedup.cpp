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
//   eigenvalues, §3.2). "About 4.2×" as in speed_claim.hpp; "in between" must show beyond run-to-run noise, 5% on
//   each side.
// Method: measured, not decided: Google Benchmark bench_exp3 (CPU time per matrix, median of repetitions, over
//   4096 S = MᵀM). The suite's own exponential against its speed targets is recorded alongside. Inconclusive
//   without the benchmark file. Draws thesis Fig 3.2 for this machine.
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
                    (sd_between ? "lies" : "does not lie") +
                    " in between (time of Diag / time of SD = " + fixed(diag / sd) + ")";
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
        {"targets",
         "scalar ≥ 1.5× vs eigen-direct-diag and eigen-pade; batched ≤ 15 ns and ≥ 4× vs scalar "
         "eigen-direct-diag"},
        {"met", vs_direct >= 1.5 && vs_pade >= 1.5 && batched <= 15 && batched_vs_direct >= 4},
    };
  }
  outcome.figures = bar_chart(ctx, results, "exp3/", {kDiag, kSd, kImprovedSd}, "thesis-fig3-2",
                              "Fig. 3.2: exp of 3×3 symmetric S = MᵀM (" + results.machine + ")", "ns per matrix", 1.0);
  return outcome;
}

}  // namespace
}  // namespace affinterp::claims::sym3
