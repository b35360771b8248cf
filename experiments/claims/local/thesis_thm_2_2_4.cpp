#include "experiments/claims/claim.hpp"
#include "experiments/claims/local/area_theorem.hpp"
#include "experiments/claims/local/area_theorem_proof.hpp"
#include "experiments/claims/local/area_witness.hpp"
#include "experiments/claims/local/condition_sweep.hpp"
#include "experiments/claims/local/simple_values.hpp"
#include "experiments/claims/values.hpp"
#include "theory/local/goodness.hpp"

#include <tuple>

namespace affinterp::claims::local::thesis_thm_2_2_4 {
namespace {

Outcome check(const ClaimContext& ctx);

const ClaimDeclaration claim{{
    .id = "thesis.thm-2.2.4",
    .chapter = Chapter::local,
    .where = "thesis Thm 2.2.4",
    .statement = "Polar interpolation is good for area exactly when Thm 2.2.1's condition holds with tr S for tr A.",
    .strength = Strength::exact_counterexample,
    .check = check,
}};

// Reading: Def 2.2.1 as for Thm 2.2.1; A_p(t) = R_{tγ}((1−t)I + tS) with S = [[x, h], [h, y]] positive definite, and
//   det A_p(t) = det((1−t)I + tS) for every γ.
// Method: proof for all reals (area_theorem_proof.hpp): the printed condition and its correction each
//   against Def 2.2.1 as two sentences at level E (Lemmas L1, L2, L5), decided by QEPCAD B and Z3; the printed
//   condition's counterexample from the deciders' point, shrunk and re-verified by goodness.hpp. Second line:
//   over an (x, y, h) grid with xy > h², the printed condition (Thm 2.2.1's with tr S for tr A) against the
//   exact decision of Def 2.2.1 and against the corrected condition. The figure is the slice h = 1/2.
// Sizes: quick step 1/4, sentences at level E; full step 1/16, also levels D and L; x, y ∈ (0, 4], h ∈ [−4, 4].

/// S = [[x, h], [h, y]] positive definite: det A_p(t) = det((1−t)I + tS) (Lemma L5).
AreaParameters polar_parameters() {
  const Polynomial x = var("x"), y = var("y"), h = var("h");
  const PolyMat2 S{{{x, h}, {h, y}}};
  const auto S_at = [](const logic::Point& p) { return symmetric(p.at("x"), p.at("y"), p.at("h")); };
  return {S,
          {"x", "y", "h"},
          logic::greater(x, 0) && logic::greater(y, 0) && logic::greater(det(S), 0),
          "S = [[x, h], [h, y]] real positive definite (every gamma)",
          S_at,
          [](const logic::Point& p) {
            return p.at("x") > 0 && p.at("y") > 0 && p.at("x") * p.at("y") > p.at("h") * p.at("h");
          },
          "det A_p(t) = det R_{t gamma} det((1-t)I + tS) and det R = cos^2 + sin^2 = 1 (Lemma L5)"};
}

ProofPlan proof_plan() { return area_theorem_plan(polar_parameters()); }

Outcome check(const ClaimContext& ctx) {
  const Rational step = ctx.pick(Rational(1) / 4, Rational(1) / 16);
  using Case = std::tuple<Rational, Rational, Rational>;  // (x, y, h), xy > h²
  std::vector<Case> cases;
  for (const Rational& x : grid(step, 4, step))
    for (const Rational& y : grid(step, 4, step))
      for (const Rational& h : grid(-4, 4, step))
        if (x * y > h * h) cases.emplace_back(x, y, h);
  const auto cost = [](const Case& c) {
    return height(std::get<0>(c)) + height(std::get<1>(c)) + height(std::get<2>(c));
  };
  const auto S_of = [](const Case& c) { return symmetric(std::get<0>(c), std::get<1>(c), std::get<2>(c)); };
  const auto [printed, corrected] = tally_area_conditions(cases, ctx.threads, S_of, cost);

  Outcome outcome;
  outcome.evidence.method =
      "exact rational decision of Def 2.2.1 for A_p(t) vs the printed condition over an (x, y, h) grid";
  outcome.evidence.details["reading"] = area_reading + " det A_p(t) = det((1-t)I + tS) for every gamma; det A = det S.";
  outcome.evidence.details["grid"] = "x, y in (0, 4], h in [-4, 4], xy > h^2, step " + exact::to_string(step);
  decide_area_theorem(outcome, printed, corrected, "Thm 2.2.4 (polar)");
  if (printed.disagreements() > 0) {
    outcome.correction =
        "A_p(t) is good for area iff (2 det A <= tr S <= 2) or (2 <= tr S <= 2 det A) (Thm 2.2.1 corrected, applied to "
        "S).";
    const Case& c = *printed.condition_only.simplest;
    outcome.counterexample = {{"x", exact::to_string(std::get<0>(c))},
                              {"y", exact::to_string(std::get<1>(c))},
                              {"h", exact::to_string(std::get<2>(c))},
                              {"gamma", "0"},
                              {"A", exact_matrix(S_of(c))},
                              {"printed_condition", true},
                              {"good_for_area", false},
                              {"witness", area_witness(S_of(c))}};
  }
  const AreaParameters parameters = polar_parameters();
  ProofRun proof = run_proof(ctx, proof_plan());
  require_agreement(outcome, area_proof_verdict(proof));
  if (printed.disagreements() > 0) outcome.counterexample["from_proof"] = area_proof_counterexample(proof, parameters);
  attach_proof(outcome, std::move(proof));
  if (ctx.draws_figures()) {
    std::vector<Case> slice;  // h = 1/2: the (x, y) plane of S = [[x, 1/2], [1/2, y]]
    for (const Case& c : cases)
      if (std::get<2>(c) == Rational(1) / 2) slice.push_back(c);
    outcome.figures = draw_area_map<Case>(
        ctx, "thesis-thm-2.2.4-region",
        "Thm 2.2.4 (polar interpolation), slice h = 1/2: printed condition vs good for area", "x", "y", slice,
        [](const Case& c) {
          return std::pair{static_cast<double>(std::get<0>(c)), static_cast<double>(std::get<1>(c))};
        },
        S_of, step);
  }
  return outcome;
}

}  // namespace
}  // namespace affinterp::claims::local::thesis_thm_2_2_4
