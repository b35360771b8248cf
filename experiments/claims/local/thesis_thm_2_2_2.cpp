#include "experiments/claims/claim.hpp"
#include "experiments/claims/local/area_theorem.hpp"
#include "experiments/claims/local/area_theorem_proof.hpp"
#include "experiments/claims/local/area_witness.hpp"
#include "experiments/claims/local/condition_sweep.hpp"
#include "experiments/claims/local/simple_values.hpp"
#include "experiments/claims/values.hpp"
#include "theory/local/goodness.hpp"

#include <utility>

namespace affinterp::claims::local::thesis_thm_2_2_2 {
namespace {

Outcome check(const ClaimContext& ctx);

const ClaimDeclaration claim{{
    .id = "thesis.thm-2.2.2",
    .chapter = Chapter::local,
    .where = "thesis Thm 2.2.2",
    .statement = "SVD interpolation is good for area exactly when Thm 2.2.1's condition holds with tr D for tr A.",
    .strength = Strength::exact_counterexample,
    .check = check,
}};

// Reading: Def 2.2.1 as for Thm 2.2.1; A_s(t) = R_{tα}((1−t)I + tD)R_{tβ} with D = diag(x, y), and
//   det A_s(t) = det((1−t)I + tD) for every α, β, so the (x, y) plane decides the theorem.
// Method: proof for all reals (area_theorem_proof.hpp): the printed condition and its correction each
//   against Def 2.2.1 as two sentences at level E (Lemmas L1, L2, L5), decided by QEPCAD B and Z3; the printed
//   condition's counterexample from the deciders' point, shrunk and re-verified by goodness.hpp. Second line:
//   over an (x, y) grid, x ≥ y > 0, the printed condition (Thm 2.2.1's with tr D for tr A) against the exact
//   decision of Def 2.2.1 and against the corrected condition.
// Sizes: quick step 1/4, sentences at level E; full step 1/32, also levels D and L; x, y ∈ (0, 4].

/// D = diag(x, y), x, y > 0: det A_s(t) = det((1−t)I + tD) (Lemma L5).
AreaParameters svd_parameters() {
  const Polynomial x = var("x"), y = var("y");
  const auto D_at = [](const logic::Point& p) { return diagonal(p.at("x"), p.at("y")); };
  return {{{{x, Polynomial(0)}, {Polynomial(0), y}}},
          {"x", "y"},
          logic::greater(x, 0) && logic::greater(y, 0),
          "D = diag(x, y) with x, y > 0 real (every alpha, beta)",
          D_at,
          [](const logic::Point& p) { return p.at("x") > 0 && p.at("y") > 0; },
          "det A_s(t) = det R_{t alpha} det((1-t)I + tD) det R_{t beta} and det R = cos^2 + sin^2 = 1 (Lemma L5)"};
}

ProofPlan proof_plan() { return area_theorem_plan(svd_parameters()); }

Outcome check(const ClaimContext& ctx) {
  const Rational step = ctx.pick(Rational(1) / 4, Rational(1) / 32);
  std::vector<std::pair<Rational, Rational>> cases;  // (x, y), x >= y > 0
  for (const Rational& x : grid(step, 4, step))
    for (const Rational& y : grid(step, x, step)) cases.emplace_back(x, y);
  using Case = std::pair<Rational, Rational>;
  const auto cost = [](const Case& c) { return height(c.first) + height(c.second); };
  const auto D_of = [](const Case& c) { return diagonal(c.first, c.second); };  // det A_s(t) = det((1−t)I + tD)
  const auto [printed, corrected] = tally_area_conditions(cases, ctx.threads, D_of, cost);

  Outcome outcome;
  outcome.evidence.method =
      "exact rational decision of Def 2.2.1 for A_s(t) vs the printed condition over an (x, y) grid";
  outcome.evidence.details["reading"] = area_reading + " det A_s(t) = det((1-t)I + tD) for every alpha, beta.";
  outcome.evidence.details["grid"] = "x >= y > 0, x, y in (0, 4], step " + exact::to_string(step);
  decide_area_theorem(outcome, printed, corrected, "Thm 2.2.2 (SVD)");
  if (printed.disagreements() > 0) {
    outcome.correction =
        "A_s(t) is good for area iff (2 det A <= tr D <= 2) or (2 <= tr D <= 2 det A) (Thm 2.2.1 corrected, applied to "
        "D).";
    const auto& [x, y] = *printed.condition_only.simplest;
    outcome.counterexample = {{"x", exact::to_string(x)},
                              {"y", exact::to_string(y)},
                              {"alpha", "0"},
                              {"beta", "0"},
                              {"A", exact_matrix(diagonal(x, y))},
                              {"printed_condition", true},
                              {"good_for_area", false},
                              {"witness", area_witness(diagonal(x, y))}};
  }
  const AreaParameters parameters = svd_parameters();
  ProofRun proof = run_proof(ctx, proof_plan());
  require_agreement(outcome, area_proof_verdict(proof));
  if (printed.disagreements() > 0) outcome.counterexample["from_proof"] = area_proof_counterexample(proof, parameters);
  attach_proof(outcome, std::move(proof));
  if (ctx.draws_figures())
    outcome.figures = draw_area_map<Case>(
        ctx, "thesis-thm-2.2.2-region", "Thm 2.2.2 (SVD interpolation): printed condition vs good for area", "x", "y",
        cases,
        [](const Case& c) {
          return std::pair{static_cast<double>(c.first), static_cast<double>(c.second)};
        },
        D_of, step);
  return outcome;
}

}  // namespace
}  // namespace affinterp::claims::local::thesis_thm_2_2_2
