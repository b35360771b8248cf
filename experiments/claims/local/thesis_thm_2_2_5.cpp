#include "experiments/claims/claim.hpp"
#include "experiments/claims/local/condition_sweep.hpp"
#include "experiments/claims/local/local_proof.hpp"
#include "experiments/claims/local/norm_witness.hpp"
#include "experiments/claims/local/printed_conditions.hpp"
#include "experiments/claims/local/region_figure.hpp"
#include "experiments/claims/local/simple_values.hpp"
#include "experiments/proofs/citations.hpp"
#include "experiments/proofs/literal_formulations.hpp"
#include "theory/local/goodness.hpp"
#include "theory/local/thesis_conditions.hpp"

#include <tuple>
#include <vector>

namespace affinterp::claims::local::thesis_thm_2_2_5 {
namespace {

Outcome check(const ClaimContext& ctx);

const ClaimDeclaration claim{{
    .id = "thesis.thm-2.2.5",
    .chapter = Chapter::local,
    .where = "thesis Thm 2.2.5",
    .statement = "Polar interpolation with S = [[x, h], [h, y]] is good for norm exactly when (x−1)(y−1) ≥ h² and (x + "
                 "y ≥ 2 or both x, y in (0, 1]).",
    .strength = Strength::grid,
    .check = check,
}};

// Reading: "good for norm" (Def 2.2.2) = |A_p(t)v| weakly monotone on [0, 1] for every unit v; R_{tγ} is
//   orthogonal, so |A_p(t)v| = |((1−t)I + tS)v|.
// Method: proof for all reals: the printed condition against Def 2.2.2 as two sentences in x, y, h at
//   level N (Lemmas L3, L4, L6, L8), decided by QEPCAD B and Z3, with Lemma L3 as its own sentence and the
//   identities ½ d/dt ‖((1−t)I + tS)v‖² = vᵀPv at t = 0, vᵀQv at t = 1; a third sentence shows the second
//   conjunct implied by the first on the domain. Second formulations without Dines' theorem: the
//   directions (1, m), (0, 1) at levels D and E, each lemma a sentence (experiments/proofs/literal_formulations.hpp);
//   level L tried for the record. Second line: over an (x, y, h) grid with xy > h², the printed
//   condition against the exact decision of Def 2.2.2 (theory/local/goodness.hpp: it fails iff some v has P(v) < 0 <
//   Q(v), certified by Dines' theorem); a counterexample carries a rational direction where the norm dips. The figure
//   is the slice h = 1/2.
// Sizes: quick step 1/4; full step 1/16; x, y ∈ (0, 4], h ∈ [−4, 4]; the sentences are the same at both sizes.

using affinterp::local::good_for_norm;
using affinterp::local::thm_2_2_5_condition;

/// The proof: Def 2.2.2 at level N against the printed condition, in S = [[x, h], [h, y]] ≻ 0.
ProofPlan proof_plan() {
  const Polynomial x = var("x"), y = var("y"), h = var("h"), v1 = var("v1"), v2 = var("v2");
  const PolyMat2 S{{{x, h}, {h, y}}};
  const std::vector<std::string> variables{"x", "y", "h"};
  const Formula domain = logic::greater(x, 0) && logic::greater(y, 0) && logic::greater(det(S), 0);
  const Formula condition = thm_2_2_5_formula(x, y, h), good = norm_property(S, "N");
  // ½ q_v′(0) = vᵀPv and ½ q_v′(1) = vᵀQv, P = S − I (symmetric), Q = P + (S − I)² (Lemma L3's forms).
  const Polynomial half_slope =
      Polynomial(exact::Rational(1, 2)) * norm_squared_of_blend(S, v1, v2, "t").derivative("t");
  const Polynomial p11 = x - Polynomial(1), p22 = y - Polynomial(1);
  const Polynomial P = p11 * v1 * v1 + Polynomial(2) * h * v1 * v2 + p22 * v2 * v2;
  const Polynomial Q =
      P + (p11 * p11 + h * h) * v1 * v1 + Polynomial(2) * (p11 + p22) * h * v1 * v2 + (h * h + p22 * p22) * v2 * v2;
  const proofs::ConditionOnDomain printed{"printed.", variables, domain, condition, S};
  return {"S = [[x, h], [h, y]] real positive definite (every gamma)",
          "Def 2.2.2 for ((1-t)I + tS)v (R_{t gamma} is orthogonal, Lemma L5) at level N: ||.|| is monotone iff its "
          "square is (L4); 1/2 d/dt ||((1-t)I + tS)v||^2 = P(v) + t||(S - I)v||^2 is affine with slope >= 0 "
          "(identities), so monotone for v unless P(v) < 0 < Q(v) (Lemma L3, decided as its own sentence); "
          "homogeneous in v (L6); no such v iff Q <= 0 or P - nu Q >= 0 for some nu >= 0 (Dines 1941, L8). "
          "cond-not-prop and prop-not-cond empty = equivalent; second-conjunct-implied: (x-1)(y-1) >= h^2 alone "
          "implies x + y >= 2 or 0 < x, y <= 1 on the domain",
          {lemma_L3(), cond_not_prop("printed.", "N", variables, domain, condition, good),
           prop_not_cond("printed.", "N", variables, domain, condition, good),
           sentence("printed.second-conjunct-implied",
                    "a positive definite S with (x-1)(y-1) >= h^2 but neither x + y >= 2 nor 0 < x, y <= 1", variables,
                    domain && logic::greater_equal((x - Polynomial(1)) * (y - Polynomial(1)), h * h) &&
                        !(logic::greater_equal(x + y, 2) || (logic::less_equal(x, 1) && logic::less_equal(y, 1))))},
          {{"1/2 d/dt ||((1-t)I + tS)v||^2 at t = 0 is v^T P v", half_slope.substitute("t", 0) - P},
           {"1/2 d/dt ||((1-t)I + tS)v||^2 at t = 1 is v^T Q v", half_slope.substitute("t", 1) - Q},
           {"1/2 d/dt ||((1-t)I + tS)v||^2 is affine in t",
            half_slope - half_slope.substitute("t", 0) - var("t") * (Q - P)}},
          std::string(proofs::citations::dines),
          proofs::norm_directions(printed),
          {proofs::norm_directions_literal(printed)}};
}

/// The decided proof of Thm 2.2.5's "iff" (both directions empty: confirmed, else refuted) against the grid's
/// verdict, and whether its second conjunct is implied by the first on the domain (atlas.polar.norm).
void add_proof(const ClaimContext& ctx, Outcome& outcome) {
  ProofRun proof = run_proof(ctx, proof_plan());
  if (proof.decided())
    require_agreement(outcome, proof.result("printed.cond-not-prop.N") == "empty" &&
                                       proof.result("printed.prop-not-cond.N") == "empty"
                                   ? Verdict::confirmed
                                   : Verdict::refuted);
  if (proof.decided() && proof.result("printed.second-conjunct-implied") == "empty")
    outcome.summary += "; the second conjunct is implied by (x-1)(y-1) >= h^2 on the domain (atlas.polar.norm)";
  attach_proof(outcome, std::move(proof));
}

Outcome check(const ClaimContext& ctx) {
  const Rational step = ctx.pick(Rational(1) / 4, Rational(1) / 16);
  using Case = std::tuple<Rational, Rational, Rational>;  // S = [[x, h], [h, y]]
  std::vector<Case> cases;
  for (const Rational& x : grid(step, 4, step))
    for (const Rational& y : grid(step, 4, step))
      for (const Rational& h : grid(-4, 4, step))
        if (x * y > h * h) cases.emplace_back(x, y, h);
  const auto S_of = [](const Case& c) { return symmetric(std::get<0>(c), std::get<1>(c), std::get<2>(c)); };
  const auto condition = [](const Case& c) {
    return thm_2_2_5_condition(std::get<0>(c), std::get<1>(c), std::get<2>(c));
  };
  const auto property = [&](const Case& c) { return good_for_norm(S_of(c)); };
  const auto cost = [](const Case& c) {
    return height(std::get<0>(c)) + height(std::get<1>(c)) + height(std::get<2>(c));
  };
  const auto tally = compare_over(cases, ctx.threads, condition, property, cost);

  Outcome outcome;
  outcome.evidence.method =
      "exact rational decision of Def 2.2.2 for A_p(t) vs the printed condition over an (x, y, h) grid";
  outcome.evidence.sample_size = tally.cases;
  outcome.evidence.details["reading"] =
      "'good for norm' (Def 2.2.2) = |A_p(t)v| weakly monotone on [0, 1] for every unit v; |A_p(t)v| = |((1-t)I + "
      "tS)v| "
      "(R_{t gamma} is orthogonal). Decided exactly per S: fails iff some v has P(v) < 0 < Q(v), P = S - I, "
      "Q = (S - I) + (S - I)^2, certified by Dines' theorem (see theory/local/goodness.hpp).";
  outcome.evidence.details["grid"] = "x, y in (0, 4], h in [-4, 4], xy > h^2, step " + exact::to_string(step);
  outcome.evidence.details["printed_condition"] = tally.summary();
  if (tally.disagreements() == 0) {
    outcome.verdict = Verdict::confirmed;
    outcome.summary = "the printed condition matches the exact decision on all " + std::to_string(tally.cases) +
                      " grid cases (it says: both eigenvalues of S >= 1, or both <= 1)";
  } else {
    outcome.verdict = Verdict::refuted;
    outcome.summary = std::to_string(tally.condition_only.count) +
                      " cases satisfy the printed condition but are not good for norm, " +
                      std::to_string(tally.property_only.count) + " are good but fail it (of " +
                      std::to_string(tally.cases) + ")";
    const Case& c = tally.condition_only.simplest ? *tally.condition_only.simplest : *tally.property_only.simplest;
    outcome.counterexample = {{"x", exact::to_string(std::get<0>(c))}, {"y", exact::to_string(std::get<1>(c))},
                              {"h", exact::to_string(std::get<2>(c))}, {"printed_condition", condition(c)},
                              {"good_for_norm", property(c)},          {"witness", norm_witness(S_of(c))}};
  }
  add_proof(ctx, outcome);
  if (ctx.draws_figures()) {
    std::vector<plots::RegionPoint> points;
    for (const Case& c : cases)
      if (std::get<2>(c) == Rational(1) / 2)
        points.push_back(
            {static_cast<double>(std::get<0>(c)), static_cast<double>(std::get<1>(c)), condition(c), property(c)});
    outcome.figures =
        draw_region_figure(ctx, "thesis-thm-2.2.5-region",
                           "Thm 2.2.5 (polar interpolation), slice h = 1/2: printed condition vs good for norm", "x",
                           "y", points, static_cast<double>(step) / 2);
  }
  return outcome;
}

}  // namespace
}  // namespace affinterp::claims::local::thesis_thm_2_2_5
