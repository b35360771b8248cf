#include "experiments/claims/claim.hpp"
#include "experiments/claims/local/area_theorem.hpp"
#include "experiments/claims/local/area_theorem_proof.hpp"
#include "experiments/claims/local/area_witness.hpp"
#include "experiments/claims/local/condition_sweep.hpp"
#include "experiments/claims/local/simple_values.hpp"
#include "experiments/claims/values.hpp"
#include "experiments/support/random.hpp"
#include "theory/local/goodness.hpp"

#include <cstdlib>
#include <optional>

namespace affinterp::claims::local::thesis_thm_2_2_1 {
namespace {

Outcome check(const ClaimContext& ctx);

const ClaimDeclaration claim{{
    .id = "thesis.thm-2.2.1",
    .chapter = Chapter::local,
    .where = "thesis Thm 2.2.1",
    .statement = "Linear interpolation is good for area exactly when tr A ≥ det A + 1, or 2 det A ≤ tr A < 2, or 2 ≤ "
                 "tr A < 2 det A.",
    .strength = Strength::exact_counterexample,
    .check = check,
}};

// Reading: "good for area" (Def 2.2.1) = det A_l(t) weakly monotone and > 0 on [0, 1]; A ranges over GL+(2).
// Method: proof for all reals (area_theorem_proof.hpp): the printed condition and its correction each
//   against Def 2.2.1 as two sentences in a, b, c, d (A = [[a, b], [c, d]], det A > 0) at level E (Lemmas L1,
//   L2), decided by QEPCAD B and Z3; the printed condition's counterexample from the deciders' point, shrunk and
//   re-verified by goodness.hpp. Second line: over a (tr A, det A) grid, with a matrix of that trace and determinant
//   whose other entries are drawn at random (the property must not depend on them), the printed condition against the
//   exact decision of Def 2.2.1 (theory/local/goodness.hpp), and the corrected condition over the same cases; the
//   counterexample is the simplest integer matrix where the printed condition holds and A_l(t) is not good for area.
// Sizes: quick step 1/4, sentences at level E; full step 1/16, also levels D and L; tr A ∈ [−4, 6], det A ∈ (0, 5].

/// A = [[a, b], [c, d]] over GL+(2).
AreaParameters linear_parameters() {
  const Polynomial a = var("a"), b = var("b"), c = var("c"), d = var("d");
  const PolyMat2 A{{{a, b}, {c, d}}};
  const auto A_at = [](const logic::Point& p) {
    Mat2<Rational> A;
    A << p.at("a"), p.at("b"), p.at("c"), p.at("d");
    return A;
  };
  return {A,
          {"a", "b", "c", "d"},
          logic::greater(det(A), 0),
          "A = [[a, b], [c, d]] real with det A > 0",
          A_at,
          [A_at](const logic::Point& p) { return det2(A_at(p)) > 0; },
          ""};
}

ProofPlan proof_plan() { return area_theorem_plan(linear_parameters()); }

/// The simplest integer matrix (entries in [−2, 2], least Σ|a_ij|) with det > 0 where `condition` holds
/// and the linear interpolation is not good for area.
std::optional<Mat2<Rational>> simplest_integer_counterexample() {
  std::optional<Mat2<Rational>> best;
  int best_cost = 0;
  for (int code = 0; code < 625; ++code) {
    int entries[4], cost = 0;
    for (int k = 0, rest = code; k < 4; ++k, rest /= 5) entries[k] = rest % 5 - 2, cost += std::abs(entries[k]);
    const Mat2<Rational> A =
        (Eigen::Matrix2i() << entries[0], entries[1], entries[2], entries[3]).finished().cast<Rational>();
    if (det2(A) <= 0 || (best && cost >= best_cost)) continue;
    if (thm_2_2_1_condition<Rational>(A.trace(), det2(A)) && !good_for_area(A)) best = A, best_cost = cost;
  }
  return best;
}

Outcome check(const ClaimContext& ctx) {
  const Rational step = ctx.pick(Rational(1) / 4, Rational(1) / 16);
  // A with tr A = trace and det A = det: a(tr A − a) − bc = det A.
  Rng rng(ctx.seed);
  std::vector<Mat2<Rational>> cases;
  for (const Rational& trace : grid(-4, 6, step))
    for (const Rational& det : grid(step, 5, step)) {
      const Rational a = Rational(rng.integer(-4, 4)) / 2,
                     b = Rational(rng.integer(1, 3)) * (rng.integer(0, 1) ? 1 : -1);
      Mat2<Rational> A;
      A << a, b, (a * (trace - a) - det) / b, trace - a;
      cases.push_back(A);
    }
  const auto cost = [](const Mat2<Rational>& A) { return height(A.trace()) + height(det2(A)); };
  const auto identity = [](const Mat2<Rational>& A) { return A; };  // A_l(t) = (1−t)I + tA
  const auto [printed, corrected] = tally_area_conditions(cases, ctx.threads, identity, cost);

  Outcome outcome;
  outcome.evidence.method = "exact rational decision of Def 2.2.1 vs the printed condition over a (tr A, det A) grid";
  outcome.evidence.seed = ctx.seed;
  outcome.evidence.details["reading"] = area_reading;
  outcome.evidence.details["grid"] =
      "tr A in [-4, 6], det A in (0, 5], step " + exact::to_string(step) +
      "; A = [[a, b], [(a(tr-a)-det)/b, tr-a]] with random a in {-4..4}/2, b in +-{1,2,3}";
  decide_area_theorem(outcome, printed, corrected, "Thm 2.2.1 (linear)");
  if (printed.disagreements() > 0) {
    outcome.correction =
        "A_l(t) is good for area iff (2 det A <= tr A <= 2) or (2 <= tr A <= 2 det A): the slopes "
        "tr A - 2 (t = 0) and 2 det A - tr A (t = 1) of det A_l(t) must not differ in sign. Case (iii) "
        "of the proof divides by 1 - tr A + det A < 0 without reversing the inequalities.";
    const auto A = simplest_integer_counterexample();
    const Mat2<Rational> shown = A ? *A : *printed.condition_only.simplest;
    outcome.counterexample = {{"A", exact_matrix(shown)},
                              {"tr A", exact::to_string(shown.trace())},
                              {"det A", exact::to_string(det2(shown))},
                              {"printed_condition", true},
                              {"good_for_area", false},
                              {"witness", area_witness(shown)}};
  }
  const AreaParameters parameters = linear_parameters();
  ProofRun proof = run_proof(ctx, proof_plan());
  require_agreement(outcome, area_proof_verdict(proof));
  if (printed.disagreements() > 0) outcome.counterexample["from_proof"] = area_proof_counterexample(proof, parameters);
  attach_proof(outcome, std::move(proof));
  if (ctx.draws_figures())
    outcome.figures = draw_area_map<Mat2<Rational>>(
        ctx, "thesis-thm-2.2.1-region", "Thm 2.2.1 (linear interpolation): printed condition vs good for area", "tr A",
        "det A", cases,
        [](const Mat2<Rational>& A) {
          return std::pair{static_cast<double>(A.trace()), static_cast<double>(det2(A))};
        },
        identity, step);
  return outcome;
}

}  // namespace
}  // namespace affinterp::claims::local::thesis_thm_2_2_1
