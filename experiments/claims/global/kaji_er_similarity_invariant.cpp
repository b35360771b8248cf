#include "experiments/claims/claim.hpp"
#include "experiments/claims/global/exact_global.hpp"
#include "experiments/claims/global/symbolic_er.hpp"
#include "experiments/claims/proof_strength.hpp"
#include "experiments/claims/values.hpp"
#include "experiments/proofs/identity.hpp"

namespace affinterp::claims::kaji_er_similarity_invariant {
namespace {

Outcome check(const ClaimContext& ctx);

const ClaimDeclaration claim{{
    .id = "kaji.er.similarity-invariant",
    .chapter = Chapter::global,
    .where = "Kaji §4",
    .statement = "E^R(A, B) does not change when A is replaced by s R_δ A.",
    .strength = Strength::sample,
    .check = check,
}};

// Reading: invariance in the first argument A (the local homotopy). In B, E^R(A, CB) = |det C| E^R(A, B) is scaled,
//   not invariant; the evidence says so.
// Method: exact rational E^R(C A, B) against E^R(A, B) for random A, B and similarities C = xI + yJ ≠ 0.
//   Proof for all A ≠ 0, B and C = xI + yJ ≠ 0: two identities over symbols from theory/global's E^R (proof()).
// Sizes: quick 200 triples; full 5000.

using global_exact::Mat2Q;
using global_exact::Rational;

/// The proof for all A ≠ 0, B and every similarity C = xI + yJ ≠ 0 (= s R_δ, s ≠ 0):
///   ‖CA‖² = (x² + y²)‖A‖²        (norm-scales: CA ≠ 0, so E^R(CA, B) is defined)
///   E^R(CA, B) = E^R(A, B)       (invariant: a rational identity in a, b, x, y, from theory/global's E^R).
Proof proof(const ClaimContext& ctx) {
  const symbolic_er::Pair p;
  const GiNaC::symbol x("x"), y("y");
  const symbolic_er::Mat2X CA = symbolic_er::times(symbolic_er::similarity(x, y), p.A);  // the product a step
  const std::vector<proofs::Identity> identities = {
      {"norm-scales", "‖(xI + yJ)A‖² = (x² + y²)‖A‖²", symbolic_er::norm2(CA),
       (x * x + y * y) * symbolic_er::norm2(p.A)},
      {"invariant", "E^R((xI + yJ)A, B) = E^R(A, B) wherever both are defined", symbolic_er::E_R(CA, p.B),
       symbolic_er::E_R(p.A, p.B)},
  };
  return proofs::identity_proof("all real 2×2 A ≠ 0 and B, every similarity s R_δ = xI + yJ ≠ 0",
                                "identities over symbols from theory/global's E^R: ‖CA‖² = (x² + y²)‖A‖² > 0, and "
                                "E^R(CA, B) = E^R(A, B) as rational functions",
                                proofs::prove_identities(identities, ctx.proof_files()));
}

Outcome check(const ClaimContext& ctx) {
  Outcome out;
  Rng rng(ctx.seed);
  const int samples = ctx.pick(200, 5000);
  for (int k = 0; k < samples; ++k) {
    const Mat2Q A = global_exact::random_matrix(rng, 9, 4, true), B = global_exact::random_matrix(rng, 9, 4, false);
    Rational x, y;  // s R_δ = xI + yJ, any (x, y) ≠ 0
    do x = Rational(rng.integer(-9, 9)) / 4, y = Rational(rng.integer(-9, 9)) / 4;
    while (x == 0 && y == 0);
    const Mat2Q C = local::scaled(x, Mat2Q::Identity()) + local::scaled(y, global::rotation_J<Rational>());
    if (global::similarity_error<Rational>(C.lazyProduct(A), B) != global::similarity_error(A, B)) {
      out.verdict = Verdict::refuted;
      out.summary = "E^R(sR_δA, B) ≠ E^R(A, B)";
      out.counterexample = {{"A", exact_matrix(A)}, {"B", exact_matrix(B)}, {"sR_delta", exact_matrix(C)}};
      return out;
    }
  }
  out.verdict = Verdict::confirmed;
  out.summary = "E^R(sR_δ A, B) = E^R(A, B) exactly for every similarity sR_δ ≠ 0 tried (span{CA, JCA} = span{A, JA})";
  out.evidence.method = "exact rational computation with s R_δ = xI + yJ, x, y rational";
  out.evidence.sample_size = static_cast<std::uint64_t>(samples);
  out.evidence.seed = ctx.seed;
  out.evidence.worst_deviation = 0.0;
  out.evidence.details = {{"reading",
                           "invariance in the first argument A (the local homotopy); in B, E^R(A, CB) = |det C| E^R(A, "
                           "B) is scaled, not invariant"}};
  out.proof = proof(ctx);
  if (proofs::proves(*out.proof)) {
    out.strength = *proof_strength(*out.proof);
    out.summary += "; proved for all A ≠ 0, B, sR_δ ≠ 0 by two identities (GiNaC and an exact degree grid)";
  } else {
    out.verdict = Verdict::inconclusive;
    out.summary = "an identity of the proof does not hold although every sample agreed: " + out.summary;
  }
  return out;
}

}  // namespace
}  // namespace affinterp::claims::kaji_er_similarity_invariant
