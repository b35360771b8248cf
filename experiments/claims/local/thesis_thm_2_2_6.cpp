#include "experiments/claims/claim.hpp"
#include "experiments/claims/local/area_theorem.hpp"
#include "experiments/claims/local/condition_sweep.hpp"
#include "experiments/claims/local/local_proof.hpp"
#include "experiments/claims/local/simple_values.hpp"
#include "experiments/claims/values.hpp"
#include "theory/local/goodness.hpp"

#include <tuple>

namespace affinterp::claims::local::thesis_thm_2_2_6 {
namespace {

Outcome check(const ClaimContext& ctx);

const ClaimDeclaration claim{{
    .id = "thesis.thm-2.2.6",
    .chapter = Chapter::local,
    .where = "thesis Thm 2.2.6",
    .statement = "SVD interpolation is good for area if and only if polar interpolation is.",
    .strength = Strength::grid,
    .check = check,
}};

// Reading: Def 2.2.1 as for Thm 2.2.1, for the SVD and the polar interpolation of the same A.
// Method: proof for all reals: with R_β = [[c, −s], [s, c]], c² + s² = 1 (every real β), and
//   S = R_βᵀ D R_β, two sentences "one good for area, the other not" in x, y, c, s at level E (Lemmas L1, L2, L5,
//   L11) and one "tr S ≠ tr D or det S ≠ det D" (the thesis's own route), decided by QEPCAD B and Z3; under the
//   full size also level D. Second line: A = R_α D R_β with R_β a rational rotation ((1 − u², 2u)/(1 + u²)), so the
//   polar factor S = R_βᵀ D R_β (thesis §2.2.3) is exact; α enters neither determinant. Over an (x, y, u) grid, good
//   for area of A_s(t) against that of A_p(t), and the stronger fact behind it: det A_s(t) and det A_p(t) are the same
//   polynomial.
// Sizes: quick (x, y) and u steps 1/2, sentences at level E; full 1/8, also level D; x ≥ y in (0, 4], u ∈ [−2, 2].

/// The proof: SVD and polar interpolation of A = R_α D R_β are good for area together, for every real x, y > 0, β.
ProofPlan proof_plan() {
  const Polynomial x = var("x"), y = var("y"), c = var("c"), s = var("s");
  const PolyMat2 D{{{x, Polynomial(0)}, {Polynomial(0), y}}}, R = rotation(c, s);
  const PolyMat2 S = product(product(transpose(R), D), R);  // the polar factor of A (Lemma L11)
  const std::vector<std::string> variables{"x", "y", "c", "s"};
  const Formula domain = logic::greater(x, 0) && logic::greater(y, 0) && logic::equal(c * c + s * s, 1);
  ProofPlan plan{
      "D = diag(x, y) with x, y > 0 and every real beta (R_beta = [[c, -s], [s, c]], c^2 + s^2 = 1); "
      "S = R_beta^T D R_beta, the polar factor of A = R_alpha D R_beta",
      "Def 2.2.1 for det A_s(t) = det((1-t)I + tD) and det A_p(t) = det((1-t)I + tS) (the rotations have "
      "det c^2 + s^2 = 1, Lemma L5; A = (R_alpha R_beta) S as R_beta R_beta^T = (c^2 + s^2) I, L11) at "
      "level E (Lemmas L1, L2, L2 decided as its own sentences): no point where exactly one is good; second "
      "formulation at level D (L1 as its own sentence); and the thesis's route: tr S = tr D and det S = det D wherever "
      "c^2 + s^2 = 1",
      {lemma_L2(), lemma_L2_area()},
      {{"R_beta R_beta^T = (c^2 + s^2) I (entry 11)", product(R, transpose(R))[0][0] - (c * c + s * s)},
       {"R_beta R_beta^T = (c^2 + s^2) I (entry 12)", product(R, transpose(R))[0][1]},
       {"det R_beta = c^2 + s^2", det(R) - (c * c + s * s)}}};
  plan.sentences.push_back(lemma_L1());
  const std::vector<std::string> levels{"E", "D"};
  for (const std::string& level : levels) {
    const Formula svd_good = area_property(D, level), polar_good = area_property(S, level);
    plan.sentences.push_back(sentence("svd-good-polar-not." + level,
                                      "x, y, beta where the SVD interpolation is good for area and the polar one not",
                                      variables, domain && svd_good && !polar_good));
    plan.sentences.push_back(sentence("polar-good-svd-not." + level,
                                      "x, y, beta where the polar interpolation is good for area and the SVD one not",
                                      variables, domain && !svd_good && polar_good));
  }
  // The second formulation: Def 2.2.1 as written for both homotopies (level L); the identities of L5 and L11 the only
  // lemmas.
  const Formula svd_literal = area_property(D, "L"), polar_literal = area_property(S, "L");
  plan.formulations.push_back(
      {"Def 2.2.1 as written (level L) for det A_s(t) = det((1-t)I + tD) and det A_p(t) = det((1-t)I + tS): "
       "positive for every t in [0, 1] and monotone for all 0 <= s <= t <= 1 (the rotations have det c^2 + s^2 = "
       "1, Lemma L5, and A = (R_alpha R_beta) S, L11: identities). No other lemma",
       {sentence("svd-good-polar-not.L",
                 "x, y, beta where the SVD interpolation is good for area and the polar one not", variables,
                 domain && svd_literal && !polar_literal),
        sentence("polar-good-svd-not.L",
                 "x, y, beta where the polar interpolation is good for area and the SVD one not", variables,
                 domain && !svd_literal && polar_literal)}});
  plan.sentences.push_back(
      sentence("trace-det-differ", "x, y, beta where tr S != tr D or det S != det D", variables,
               domain && (logic::not_equal(trace(S), trace(D)) || logic::not_equal(det(S), det(D)))));
  return plan;
}

Outcome check(const ClaimContext& ctx) {
  const Rational step = ctx.pick(Rational(1) / 2, Rational(1) / 8);
  const Rational u_step = ctx.pick(Rational(1) / 2, Rational(1) / 8);
  using Case = std::tuple<Rational, Rational, Rational>;  // (x, y, u)
  std::vector<Case> cases;
  for (const Rational& x : grid(step, 4, step))
    for (const Rational& y : grid(step, x, step))
      for (const Rational& u : grid(-2, 2, u_step)) cases.emplace_back(x, y, u);
  const auto S_of = [](const Case& c) {
    const Mat2<Rational> R = rational_rotation<Mat2<Rational>>(std::get<2>(c)), R_transposed = R.transpose();
    const Mat2<Rational> R_transposed_D = R_transposed.lazyProduct(diagonal(std::get<0>(c), std::get<1>(c)));
    const Mat2<Rational> S = R_transposed_D.lazyProduct(R);
    return S;
  };
  const auto cost = [](const Case& c) {
    return height(std::get<0>(c)) + height(std::get<1>(c)) + height(std::get<2>(c));
  };
  const auto tally = compare_over(
      cases, ctx.threads, [](const Case& c) { return good_for_area(diagonal(std::get<0>(c), std::get<1>(c))); },
      [&](const Case& c) { return good_for_area(S_of(c)); }, cost);
  // The stronger fact behind it: tr S = tr D and det S = det D, so the two det polynomials coincide.
  std::uint64_t polynomial_mismatches = 0;
  for (const Case& c : cases) {
    const auto p = affinterp::local::blend_determinant(diagonal(std::get<0>(c), std::get<1>(c)));
    const auto q = affinterp::local::blend_determinant(S_of(c));
    polynomial_mismatches += !(p.c0 == q.c0 && p.c1 == q.c1 && p.c2 == q.c2);
  }

  Outcome outcome;
  outcome.evidence.method =
      "exact rational decision of Def 2.2.1 for A_s(t) and A_p(t) of the same A over an (x, y, beta) grid";
  outcome.evidence.sample_size = tally.cases;
  outcome.evidence.details["reading"] = area_reading;
  outcome.evidence.details["grid"] = "x >= y > 0 in (0, 4] step " + exact::to_string(step) +
                                     "; beta = 2 atan(u), u in [-2, 2] step " + exact::to_string(u_step);
  outcome.evidence.details["svd_vs_polar"] = tally.summary();
  outcome.evidence.details["det_polynomial_mismatches"] = polynomial_mismatches;
  if (tally.disagreements() == 0 && polynomial_mismatches == 0) {
    outcome.verdict = Verdict::confirmed;
    outcome.summary = "A_s(t) and A_p(t) are good for area together on all " + std::to_string(tally.cases) +
                      " cases; det A_s(t) and det A_p(t) are the same polynomial (tr S = tr D, det S = det D). The "
                      "equivalence holds although the conditions of Thms 2.2.2/2.2.4 it is derived from are wrong.";
  } else {
    outcome.verdict = Verdict::refuted;
    outcome.summary = std::to_string(tally.disagreements()) + " cases where exactly one of A_s, A_p is good for area";
    const Case& c = tally.condition_only.simplest ? *tally.condition_only.simplest : *tally.property_only.simplest;
    outcome.counterexample = {{"x", exact::to_string(std::get<0>(c))},
                              {"y", exact::to_string(std::get<1>(c))},
                              {"u", exact::to_string(std::get<2>(c))},
                              {"S", exact_matrix(S_of(c))}};
  }
  attach_proof(outcome, run_proof(ctx, proof_plan()));
  return outcome;
}

}  // namespace
}  // namespace affinterp::claims::local::thesis_thm_2_2_6
