#include "experiments/claims/claim.hpp"
#include "experiments/claims/confirmed_by_proof.hpp"
#include "experiments/claims/values.hpp"
#include "experiments/proofs/ginac_scalar.hpp"
#include "experiments/proofs/identity.hpp"
#include "experiments/proofs/step_nodes.hpp"
#include "theory/exact/rational.hpp"
#include "theory/local/goodness.hpp"
#include "theory/local/local.hpp"

#include <algorithm>

namespace affinterp::claims::local::kaji_linear_collapse {
namespace {

Outcome check(const ClaimContext& ctx);

const ClaimDeclaration claim{{
    .id = "kaji.linear.collapse",
    .chapter = Chapter::local,
    .where = "Kaji §3",
    .statement = "For A = −I the linear homotopy (1−t)I + tA is the zero matrix at t = 1/2.",
    .strength = Strength::grid,
    .check = check,
}};

// Reading: as printed; A = −I lies in GL+(2) (det A = 1), so the example is admissible.
// Method: exact rational evaluation of A^L(1/2) and of the coefficients of det A^L(t) = det((1−t)I + tA).
//   Proof (proof()): the same LinearHomotopy over symbols, A^L(1/2) = 0 and det A^L(t) = (1 − 2t)² for every t.
// Sizes: one matrix at either size.

using affinterp::local::blend_determinant;
using affinterp::local::det2;
using affinterp::local::Mat2;
using affinterp::local::Quadratic;
using exact::Rational;

/// A^L(1/2) = 0 and det A^L(t) = (1 − 2t)² for A = −I, from theory/local's LinearHomotopy over a symbol t.
Proof proof(const ClaimContext& ctx) {
  using X = GiNaC::ex;
  const GiNaC::symbol t("t");
  const affinterp::local::LinearHomotopy<X> A_L{Mat2<X>(-affinterp::local::identity2<X>())};
  // The steps left to the checkers: t = 1/2 substituted into A^L(t), the determinants of A^L(t) and of A.
  const GiNaC::matrix A_t = proofs::to_ginac<2, 2>(A_L(t));
  GiNaC::matrix half_way(2, 2);
  for (unsigned k = 0; k < 4; ++k) half_way(k / 2, k % 2) = proofs::substitution(A_t(k / 2, k % 2), t, X(1) / 2);
  const std::vector<proofs::Identity> identities = {
      {"collapse", "A^L(1/2) = 0 for A = −I", half_way, proofs::to_ginac<2, 2>(Mat2<X>::Constant(X(0)))},
      {"determinant", "det A^L(t) = (1 − 2t)² for A = −I", proofs::determinant_of(A_t), GiNaC::pow(1 - 2 * t, 2)},
      {"admissible", "det(−I) = 1 > 0", proofs::determinant_of(proofs::to_ginac<2, 2>(A_L.A)), X(1)},
  };
  return proofs::identity_proof(
      "A = −I and every real t",
      "identities over a symbol t from theory/local's LinearHomotopy, the substitution t = 1/2 "
      "and the determinants performed by each checker",
      proofs::prove_identities(identities, ctx.proof_files()));
}

Outcome check(const ClaimContext& ctx) {
  const Mat2<Rational> A = -affinterp::local::identity2<Rational>();
  const Mat2<Rational> half_way = affinterp::local::LinearHomotopy<Rational>{A}(Rational(1) / 2);
  const bool collapses =
      std::all_of(half_way.reshaped().begin(), half_way.reshaped().end(), [](const Rational& a) { return a == 0; });
  const Quadratic<Rational> det = blend_determinant(A);
  Outcome outcome;
  outcome.evidence.method = "exact rational evaluation";
  outcome.evidence.sample_size = 1;
  outcome.evidence.details = {{"A", exact_matrix(A)},
                              {"det A", exact::to_string(det2(A))},
                              {"A^L(1/2)", exact_matrix(half_way)},
                              {"det A^L(t) coefficients [c0, c1, c2]",
                               {exact::to_string(det.c0), exact::to_string(det.c1), exact::to_string(det.c2)}}};
  outcome.verdict = collapses && det2(A) > 0 ? Verdict::confirmed : Verdict::refuted;
  outcome.summary = collapses ? "A = -I is in GL+(2) (det 1) and A^L(1/2) = 0 exactly; det A^L(t) = (1 - 2t)^2"
                              : "A^L(1/2) is not 0 for A = -I";
  outcome.proof = proof(ctx);
  if (outcome.verdict == Verdict::confirmed) weigh_confirmation_against_proof(outcome, "A = −I and every t");
  return outcome;
}

}  // namespace
}  // namespace affinterp::claims::local::kaji_linear_collapse
