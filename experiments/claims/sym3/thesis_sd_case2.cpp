#include "experiments/claims/claim.hpp"
#include "experiments/claims/sym3/exact_spectrum.hpp"
#include "experiments/claims/sym3/sd_sweep.hpp"
#include "theory/sym3/spectral_decomposition.hpp"

namespace affinterp::claims::sym3 {
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
// Sizes: quick 20 matrices; full 200.

using exact::Real100;

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
  return confirmed_or_refuted(ctx, s, "case 2 (x = 0, y = s − t, z = tλ2 − sλ3)",
                              "λ1 = λ2 ≠ λ3, p/q with |p| ≤ 12, q ≤ 4, labelled with the repeated pair first");
}

}  // namespace
}  // namespace affinterp::claims::sym3
