#include "experiments/claims/claim.hpp"
#include "experiments/claims/sym3/exact_spectrum.hpp"
#include "experiments/claims/sym3/sd_sweep.hpp"
#include "theory/sym3/spectral_decomposition.hpp"

namespace affinterp::claims::sym3 {
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
// Sizes: quick 10 matrices; full 100.

using exact::Real100;

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
  return confirmed_or_refuted(ctx, s, "case 1 (x = y = 0, z = e^{λ1})",
                              "λ1 = λ2 = λ3 = p/q, |p| ≤ 12, q ≤ 4 (then S = λ1 E)");
}

}  // namespace
}  // namespace affinterp::claims::sym3
