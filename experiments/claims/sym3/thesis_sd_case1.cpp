#include "experiments/claims/claim.hpp"
#include "experiments/claims/confirmed_by_proof.hpp"
#include "experiments/claims/sym3/exact_spectrum.hpp"
#include "experiments/claims/sym3/sd_sweep.hpp"
#include "experiments/proofs/identity.hpp"
#include "experiments/proofs/step_nodes.hpp"
#include "theory/sym3/spectral_decomposition.hpp"

namespace affinterp::claims::sym3::thesis_sd_case1 {
namespace {

Outcome check(const ClaimContext& ctx);

const ClaimDeclaration claim{{
    .id = "thesis.sd.case1",
    .chapter = Chapter::sym3,
    .where = "thesis §3.1.2",
    .statement = "With a triple eigenvalue, exp S = e^{λ1} I.",
    .strength = Strength::grid,
    .check = check,
}};

// Reading: the case is for exactly equal eigenvalues; the 10⁻⁶ threshold of the algorithm is an accuracy matter
//   (thesis.exp.accuracy).
// Method: the printed x = y = 0, z = e^{λ1} at 100 digits on rational S = Q diag(λ, λ, λ) Qᵀ (sd_sweep.hpp).
//   Proof for every real λ1 (proof()): theory/sym3's case-1 coefficients over a symbol, xλ1² + yλ1 + z = e^{λ1}
//   (e^{λ1} an independent variable); S = λ1 E by the spectral theorem, so xS² + yS + zE = e^{λ1} E = exp S.
// Sizes: quick 10 matrices; full 100.

using exact::Real100;

/// xλ1² + yλ1 + z = e^{λ1} with theory/sym3's case-1 x, y, z over a symbol λ1.
Proof proof(const ClaimContext& ctx) {
  const GiNaC::symbol l1("l1"), lambda("lambda");
  const auto c = affinterp::sym3::sd_case1<GiNaC::ex>(l1);
  // p(λ) = xλ² + yλ + z at λ = l1: the substitution left to the checkers.
  const GiNaC::ex p_at_l1 = proofs::substitution(c.x * lambda * lambda + c.y * lambda + c.z, lambda, l1);
  return proofs::identity_proof(
      "every real λ1 (symmetric S with a triple eigenvalue, i.e. S = λ1 E)",
      "a rational identity in λ1 and e^λ1 (an independent variable on the grid) from theory/sym3's case 1 over "
      "symbols; exp S = xS² + yS + zE follows by Lemma L20 (the spectral theorem)",
      {proofs::prove_identity({"interpolates-at-l1", "x l1² + y l1 + z = exp(l1)", p_at_l1, GiNaC::exp(l1)},
                              ctx.proof_files())});
}

Outcome check(const ClaimContext& ctx) {
  Rng rng(ctx.seed);
  const Sweep s = sweep(
      rng, ctx.pick(10, 100),
      [](Rng& r) {
        const Rational a = eigenvalue(r);
        return Vec3Q(a, a, a);
      },
      [](const Real100& l1, const Real100&, const Real100&) {
        return affinterp::sym3::sd_case1(l1);  // thesis §3.1.2, case 1
      });
  Outcome out = confirmed_or_refuted(ctx, s, "case 1 (x = y = 0, z = e^{λ1})",
                                     "λ1 = λ2 = λ3 = p/q, |p| ≤ 12, q ≤ 4 (then S = λ1 E)");
  out.proof = proof(ctx);
  if (out.verdict == Verdict::confirmed) weigh_confirmation_against_proof(out, "every real triple eigenvalue λ1");
  return out;
}

}  // namespace
}  // namespace affinterp::claims::sym3::thesis_sd_case1
