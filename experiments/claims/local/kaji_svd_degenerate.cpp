#include "experiments/claims/claim.hpp"
#include "experiments/claims/local/local_proof.hpp"
#include "experiments/claims/local/quadratic_signs.hpp"
#include "experiments/claims/local/simple_values.hpp"
#include "experiments/support/random.hpp"
#include "theory/local/goodness.hpp"
#include "theory/local/local.hpp"

#include <algorithm>

namespace affinterp::claims::local::kaji_svd_degenerate {
namespace {

Outcome check(const ClaimContext& ctx);

const ClaimDeclaration claim{{
    .id = "kaji.svd.degenerate",
    .chapter = Chapter::local,
    .where = "Kaji §3",
    .statement = "The SVD-based homotopies of Alexa et al. can also reach a zero determinant at some real t.",
    .strength = Strength::grid,
    .check = check,
}};

// Reading: the SVD homotopy is A_s(t) = R_{tα}((1−t)I + tD)R_{tβ} of thesis Def 2.2.4 (the [ACOL00] variant we
//   have), t real, and A is not a rotation: for a rotation every homotopy here keeps det = 1.
// Method: det A_s(t) = det((1−t)I + tD) for all α, β: exact root analysis of that quadratic on an (x, y) grid,
//   then A_s evaluated in Real50 at the root t0 = 1/(1 − x) with random α, β must be singular.
//   Proof for all reals: one sentence in x, y, decided by QEPCAD B and Z3: no D = diag(x, y) ≠ I, x, y > 0, keeps
//   det((1−t)I + tD) ≠ 0 for every real t (det R = c² + s² = 1, Lemma L5, identity).
// Sizes: quick step 1/4; full step 1/32; the same sentence at both sizes.

using affinterp::local::blend_determinant;
using affinterp::local::det2;
using affinterp::local::Quadratic;
using exact::Real50;

/// The proof: every non-identity D = diag(x, y) ≻ 0 makes det A_s(t) vanish at some real t.
ProofPlan proof_plan() {
  const Polynomial x = var("x"), y = var("y"), c = var("c"), s = var("s");
  const PolyMat2 D{{{x, Polynomial(0)}, {Polynomial(0), y}}};
  return {
      "D = diag(x, y), x, y > 0 real, not both 1 (A not a rotation); every alpha, beta; t real",
      "det A_s(t) = det R_{t alpha} det((1-t)I + tD) det R_{t beta} with det R = c^2 + s^2 = 1 (Lemma L5, "
      "identity); the sentence empty = a real root exists for every such D",
      {sentence("never-zero", "x, y > 0 not both 1 with det((1-t)I + tD) != 0 for every real t", {"x", "y"},
                logic::greater(x, 0) && logic::greater(y, 0) && (logic::not_equal(x, 1) || logic::not_equal(y, 1)) &&
                    logic::forall({"t"}, logic::not_equal(det_of_blend(D, "t"), 0)))},
      {{"det R = c^2 + s^2", det(rotation(c, s)) - (c * c + s * s)}}};
}

Outcome check(const ClaimContext& ctx) {
  const Rational step = ctx.pick(Rational(1) / 4, Rational(1) / 32);
  Rng rng(ctx.seed);
  std::uint64_t cases = 0, non_degenerate = 0;
  Real50 worst = 0;
  for (const Rational& x : grid(step, 4, step))
    for (const Rational& y : grid(step, x, step)) {
      if (x == 1 && y == 1) continue;
      ++cases;
      const Quadratic<Rational> det = blend_determinant(diagonal(x, y));  // det A_s(t): det R_{tα} = det R_{tβ} = 1
      if (!has_real_root(det)) {
        ++non_degenerate;
        continue;
      }
      const Rational root = x != 1 ? 1 / (1 - x) : 1 / (1 - y);
      const affinterp::local::SvdHomotopy<Real50> A_s{
          {Real50(rng.uniform(-3.2, 3.2)), Real50(x), Real50(y), Real50(rng.uniform(-3.2, 3.2))}};
      worst = std::max(worst, Real50(abs(det2(A_s(Real50(root))))));
    }
  Outcome outcome;
  outcome.evidence.method = "exact rational root analysis of det((1-t)I + tD) + Real50 evaluation of A_s at the root";
  outcome.evidence.sample_size = cases;
  outcome.evidence.seed = ctx.seed;
  outcome.evidence.tolerance = 1e-40;
  outcome.evidence.worst_deviation = static_cast<double>(worst);
  outcome.evidence.details = {
      {"reading",
       "the SVD homotopy A_s(t) = R_{t alpha}((1-t)I + tD)R_{t beta} of thesis Def 2.2.4 (the [ACOL00] "
       "variant available to us), t real; A not a rotation (x, y not both 1); for a rotation every "
       "homotopy here keeps det = 1"},
      {"grid", "x >= y in (0, 4] step " + exact::to_string(step)},
      {"cases_without_real_root", non_degenerate},
      {"worst_|det A_s(t0)|_Real50", static_cast<double>(worst)}};
  const bool holds = non_degenerate == 0 && worst < Real50("1e-40");
  outcome.verdict = holds ? Verdict::confirmed : Verdict::refuted;
  outcome.summary = holds ? "det A_s(t) = ((x-1)t+1)((y-1)t+1) vanishes at a real t on all " + std::to_string(cases) +
                                " non-rotation cases; A_s(t0) evaluated in Real50 has |det| <= 1e-40"
                          : "some SVD homotopy never degenerates, or A_s(t0) is not singular";
  attach_proof(outcome, run_proof(ctx, proof_plan()));
  return outcome;
}

}  // namespace
}  // namespace affinterp::claims::local::kaji_svd_degenerate
