#include "experiments/claims/claim.hpp"
#include "experiments/claims/proof_strength.hpp"
#include "experiments/claims/values.hpp"
#include "experiments/proofs/ginac_scalar.hpp"
#include "experiments/proofs/identity.hpp"
#include "experiments/proofs/step_nodes.hpp"
#include "theory/exact/rational.hpp"

#include <stdexcept>

namespace affinterp::claims::sym3::thesis_eq_3_charpoly {
namespace {

Outcome check(const ClaimContext& ctx);

const ClaimDeclaration claim{{
    .id = "thesis.eq-3.charpoly",
    .chapter = Chapter::sym3,
    .where = "thesis §3.2",
    .statement =
        "For symmetric 3×3 S the characteristic polynomial is x³ − (tr S)x² + ((tr S)² − ‖S‖²_F)/2 · x − det S.",
    .strength = Strength::grid,
    .check = check,
}};

// Reading: ‖S‖²_F is the sum of the squares of all nine entries (the off-diagonal ones twice).
// Method: det(xE − S) and the printed polynomial in exact rational arithmetic on the grid {0, 1, 2, 3}⁷ of
//   (x, a, b, c, d, e, f), S = [[a, d, e], [d, b, f], [e, f, c]]. Their difference has degree ≤ 3 in each of the
//   seven variables, so vanishing on the grid makes it identically zero (a polynomial of degree ≤ n in one
//   variable with n + 1 roots is zero; induct on the variables).
//   The identity is also decided over symbols by the identity prover's two checkers (proof()).
// Sizes: the whole grid, 4⁷ points, at either size.

using exact::Mat3Q;
using exact::Rational;

template <class Scalar>
using Mat3 = Eigen::Matrix<Scalar, 3, 3>;

template <class Scalar>
Scalar det3(const Mat3<Scalar>& A) {
  return A(0, 0) * (A(1, 1) * A(2, 2) - A(1, 2) * A(2, 1)) - A(0, 1) * (A(1, 0) * A(2, 2) - A(1, 2) * A(2, 0)) +
         A(0, 2) * (A(1, 0) * A(2, 1) - A(1, 1) * A(2, 0));
}

/// The printed right-hand side; ‖S‖²_F is the sum of the squares of all nine entries.
template <class Scalar>
Scalar printed(const Scalar& x, const Mat3<Scalar>& S) {
  const Scalar trace = S.trace();
  Scalar frobenius2 = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) frobenius2 += S(i, j) * S(i, j);
  return x * x * x - trace * x * x + (trace * trace - frobenius2) / 2 * x - det3(S);
}

/// det(xE − S) = the printed polynomial over symbols x, a, …, f (S = [[a, d, e], [d, b, f], [e, f, c]]).
Proof proof(const ClaimContext& ctx) {
  const GiNaC::symbol x("x"), a("a"), b("b"), c("c"), d("d"), e("e"), f("f");
  Mat3<GiNaC::ex> S, xE_minus_S;
  S << a, d, e, d, b, f, e, f, c;
  xE_minus_S = -S;
  for (int i = 0; i < 3; ++i) xE_minus_S(i, i) += x;
  return proofs::identity_proof(
      "every real symmetric 3×3 S and every real x", "one polynomial identity in x, a, …, f",
      {proofs::prove_identity({"charpoly", "det(xE − S) = x³ − (tr S)x² + ((tr S)² − ‖S‖²_F)/2·x − det S",
                               proofs::determinant_of(proofs::to_ginac<3, 3>(xE_minus_S)), printed<GiNaC::ex>(x, S)},
                              ctx.proof_files())});
}

Outcome check(const ClaimContext& ctx) {
  constexpr int values = 4, variables = 7;
  int points = 0;
  for (int index = 0; index < 16384; ++index, ++points) {  // 4⁷ grid points
    int v[variables];
    for (int i = 0, rest = index; i < variables; ++i, rest /= values) v[i] = rest % values;
    const Rational x = v[0];
    Mat3Q S;
    S << v[1], v[4], v[5], v[4], v[2], v[6], v[5], v[6], v[3];
    Mat3Q xE_minus_S = -S;
    for (int i = 0; i < 3; ++i) xE_minus_S(i, i) += x;
    const Rational lhs = det3<Rational>(xE_minus_S), rhs = printed<Rational>(x, S);
    if (lhs != rhs) {
      Outcome out;
      out.verdict = Verdict::refuted;
      out.summary = "det(xE − S) differs from the printed polynomial at an integer point";
      out.evidence.method = "exact rational evaluation on the grid {0,1,2,3}^7";
      out.evidence.sample_size = static_cast<std::uint64_t>(points + 1);
      out.counterexample = {{"S", exact_matrix(S)},
                            {"x", exact::to_string(x)},
                            {"det(xE - S)", exact::to_string(lhs)},
                            {"printed", exact::to_string(rhs)}};
      return out;
    }
  }
  Outcome out;
  out.proof = proof(ctx);
  if (!proofs::proves(*out.proof))
    throw std::runtime_error("the grid says the identity holds, the identity prover that it does not");
  out.verdict = Verdict::confirmed;
  out.strength = *proof_strength(*out.proof);
  out.summary =
      "det(xE − S) = x³ − (tr S)x² + ((tr S)² − ‖S‖²_F)/2·x − det S holds identically (exact, "
      "polynomial identity decided on the grid {0,1,2,3}^7)";
  out.evidence.method =
      "exact rational evaluation of both sides on the 4^7 grid of (x, a, b, c, d, e, f); a "
      "polynomial of degree ≤ 3 in each of 7 variables vanishing there is identically zero";
  out.evidence.sample_size = static_cast<std::uint64_t>(points);
  out.evidence.worst_deviation = 0.0;
  out.evidence.details = {{"reading", "‖S‖_F² = sum of the squares of all nine entries (off-diagonals twice)"},
                          {"variables", "S = [[a, d, e], [d, b, f], [e, f, c]]"},
                          {"degree_bound", "at most 3 in x and at most 2 in each entry of S"}};
  return out;
}

}  // namespace
}  // namespace affinterp::claims::sym3::thesis_eq_3_charpoly
