#include "experiments/claims/claim.hpp"
#include "experiments/claims/global/exact_global.hpp"
#include "experiments/claims/values.hpp"

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
// Sizes: quick 100 matrices; full 2000.

using global_exact::Mat2Q;
using global_exact::Rational;

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
  return out;
}

}  // namespace
}  // namespace affinterp::claims
