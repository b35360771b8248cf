#include "experiments/claims/claim.hpp"
#include "experiments/claims/local/local_proof.hpp"
#include "experiments/claims/local/random_gl_plus.hpp"
#include "experiments/proofs/citations.hpp"
#include "plots/local/figures.hpp"
#include "theory/local/local.hpp"

#include <algorithm>
#include <string>

namespace affinterp::claims::local::kaji_exp_det_positive {
namespace {

Outcome check(const ClaimContext& ctx);

const ClaimDeclaration claim{{
    .id = "kaji.exp.det-positive",
    .chapter = Chapter::local,
    .where = "Kaji §3",
    .statement = "The exp-log homotopy has positive determinant for every real t.",
    .strength = Strength::grid,
    .check = check,
}};

// Reading: "every real t" is sampled on [−10, 10].
// Method: det A^E(t) = det R_{tθ} det S^t = λ1^t λ2^t = (det A)^t > 0 (Kaji §3). In Real50, det A^E(t) from the
//   matrix entries (ad − bc) is compared with (det A)^t on a t grid for random A; |t| ≤ 10 and x/y ≤ 10 keep the
//   cancellation in ad − bc below 10^10 of the 50 digits. Draws Kaji Fig. 1.
//   Proof for all reals: Lemma L10 (analytic): S = Q diag(λ1, λ2) Qᵀ ≻ 0 and S^t = Q diag(λ1^t, λ2^t) Qᵀ, so
//   det A^E(t) = det R_{tθ} λ1^t λ2^t = (det S)^t for every real t, positive when λ1, λ2 > 0; the algebraic
//   residue, one sentence decided by QEPCAD B and Z3: a positive definite S has no eigenvalue ≤ 0.
// Sizes: quick 50 matrices × 21 times; full 400 × 101; the same sentence at both sizes.

using affinterp::local::det2;
using affinterp::local::ExpLogHomotopy;

/// The proof's algebraic residue after Lemma L10.
ProofPlan proof_plan() {
  const Polynomial x = var("x"), y = var("y"), h = var("h"), l1 = var("l1"), l2 = var("l2");
  const Polynomial det_S = x * y - h * h;
  return {
      "S = [[x, h], [h, y]] real positive definite (A = R_theta S in GL+(2)), every real t",
      "Lemma L10 (analytic): det A^E(t) = det R_{t theta} det S^t = 1 * l1^t l2^t for the eigenvalues l1, l2 of S "
      "(the pair with l1 + l2 = tr S, l1 l2 = det S), and a real power of a positive real is positive; the "
      "residue sentence empty = both eigenvalues are positive",
      {sentence("eigenvalue-not-positive", "a positive definite S with an eigenvalue <= 0", {"x", "y", "h", "l1", "l2"},
                logic::greater(x, 0) && logic::greater(y, 0) && logic::greater(det_S, 0) &&
                    logic::equal(l1 + l2, x + y) && logic::equal(l1 * l2, det_S) &&
                    (logic::less_equal(l1, 0) || logic::less_equal(l2, 0)))},
      {},
      std::string(proofs::citations::exponential),
      {},
      {{.formulation = "det A^E(t) > 0 for every real t, as written",
        .sentences = {},
        .not_expressible = std::string(proofs::not_first_order_exponential)}}};
}

Outcome check(const ClaimContext& ctx) {
  Rng rng(ctx.seed);
  const int samples = ctx.pick(50, 400), times = ctx.pick(21, 101);
  Real50 worst = 0, smallest = 1;
  std::uint64_t non_positive = 0;
  for (int i = 0; i < samples; ++i) {
    const Mat2<Real50> A = random_gl_plus(rng, 10);
    const ExpLogHomotopy<Real50> A_E = ExpLogHomotopy<Real50>::of(A);  // Kaji eq. (3)
    for (int j = 0; j < times; ++j) {
      const Real50 t = Real50(-10) + Real50(20) * j / (times - 1);
      const Real50 det = det2(A_E(t)), expected = pow(det2(A), t);
      non_positive += !(det > 0);
      worst = std::max(worst, Real50(abs(det - expected) / expected));
      smallest = std::min(smallest, Real50(det / expected));
    }
  }
  Outcome outcome;
  outcome.evidence.method = "Real50 evaluation of det A^E(t) on a t grid over [-10, 10]";
  outcome.evidence.sample_size = static_cast<std::uint64_t>(samples) * times;
  outcome.evidence.seed = ctx.seed;
  outcome.evidence.tolerance = 1e-30;
  outcome.evidence.worst_deviation = static_cast<double>(worst);
  outcome.evidence.details = {
      {"sample", std::to_string(samples) + " random A (x/y <= 10, det A in [1/16, 16]) x " + std::to_string(times) +
                     " times t in [-10, 10]"},
      {"measure", "|det A^E(t) - (det A)^t| / (det A)^t, det from the matrix entries"},
      {"non_positive", non_positive},
      {"reason", "det A^E(t) = det R_{t theta} det S^t = 1 * lambda1^t lambda2^t > 0 (Kaji §3)"}};
  const bool holds = non_positive == 0 && worst < Real50("1e-30");
  outcome.verdict = holds ? Verdict::confirmed : Verdict::refuted;
  outcome.summary = holds ? "det A^E(t) = (det A)^t > 0 at every sampled t in [-10, 10] (Real50)"
                          : "det A^E(t) is not positive somewhere";
  attach_proof(outcome, run_proof(ctx, proof_plan()));
  if (ctx.draws_figures()) outcome.figures = ctx.figure_refs(plots::draw_kaji_figure_1(ctx.figure_dir));
  return outcome;
}

}  // namespace
}  // namespace affinterp::claims::local::kaji_exp_det_positive
