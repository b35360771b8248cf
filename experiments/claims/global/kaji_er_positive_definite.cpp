#include "experiments/claims/claim.hpp"
#include "experiments/claims/global/exact_global.hpp"
#include "experiments/claims/global/symbolic_er.hpp"
#include "experiments/claims/values.hpp"
#include "experiments/proofs/identity.hpp"

#include <algorithm>

namespace affinterp::claims {
namespace {

Outcome check(const ClaimContext& ctx);

const ClaimDeclaration claim{{
    .id = "kaji.er.positive-definite",
    .chapter = Chapter::global,
    .where = "Kaji §4, Appendix",
    .statement = "E^R is a positive definite quadratic form in the entries of B.",
    .strength = Strength::exact_counterexample,
    .check = check,
}};

// Reading: "positive definite in the entries of B" for fixed A.
// Method: E^R(A, ·) is the quadratic form Q = I − (a aᵀ + j jᵀ)/‖A‖² on vec B (a = vec A, j = vec JA); its rank
//   and Q² = Q (an orthogonal projection, hence only semi-definite) computed exactly on random A, and
//   E^R(I, I) = 0 as the counterexample.
//   Proof for all A ≠ 0: E^R(A, A) = 0 (not definite) and ‖A‖⁴ E^R(A, B) is a square (semi-definite), identities
//   over symbols from theory/global's E^R (proof()).
// Sizes: quick 100 matrices; full 2000.

using global_exact::Mat2Q;
using global_exact::Rational;

/// The proof for all A ≠ 0, from theory/global's E^R over symbols:
///   E^R(A, A) = 0                                    (at-A: B = A ≠ 0 gives 0, so not definite)
///   ‖A‖⁴ E^R(A, B) = ‖ ‖A‖²B − ⟨A,B⟩A − ⟨JA,B⟩JA ‖²     (semidefinite: a square, so E^R ≥ 0).
Proof proof(const ClaimContext& ctx) {
  using symbolic_er::Mat2X;
  const symbolic_er::Pair p;
  const GiNaC::ex nA = symbolic_er::norm2(p.A), a = symbolic_er::inner(p.A, p.B), j = symbolic_er::inner_J(p.A, p.B);
  const Mat2X JA = global::rotation_J<GiNaC::ex>().lazyProduct(p.A);
  const Mat2X projection_residual = local::scaled(nA, p.B) - local::scaled(a, p.A) - local::scaled(j, JA);
  const std::vector<proofs::Identity> identities = {
      {"at-A", "E^R(A, A) = 0 for every A ≠ 0", symbolic_er::E_R(p.A, p.A), GiNaC::ex(0)},
      {"semidefinite", "‖A‖⁴ E^R(A, B) = ‖ ‖A‖²B − ⟨A,B⟩A − ⟨JA,B⟩JA ‖²", nA * nA * symbolic_er::E_R(p.A, p.B),
       projection_residual.squaredNorm()},
  };
  return proofs::identity_proof("all real 2×2 A ≠ 0 and B",
                                "identities over symbols from theory/global's E^R: E^R(A, ·) vanishes at B = A ≠ 0 "
                                "(not definite) and ‖A‖⁴E^R(A, B) is a sum of squares (semi-definite)",
                                proofs::prove_identities(identities, ctx.proof_files()));
}

Outcome check(const ClaimContext& ctx) {
  Outcome out;
  Rng rng(ctx.seed);
  const int samples = ctx.pick(100, 2000);
  // E^R(A, ·) is the quadratic form Q = I − (a aᵀ + j jᵀ)/‖A‖² on vec B (a = vec A, j = vec JA): compute its
  // rank, check Q² = Q (an orthogonal projection, hence semi-definite) and that B = A gives 0.
  // Q = I − (a aᵀ + j jᵀ)/‖A‖², from E^R(A, B) = ‖B‖² − (⟨A,B⟩² + ⟨JA,B⟩²)/‖A‖² (Kaji Appendix).
  Eigen::Index worst_rank = 4;
  bool projection = true;
  for (int k = 0; k < samples; ++k) {
    const Mat2Q A = global_exact::random_matrix(rng, 9, 4, true);
    const Eigen::Matrix<Rational, 4, 1> a = global::vec(A),
                                        j = global::vec<Rational>(global::rotation_J<Rational>().lazyProduct(A));
    const Eigen::Matrix<Rational, 4, 4> projected = a.lazyProduct(a.transpose()) + j.lazyProduct(j.transpose());
    const Eigen::Matrix<Rational, 4, 4> Q =
        Eigen::Matrix<Rational, 4, 4>::Identity() - local::scaled(Rational(1) / A.squaredNorm(), projected);
    const global_exact::MatQ dynamic_Q = Q;
    worst_rank = std::min(worst_rank, global_exact::rank(dynamic_Q));
    const global_exact::MatQ Q_squared = Q.lazyProduct(Q);
    projection = projection && global_exact::equal(Q_squared, dynamic_Q);
  }
  const Mat2Q A = Mat2Q::Identity(), B = Mat2Q::Identity();
  const Rational at_A = global::similarity_error(A, B);
  out.verdict = at_A == 0 ? Verdict::refuted : Verdict::confirmed;
  out.summary = "E^R(A, ·) is only positive semi-definite: an orthogonal projection of rank " +
                std::to_string(worst_rank) +
                " on vec B, vanishing on the plane span{A, JA} = {s R_δ A}; e.g. E^R(I, I) = " + exact::to_string(at_A);
  out.evidence.method = "exact rational computation of the form's matrix, its rank and Q² = Q";
  out.evidence.sample_size = static_cast<std::uint64_t>(samples);
  out.evidence.seed = ctx.seed;
  out.evidence.details = {
      {"smallest_rank_seen", worst_rank},
      {"Q_squared_equals_Q_on_all", projection},
      {"consequence",
       "Σ E^R_i over a mesh is invariant under translation and, up to the factor s², under global "
       "rotation and scale: constraints must fix translation, rotation and scale (Kaji's claim that "
       "E_t is positive definite fails too; its minimum without them is the collapse B = 0)"}};
  out.counterexample = {{"A", exact_matrix(A)},
                        {"B", exact_matrix(B)},
                        {"E_R", exact::to_string(at_A)},
                        {"note", "B ≠ 0 with E^R(A, B) = 0: the quadratic form is not definite"}};
  out.proof = proof(ctx);
  if (!proofs::all_results(out.proof->sentences, "zero")) {
    out.verdict = Verdict::inconclusive;
    out.summary = "an identity of the proof does not hold: " + out.summary;
  }
  return out;
}

}  // namespace
}  // namespace affinterp::claims
