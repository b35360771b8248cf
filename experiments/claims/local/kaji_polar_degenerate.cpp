#include "experiments/claims/claim.hpp"
#include "experiments/claims/local/quadratic_signs.hpp"
#include "experiments/claims/local/simple_values.hpp"
#include "experiments/claims/values.hpp"
#include "theory/local/goodness.hpp"

#include <optional>
#include <utility>

namespace affinterp::claims::local {
namespace {

Outcome check(const ClaimContext& ctx);

const ClaimDeclaration claim{{
    .id = "kaji.polar.degenerate",
    .chapter = Chapter::local,
    .where = "Kaji §3",
    .statement = "Unless both singular values equal 1, the polar homotopy's determinant is negative at some real t.",
    .strength = Strength::exact_counterexample,
    .check = check,
}};

// Reading: t ranges over all of ℝ, as in Kaji's homotopies; det A^P(t) = det((1−t)I + tS) (kaji.polar.det), so
//   only the eigenvalues λ1, λ2 of S matter and S = diag(λ1, λ2) stands for every S.
// Method: exact sign analysis of the quadratic det A^P(t) over all real t on a (λ1, λ2) grid; where it never
//   goes negative, the simplest such case is the counterexample, and the correction (it vanishes somewhere,
//   and is negative somewhere iff λ1 ≠ λ2) is tested on the same grid.
// Sizes: quick step 1/4; full step 1/32.

using affinterp::local::blend_determinant;
using affinterp::local::Quadratic;

Outcome check(const ClaimContext& ctx) {
  const Rational step = ctx.pick(Rational(1) / 4, Rational(1) / 32);
  std::uint64_t cases = 0, never_negative = 0, corrected_failures = 0;
  std::optional<std::pair<Rational, Rational>> simplest;
  for (const Rational& lambda1 : grid(step, 4, step))
    for (const Rational& lambda2 : grid(step, 4, step)) {
      if (lambda1 == 1 && lambda2 == 1) continue;
      ++cases;
      const Quadratic<Rational> det = blend_determinant(diagonal(lambda1, lambda2));  // = det A^P(t), kaji.polar.det
      if (!takes_negative_value(det)) {
        ++never_negative;
        if (!simplest || height(lambda1) + height(lambda2) < height(simplest->first) + height(simplest->second))
          simplest = std::pair{lambda1, lambda2};
      }
      // The correction: det A^P vanishes at some real t; it is negative somewhere iff λ1 ≠ λ2.
      corrected_failures += !has_real_root(det) || takes_negative_value(det) != (lambda1 != lambda2);
    }
  Outcome outcome;
  outcome.evidence.method = "exact rational sign analysis of det A^P(t) over all real t on a (lambda1, lambda2) grid";
  outcome.evidence.sample_size = cases;
  outcome.evidence.details = {
      {"reading", "t ranges over all of R, as in Kaji's homotopies; det A^P(t) = det((1-t)I + tS)"},
      {"grid", "lambda1, lambda2 in (0, 4] step " + exact::to_string(step) + ", not both 1"},
      {"never_negative", never_negative},
      {"corrected_statement_failures", corrected_failures}};
  if (never_negative == 0) {
    outcome.verdict = Verdict::confirmed;
    outcome.summary = "det A^P(t) < 0 for some real t on all " + std::to_string(cases) + " cases";
  } else {
    outcome.verdict = corrected_failures == 0 ? Verdict::corrected : Verdict::refuted;
    outcome.summary = std::to_string(never_negative) + " of " + std::to_string(cases) +
                      " cases never go negative: exactly those with lambda1 = lambda2 != 1, where det A^P(t) = "
                      "((lambda-1)t+1)^2 >= 0 "
                      "only touches 0; degeneracy (det = 0 at t = 1/(1-lambda_i)) holds in every case";
    outcome.correction =
        "det A^P(t) vanishes at t = 1/(1 - lambda_i) for some real t whenever lambda1 != 1 or lambda2 != 1 (so A^P "
        "degenerates); it becomes negative for some t iff moreover lambda1 != lambda2.";
    const auto& [l1, l2] = *simplest;
    const Quadratic<Rational> det = blend_determinant(diagonal(l1, l2));
    outcome.counterexample = {{"A", exact_matrix(diagonal(l1, l2))},
                              {"theta", "0"},
                              {"lambda1", exact::to_string(l1)},
                              {"lambda2", exact::to_string(l2)},
                              {"det A^P(t) coefficients [c0, c1, c2]",
                               {exact::to_string(det.c0), exact::to_string(det.c1), exact::to_string(det.c2)}},
                              {"discriminant", exact::to_string(det.c1 * det.c1 - 4 * det.c0 * det.c2)},
                              {"note", "a perfect square with positive leading coefficient: >= 0 for every real t"}};
  }
  return outcome;
}

}  // namespace
}  // namespace affinterp::claims::local
