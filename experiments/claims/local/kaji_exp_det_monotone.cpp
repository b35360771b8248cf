#include "experiments/claims/claim.hpp"
#include "experiments/claims/local/local_proof.hpp"
#include "experiments/claims/local/random_gl_plus.hpp"
#include "experiments/proofs/citations.hpp"
#include "theory/local/local.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace affinterp::claims::local::kaji_exp_det_monotone {
namespace {

Outcome check(const ClaimContext& ctx);

const ClaimDeclaration claim{{
    .id = "kaji.exp.det-monotone",
    .chapter = Chapter::local,
    .where = "Kaji §3",
    .statement = "The exp-log homotopy's determinant is monotone in t: its derivative is identically zero when λ1λ2 = "
                 "1 and nowhere zero otherwise.",
    .strength = Strength::grid,
    .check = check,
}};

// Reading: "monotone" is strict unless λ1λ2 = 1, where det A^E(t) = 1 for all t.
// Method: in Real50 on a t grid over [−10, 10]: for det A = 1 (every fourth sample) det A^E(t) must stay 1; otherwise
//   consecutive values must move in the sign of log det A, and the central difference (h = 1e-15) must match
//   d/dt (λ1λ2)^t = log(λ1λ2)(λ1λ2)^t.
//   Proof for all reals: Lemma L10 (analytic): det A^E(t) = c^t with c = det S > 0, whose derivative is L c^t with
//   L = log c, where L has the sign of c − 1 and c^t > 0; the algebraic residue, two sentences in c, L, E = c^t
//   (and E2, c^t at another time) decided by QEPCAD B and Z3: L·E = 0 exactly when c = 1, and L·E never takes
//   both signs.
// Sizes: quick 50 matrices × 21 times; full 300 × 61; the same sentences at both sizes.

using affinterp::local::det2;
using affinterp::local::ExpLogHomotopy;

/// As random_gl_plus, with det A = 1 exactly up to Real50 rounding.
Mat2<Real50> random_unimodular(Rng& rng, double max_ratio) {
  const Real50 x = exp(Real50(rng.uniform(0, std::log(max_ratio)) / 2));
  return Svd<Real50>{Real50(rng.uniform(-std::numbers::pi, std::numbers::pi)), x, 1 / x,
                     Real50(rng.uniform(-std::numbers::pi, std::numbers::pi))}
      .matrix();
}

/// The proof's algebraic residue after Lemma L10.
ProofPlan proof_plan() {
  const Polynomial c = var("c"), L = var("L"), E = var("E"), E2 = var("E2");
  const auto iff = [](const Formula& a, const Formula& b) { return (a && b) || (!a && !b); };
  const Formula log_sign = iff(logic::greater(L, 0), logic::greater(c, 1)) &&
                           iff(logic::equal(L, 0), logic::equal(c, 1)) && iff(logic::less(L, 0), logic::less(c, 1));
  return {"c = det A = lambda1 lambda2 > 0 real, every real t",
          "Lemma L10 (analytic): det A^E(t) = c^t, d/dt c^t = L c^t with L = log c; log is increasing with log 1 = "
          "0, so L has the sign of c - 1, and E = c^t > 0. Both residue sentences empty = the derivative is "
          "identically 0 iff c = 1 and otherwise never 0 and of one sign (strictly monotone)",
          {sentence("derivative-zero-iff-det1-fails",
                    "c > 0, L = log c (by sign), E = c^t > 0 with L E = 0 not iff c = 1", {"c", "L", "E"},
                    logic::greater(c, 0) && logic::greater(E, 0) && log_sign &&
                        !iff(logic::equal(L * E, 0), logic::equal(c, 1))),
           sentence("derivative-sign-changes",
                    "c > 0 and two times (E = c^t, E2 = c^s > 0) where L c^t takes both signs", {"c", "L", "E", "E2"},
                    logic::greater(c, 0) && logic::greater(E, 0) && logic::greater(E2, 0) && log_sign &&
                        logic::less(L * E, 0) && logic::greater(L * E2, 0))},
          {},
          std::string(proofs::citations::exponential),
          {},
          {{.formulation = "det A^E(t) = (det S)^t monotone, as written",
            .sentences = {},
            .not_expressible = std::string(proofs::not_first_order_exponential)}}};
}

Outcome check(const ClaimContext& ctx) {
  Rng rng(ctx.seed);
  const int samples = ctx.pick(50, 300), times = ctx.pick(21, 61);
  const Real50 h("1e-15");
  Real50 worst_constant = 0, worst_derivative = 0;
  std::uint64_t wrong_direction = 0;
  for (int i = 0; i < samples; ++i) {
    const bool unimodular = i % 4 == 0;
    const Mat2<Real50> A = unimodular ? random_unimodular(rng, 10) : random_gl_plus(rng, 10);
    const ExpLogHomotopy<Real50> A_E = ExpLogHomotopy<Real50>::of(A);  // Kaji eq. (3)
    const Real50 log_det = log(det2(A));
    Real50 previous = 0;
    for (int j = 0; j < times; ++j) {
      const Real50 t = Real50(-10) + Real50(20) * j / (times - 1);
      const Real50 det = det2(A_E(t));
      if (unimodular) {
        worst_constant = std::max(worst_constant, Real50(abs(det - 1)));
      } else {
        if (j > 0) wrong_direction += (det - previous) * log_det <= 0;
        const Real50 derivative = (det2(A_E(t + h)) - det2(A_E(t - h))) / (2 * h),
                     expected = log_det * exp(t * log_det);
        worst_derivative = std::max(worst_derivative, Real50(abs(derivative - expected) / abs(expected)));
      }
      previous = det;
    }
  }
  Outcome outcome;
  outcome.evidence.method =
      "Real50 evaluation of det A^E(t) and its central difference (h = 1e-15) on a t grid over [-10, 10]";
  outcome.evidence.sample_size = static_cast<std::uint64_t>(samples) * times;
  outcome.evidence.seed = ctx.seed;
  outcome.evidence.tolerance = 1e-20;
  outcome.evidence.worst_deviation = static_cast<double>(std::max(worst_constant, worst_derivative));
  outcome.evidence.details = {
      {"sample", "every 4th A has det A = 1 (lambda1 lambda2 = 1), the others det A in [1/16, 16], x/y <= 10"},
      {"det_1_worst_|det A^E(t) - 1|", static_cast<double>(worst_constant)},
      {"derivative_worst_relative_deviation", static_cast<double>(worst_derivative)},
      {"steps_against_sign_of_log_det", wrong_direction}};
  const bool holds = wrong_direction == 0 && worst_constant < Real50("1e-40") && worst_derivative < Real50("1e-20");
  outcome.verdict = holds ? Verdict::confirmed : Verdict::refuted;
  outcome.summary =
      holds ? "det A^E(t) is constant 1 when lambda1 lambda2 = 1 and otherwise strictly monotone with derivative "
              "log(lambda1 lambda2)(lambda1 lambda2)^t != 0 at every sampled t (Real50)"
            : "det A^E(t) is not monotone as stated";
  attach_proof(outcome, run_proof(ctx, proof_plan()));
  return outcome;
}

}  // namespace
}  // namespace affinterp::claims::local::kaji_exp_det_monotone
