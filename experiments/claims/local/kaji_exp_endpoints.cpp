#include "experiments/claims/claim.hpp"
#include "experiments/claims/confirmed_by_proof.hpp"
#include "experiments/claims/local/random_gl_plus.hpp"
#include "experiments/claims/local/rotation_lemma.hpp"
#include "experiments/proofs/ginac_scalar.hpp"
#include "experiments/proofs/identity.hpp"
#include "experiments/proofs/step_nodes.hpp"
#include "theory/local/local.hpp"

#include <algorithm>

namespace affinterp::claims::local::kaji_exp_endpoints {
namespace {

Outcome check(const ClaimContext& ctx);

const ClaimDeclaration claim{{
    .id = "kaji.exp.endpoints",
    .chapter = Chapter::local,
    .where = "Kaji eq. (3)",
    .statement = "The exp-log homotopy R_θ^t S^t equals I at t = 0 and A at t = 1.",
    .strength = Strength::grid,
    .check = check,
}};

// Reading: θ is any representative of the polar angle (Kaji §4 shifts it by 2πk), so the endpoints must hold
//   for every k.
// Method: A^E(t) = R_{tθ} S^t (Kaji eq. (3)) evaluated in Real50 at t = 0 and 1 on random A ∈ GL+(2), θ shifted
//   by 2πk, |k| ≤ 2; the worst of |A^E(0) − I| and the relative |A^E(1) − A| must stay below 1e-40.
//   Proof for every A = R_α D R_β and every θ (proof()): R_{tθ} S^t at t = 0 and 1 from theory/local's rotation and
//   spd_power over symbols (the composition ExpLogHomotopy::operator() runs; ExpLogHomotopy itself cannot take
//   symbols, its constructor calls svd(), i.e. atan2 and hypot), with the polar factors θ = α + β, S = R_{−β} D R_β
//   of polar_from_svd and the rotation lemma; θ is a free symbol, so every representative θ + 2πk is covered.
// Sizes: quick 100 matrices; full 2000.

using affinterp::local::ExpLogHomotopy;

Real50 relative_gap(const Mat2<Real50>& got, const Mat2<Real50>& want) { return (got - want).norm() / want.norm(); }

/// A^E(0) = I and A^E(1) = A over symbols α, β, x, y (A = R_α D R_β) and any angle θ of R_θ = R_{α+β}.
Proof proof(const ClaimContext& ctx) {
  using X = GiNaC::ex;
  using affinterp::local::rotation;
  using affinterp::local::spd_power;
  const GiNaC::symbol alpha("alpha"), beta("beta"), x("x"), y("y");
  const affinterp::local::Svd<X> A_svd{alpha, x, y, beta}, S_eigen{-X(beta), x, y, beta};
  const affinterp::local::Polar<X> polar = affinterp::local::polar_from_svd(A_svd);
  RotationLemma lemma;
  const auto rational = [&lemma](const Mat2<X>& M) { return lemma(proofs::to_ginac(M)); };
  // Kaji eq. (3) as ExpLogHomotopy::operator() composes it: A^E(t) = R_{tθ} S^t, the product left to the checkers.
  const auto A_E = [&](const X& t) {
    return proofs::product(rational(Mat2<X>(rotation<X>(t * polar.theta))), rational(spd_power(S_eigen, t)));
  };
  const std::vector<proofs::Identity> identities = {
      {"start", "R_{0·θ} S^0 = I", A_E(X(0)), proofs::to_ginac(affinterp::local::identity2<X>())},
      {"end", "R_{1·θ} S^1 = R_α D R_β = A", A_E(X(1)), rational(A_svd.matrix())},
  };
  return proofs::identity_proof(
      "every A = R_α D R_β (x ≥ y > 0, α, β real) and every representative θ of its polar angle",
      "identities over symbols from theory/local's rotation, spd_power and polar_from_svd, cos and sin by the "
      "addition formulas and the half-angle parametrisation; R_{θ+2πk} = R_θ. Not proved here: that svd() and "
      "polar_decomposition() (atan2, hypot), which ExpLogHomotopy calls, compute these factors (Real50 sample only)",
      proofs::prove_identities(identities, ctx.proof_files()));
}

Outcome check(const ClaimContext& ctx) {
  Rng rng(ctx.seed);
  const int samples = ctx.pick(100, 2000);
  Real50 worst = 0;
  for (int i = 0; i < samples; ++i) {
    const Mat2<Real50> A = random_gl_plus(rng, 1e3);
    const auto polar = affinterp::local::polar_decomposition(A);
    const int k = static_cast<int>(rng.integer(-2, 2));  // any representative θ + 2πk (Kaji §4)
    // Kaji eq. (3): A^E(t) = R_{tθ} S^t.
    const ExpLogHomotopy<Real50> A_E(polar.theta + 2 * k * affinterp::local::pi<Real50>(), polar.S);
    worst = std::max({worst, Real50((A_E(Real50(0)) - affinterp::local::identity2<Real50>()).norm()),
                      relative_gap(A_E(Real50(1)), A)});
  }
  Outcome outcome;
  outcome.evidence.method = "Real50 evaluation of A^E(t) = R_{t theta} S^t at t = 0 and 1";
  outcome.evidence.sample_size = static_cast<std::uint64_t>(samples);
  outcome.evidence.seed = ctx.seed;
  outcome.evidence.tolerance = 1e-40;
  outcome.evidence.worst_deviation = static_cast<double>(worst);
  outcome.evidence.details = {
      {"sample", "A = R_alpha diag(x, y) R_beta, x/y <= 1e3, det A in [1/16, 16], theta shifted by 2 pi k, |k| <= 2"},
      {"measure", "max(|A^E(0) - I|_F, |A^E(1) - A|_F / |A|_F)"}};
  const bool holds = worst < Real50("1e-40");
  outcome.verdict = holds ? Verdict::confirmed : Verdict::refuted;
  outcome.summary = holds ? "A^E(0) = I and A^E(1) = A on " + std::to_string(samples) +
                                " random A (Real50, any representative of theta)"
                          : "A^E misses an endpoint";
  outcome.proof = proof(ctx);
  if (holds) weigh_confirmation_against_proof(outcome, "every A = R_α D R_β and every representative of θ");
  return outcome;
}

}  // namespace
}  // namespace affinterp::claims::local::kaji_exp_endpoints
