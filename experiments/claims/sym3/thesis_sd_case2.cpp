#include "experiments/claims/claim.hpp"
#include "experiments/claims/confirmed_by_proof.hpp"
#include "experiments/claims/sym3/exact_spectrum.hpp"
#include "experiments/claims/sym3/sd_sweep.hpp"
#include "experiments/proofs/identity.hpp"
#include "experiments/proofs/step_nodes.hpp"
#include "theory/sym3/spectral_decomposition.hpp"

namespace affinterp::claims::sym3::thesis_sd_case2 {
namespace {

Outcome check(const ClaimContext& ctx);

const ClaimDeclaration claim{{
    .id = "thesis.sd.case2",
    .chapter = Chapter::sym3,
    .where = "thesis §3.1.2",
    .statement = "With exactly two equal eigenvalues, the printed coefficients x = 0, y = s − t, z = tλ2 − sλ3 give "
                 "exp S = xS² + yS + zI.",
    .strength = Strength::grid,
    .check = check,
}};

// Reading: exactly two equal eigenvalues, labelled with the repeated pair first (λ1 = λ2 ≠ λ3).
// Method: the printed x = 0, y = s − t, z = tλ2 − sλ3 at 100 digits on rational S = Q diag(λ1, λ1, λ3) Qᵀ
//   (sd_sweep.hpp).
//   Proof for all real λ2 ≠ λ3 (proof()): theory/sym3's case-2 coefficients over symbols, xλ² + yλ + z = e^λ at
//   λ = λ2 and λ3 (e^{λ2}, e^{λ3} independent variables); S = Q diag(λ2, λ2, λ3) Qᵀ (spectral theorem: a symmetric
//   S is diagonalisable, so no derivative condition at the double eigenvalue), hence xS² + yS + zE = exp S.
// Sizes: quick 20 matrices; full 200.

using exact::Real100;

/// xλ² + yλ + z = e^λ at λ2 and λ3 with theory/sym3's case-2 x, y, z over symbols λ2, λ3.
Proof proof(const ClaimContext& ctx) {
  const GiNaC::symbol l2("l2"), l3("l3"), lambda("lambda");
  const auto c = affinterp::sym3::sd_case2<GiNaC::ex>(l2, l3);
  const GiNaC::ex p = c.x * lambda * lambda + c.y * lambda + c.z;  // p(λ), substituted by the checkers
  std::vector<proofs::Identity> identities;
  for (const GiNaC::symbol& l : {l2, l3})
    identities.push_back({"interpolates-at-" + l.get_name(),
                          "x " + l.get_name() + "² + y " + l.get_name() + " + z = exp(" + l.get_name() + ")",
                          proofs::substitution(p, lambda, l), GiNaC::exp(l)});
  return proofs::identity_proof(
      "all real λ1 = λ2 ≠ λ3 (symmetric S with exactly two equal eigenvalues)",
      "rational identities in λ2, λ3 and e^λ2, e^λ3 (independent variables on the grid) from theory/sym3's case 2 "
      "over symbols: the coefficients interpolate exp on the spectrum; exp S = xS² + yS + zE follows by the "
      "spectral theorem (S symmetric is diagonalisable, Lemma L20)",
      proofs::prove_identities(identities, ctx.proof_files()));
}

Outcome check(const ClaimContext& ctx) {
  Rng rng(ctx.seed);
  const Sweep s = sweep(
      rng, ctx.pick(20, 200),
      [](Rng& r) {
        const Rational a = eigenvalue(r);
        Rational b = eigenvalue(r);
        while (b == a) b = eigenvalue(r);
        return Vec3Q(a, a, b);
      },
      [](const Real100&, const Real100& l2, const Real100& l3) {
        return affinterp::sym3::sd_case2(l2, l3);  // thesis §3.1.2, case 2
      });
  Outcome out = confirmed_or_refuted(ctx, s, "case 2 (x = 0, y = s − t, z = tλ2 − sλ3)",
                                     "λ1 = λ2 ≠ λ3, p/q with |p| ≤ 12, q ≤ 4, labelled with the repeated pair first");
  out.proof = proof(ctx);
  if (out.verdict == Verdict::confirmed) weigh_confirmation_against_proof(out, "all real λ1 = λ2 ≠ λ3");
  return out;
}

}  // namespace
}  // namespace affinterp::claims::sym3::thesis_sd_case2
