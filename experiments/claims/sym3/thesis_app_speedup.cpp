#include "experiments/claims/claim.hpp"
#include "experiments/claims/sym3/speed_claim.hpp"
#include "experiments/inputs/sym3/demo_mesh.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <string_view>
#include <variant>

namespace affinterp::claims::sym3 {
namespace {

Outcome check(const ClaimContext& ctx);

const ClaimDeclaration claim{{
    .id = "thesis.app.speedup",
    .chapter = Chapter::sym3,
    .where = "thesis §3.4, Fig 3.3",
    .statement = "In a deformation application on a mesh of about 100,000 triangles, the improved algorithm is about "
                 "1.2× faster overall.",
    .strength = Strength::measured,
    .check = check,
}};

// Reading: the thesis's cage-based deformer is not available; the pipeline here (theory/deformation/deformation.hpp)
//   swaps only the per-triangle symmetric exponential, as the thesis did. "About 1.2×" allows the ratios in
//   [max(1, 1.2 / 1.5), 1.2 · 1.5] = [1, 1.8] (speed_claim.hpp); reproduced iff the ratio's 95% bootstrap
//   interval lies in it (measured.hpp).
// Method: measured, not decided: Google Benchmark bench_app3 (CPU time per frame, 10 repetitions) on
//   ChineseDragon-10kv (libcgal-demo) subdivided once, 79,976 triangles; ratio = time(Diag) / time(improved SD).
//   Inconclusive without the benchmark file or the CGAL demo data. Draws thesis Fig 3.3 for this machine.
// Sizes: the benchmark's own; the same at either size.

// The benchmarks standing for the thesis's algorithms in the application (names from theory/sym3/algorithms.hpp).
constexpr std::string_view kAppDiag = "app/eigen-qr-diag";
constexpr std::string_view kAppImprovedSd = "app/thesis-improved-sd";

Outcome check(const ClaimContext& ctx) {
  const std::string method =
      "Google Benchmark bench_app3: CPU time per frame (median of 10 repetitions) of the 3D deformation pipeline "
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
  outcome.summary = "a deformation frame of the 79,976-triangle dragon is " +
                    ratio_text(measured_ratio(results, kAppDiag, kAppImprovedSd)) +
                    " faster with improved SD than with Diag here (" + band_text(paper) +
                    ", on its cage-based deformer)";
  outcome.evidence.details["paper_model"] =
      "dragon, 50,000 vertices, 100,000 triangles, cage-based deformer of Kaji et al. [6]";
  outcome.evidence.details["reading"] =
      "the thesis's cage-based deformer is not available; the pipeline here swaps only the per-triangle symmetric "
      "exponential, as the thesis did";
  nlohmann::json ms = nlohmann::json::object();
  for (const auto& [name, value] : results.median) ms[name] = value * 1e-6;
  outcome.evidence.measurements["ms_per_frame"] = ms;
  outcome.figures =
      bar_chart(ctx, results, "app/", {kAppDiag, kAppImprovedSd}, "thesis-fig3-3",
                "Fig. 3.3: one deformation frame of the dragon, 79,976 triangles (" + results.machine + ")",
                "ms per frame", 1e-6);
  return outcome;
}

}  // namespace
}  // namespace affinterp::claims::sym3
