#include "experiments/claims/claim.hpp"
#include "experiments/claims/confirmed_by_proof.hpp"
#include "experiments/claims/local/rotation_lemma.hpp"
#include "experiments/claims/local/simple_values.hpp"
#include "experiments/proofs/ginac_scalar.hpp"
#include "experiments/proofs/identity.hpp"
#include "experiments/proofs/step_nodes.hpp"
#include "theory/local/local.hpp"

#include <algorithm>
#include <vector>

namespace affinterp::claims::local::kaji_appendix_polar_from_svd {
namespace {

Outcome check(const ClaimContext& ctx);

const ClaimDeclaration claim{{
    .id = "kaji.appendix.polar-from-svd",
    .chapter = Chapter::local,
    .where = "Kaji Appendix",
    .statement = "Given the SVD A = R_α D R_β, the polar factors are R_θ = R_{α+β} and S = R_{−β} D R_β, and S^t = "
                 "R_{−β} D^t R_β.",
    .strength = Strength::grid,
    .check = check,
}};

// Reading: as printed, with S^t for real t read as R_{−β} D^t R_β.
// Method: A = R_α D R_β with rational rotations, so R_{α+β} = R_α R_β and S = R_βᵀ D R_β are exact: A = R_{α+β} S,
//   S symmetric positive definite and S^n = R_βᵀ D^n R_β (n = 2, 3) are identities over ℚ. On a subset, in Real50,
//   the direct polar decomposition gives the same R_θ and S, and (R_βᵀ D^{2/3} R_β)³ = S².
//   Proof for every α, β, x, y (proof()): theory/local's polar_from_svd and spd_power over symbols, the rotations
//   made rational by the rotation lemma (addition formulas, half-angle parametrisation): A = R_{α+β} S, S symmetric
//   with trace x + y and determinant xy (so positive definite when x ≥ y > 0), S R_{−β} = R_{−β} D with R_{−β}
//   orthogonal, and spd_power at t = 1, 2 is S, S². Not symbolic: that svd() and polar_decomposition() (atan2,
//   hypot) find these factors, and S^t for non-integer t, which is the spectral power R_{−β} D^t R_{−β}ᵀ by
//   definition once S R_{−β} = R_{−β} D; the Real50 part covers those on the grid.
// Sizes: quick (x, y) step 1/2; full step 1/8; rotations u ∈ [−2, 2] step 1/2 at both.

using affinterp::local::det2;
using affinterp::local::Mat2;
using affinterp::local::Svd;
using exact::Real50;

Mat2<Rational> product(const Mat2<Rational>& a, const Mat2<Rational>& b) { return a.lazyProduct(b); }

/// The identities of the proof, over symbols α, β, x, y: theory/local's polar factors of A = R_α D R_β.
Proof proof(const ClaimContext& ctx) {
  using X = GiNaC::ex;
  const GiNaC::symbol alpha("alpha"), beta("beta"), x("x"), y("y");
  const Svd<X> A_svd{alpha, x, y, beta}, S_eigen{-X(beta), x, y, beta};  // A = R_α D R_β, S = R_{−β} D R_β
  const affinterp::local::Polar<X> polar = affinterp::local::polar_from_svd(A_svd);
  const Mat2<X> R_theta = affinterp::local::rotation<X>(polar.theta),
                R_minus_beta = affinterp::local::rotation<X>(-beta), R_beta = affinterp::local::rotation<X>(beta),
                D = A_svd.D(), S = polar.S;
  RotationLemma lemma;
  const auto rational = [&lemma](const Mat2<X>& M) { return lemma(proofs::to_ginac(M)); };
  // The products, transposes and determinants are left to the checkers; S and S^t are theory/local's.
  const auto times = [&rational](const Mat2<X>& a, const Mat2<X>& b) {
    return proofs::product(rational(a), rational(b));
  };
  const GiNaC::ex R_minus_beta_D_R_beta =
      proofs::product({rational(R_minus_beta), rational(D), rational(R_beta)});  // S by its definition
  const std::vector<proofs::Identity> identities = {
      {"polar-product", "R_θ S = R_α D R_β with θ = α + β, S = R_{−β} D R_β", times(R_theta, S),
       proofs::product({rational(affinterp::local::rotation<X>(alpha)), rational(D), rational(R_beta)})},
      {"symmetric", "S = S^T", rational(S), proofs::transposed(rational(S))},
      {"trace", "tr S = x + y", lemma(S.trace()), x + y},
      {"determinant", "det S = x y", proofs::determinant_of(rational(S)), x * y},
      {"orthogonal", "R_{−β} R_β = I", times(R_minus_beta, R_beta), proofs::to_ginac(affinterp::local::identity2<X>())},
      {"eigenvectors", "S R_{−β} = R_{−β} D", times(S, R_minus_beta), times(R_minus_beta, D)},
      {"power-one", "S^t at t = 1 is S = R_{−β} D R_β", rational(affinterp::local::spd_power(S_eigen, X(1))),
       R_minus_beta_D_R_beta},
      {"power-two", "S^t at t = 2 is S S", rational(affinterp::local::spd_power(S_eigen, X(2))), times(S, S)},
  };
  return proofs::identity_proof(
      "every A = R_α D R_β, D = diag(x, y), x ≥ y > 0, α and β real",
      "identities over symbols from theory/local's polar_from_svd and spd_power, cos and sin of the angles by the "
      "addition formulas and the half-angle parametrisation (a polynomial identity in cos, sin on the circle minus "
      "one point holds on the circle); a symmetric S with positive trace and determinant is positive definite; S^t "
      "for real t is R_{−β} D^t R_{−β}ᵀ by the spectral definition once S R_{−β} = R_{−β} D, R_{−β} orthogonal (Lemma "
      "L20: S^t does not depend on the decomposition). Not "
      "proved here: that svd() and polar_decomposition() (atan2, hypot) compute these factors (Real50 grid only)",
      proofs::prove_identities(identities, ctx.proof_files()));
}

/// Kaji Appendix, exactly for A = R_α D R_β with rational rotations: A = R_{α+β} S with S = R_{−β} D R_β
/// symmetric positive definite, and S^n = R_{−β} D^n R_β for n = 2, 3 (the spectral powers S^t agree with D^t).
bool exact_identities_hold(const Mat2<Rational>& R_alpha, const Mat2<Rational>& R_beta, const Mat2<Rational>& D) {
  const Mat2<Rational> R_beta_T = R_beta.transpose();
  const Mat2<Rational> A = product(product(R_alpha, D), R_beta), S = product(product(R_beta_T, D), R_beta);
  bool ok = affinterp::local::exactly_equal(product(product(R_alpha, R_beta), S), A) && S(0, 1) == S(1, 0) &&
            S(0, 0) > 0 && det2(S) > 0;
  Mat2<Rational> S_power = S, D_power = D;
  for (int n = 2; n <= 3; ++n) {
    S_power = product(S_power, S), D_power = product(D_power, D);
    ok = ok && affinterp::local::exactly_equal(S_power, product(product(R_beta_T, D_power), R_beta));
  }
  return ok;
}

/// The largest deviation in Real50 of the library's factors from the Appendix's: polar_decomposition(A) against
/// R_{α+β} and S, and the fractional power (R_{−β} D^{2/3} R_β)^3 against S² (β = 2 atan u_β).
Real50 real50_deviation(const Mat2<Rational>& R_alpha, const Mat2<Rational>& R_beta, const Rational& x,
                        const Rational& y, const Rational& u_beta) {
  const auto to50 = [](const Mat2<Rational>& M) {
    return Mat2<Real50>(M.unaryExpr([](const Rational& q) { return Real50(q); }));
  };
  const Mat2<Rational> D = diagonal(x, y), A = product(product(R_alpha, D), R_beta),
                       S = product(product(R_beta.transpose(), D), R_beta);
  const auto polar = affinterp::local::polar_decomposition(to50(A));
  Real50 worst = (polar.S - to50(S)).norm() / to50(S).norm();
  worst = std::max(worst, Real50((affinterp::local::rotation(polar.theta) - to50(product(R_alpha, R_beta))).norm()));
  const Real50 beta = 2 * atan(Real50(u_beta));  // R_β = rational_rotation(u_β)
  const Svd<Real50> S_eigen{-beta, Real50(x), Real50(y), beta};
  const Mat2<Real50> root3 = affinterp::local::spd_power(S_eigen, Real50(2) / 3);  // S^{2/3}
  return std::max(worst, Real50((root3 * root3 * root3 - to50(product(S, S))).norm() / to50(product(S, S)).norm()));
}

Outcome check(const ClaimContext& ctx) {
  const Rational step = ctx.pick(Rational(1) / 2, Rational(1) / 8);
  const std::vector<Rational> rotations = grid(-2, 2, Rational(1) / 2);
  std::uint64_t cases = 0, failures = 0;
  Real50 worst = 0;
  for (const Rational& x : grid(step, 3, step))
    for (const Rational& y : grid(step, x, step))
      for (const Rational& u_alpha : rotations)
        for (const Rational& u_beta : rotations) {
          ++cases;
          const Mat2<Rational> R_alpha = rational_rotation<Mat2<Rational>>(u_alpha),
                               R_beta = rational_rotation<Mat2<Rational>>(u_beta);
          failures += !exact_identities_hold(R_alpha, R_beta, diagonal(x, y));
          if (u_alpha != Rational(1) / 2 && u_alpha != -1) continue;  // Real50 part on a subset
          worst = std::max(worst, real50_deviation(R_alpha, R_beta, x, y, u_beta));
        }
  Outcome outcome;
  outcome.evidence.method =
      "exact rational identities with rational rotations + Real50 comparison with the direct polar decomposition";
  outcome.evidence.sample_size = cases;
  outcome.evidence.tolerance = 1e-40;
  outcome.evidence.worst_deviation = static_cast<double>(worst);
  outcome.evidence.details = {
      {"grid", "x >= y in (0, 3] step " + exact::to_string(step) +
                   "; R_alpha, R_beta with cos = (1-u^2)/(1+u^2), "
                   "sin = 2u/(1+u^2), u in [-2, 2] step 1/2"},
      {"exact_failures", failures},
      {"checked",
       "A = R_{alpha+beta} S; S symmetric positive definite; S^n = R_{-beta} D^n R_beta (n = 2, 3); "
       "Real50: polar_decomposition(A) gives the same R_theta and S; (R_{-beta} D^{2/3} R_beta)^3 = S^2"}};
  const bool holds = failures == 0 && worst < Real50("1e-40");
  outcome.verdict = holds ? Verdict::confirmed : Verdict::refuted;
  outcome.summary =
      holds ? "R_theta = R_{alpha+beta}, S = R_{-beta} D R_beta and S^t = R_{-beta} D^t R_beta hold on all " +
                  std::to_string(cases) +
                  " cases (exact; Real50 for the fractional power and the direct polar decomposition)"
            : "the Appendix's formulas fail on some case";
  outcome.proof = proof(ctx);
  if (holds) weigh_confirmation_against_proof(outcome, "every A = R_α D R_β with x ≥ y > 0");
  return outcome;
}

}  // namespace
}  // namespace affinterp::claims::local::kaji_appendix_polar_from_svd
