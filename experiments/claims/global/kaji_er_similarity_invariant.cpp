#include "experiments/claims/claim.hpp"
#include "experiments/claims/global/exact_global.hpp"
#include "experiments/claims/values.hpp"

namespace affinterp::claims {
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
// Sizes: quick 200 triples; full 5000.

using global_exact::Mat2Q;
using global_exact::Rational;

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
  return out;
}

}  // namespace
}  // namespace affinterp::claims
