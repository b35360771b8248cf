#include "experiments/claims/claim.hpp"
#include "experiments/claims/values.hpp"
#include "theory/exact/rational.hpp"

namespace affinterp::claims::sym3 {
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
// Sizes: the whole grid, 4⁷ points, at either size.

using exact::Mat3Q;
using exact::Rational;

Rational det3(const Mat3Q& A) {
  return A(0, 0) * (A(1, 1) * A(2, 2) - A(1, 2) * A(2, 1)) - A(0, 1) * (A(1, 0) * A(2, 2) - A(1, 2) * A(2, 0)) +
         A(0, 2) * (A(1, 0) * A(2, 1) - A(1, 1) * A(2, 0));
}

/// The printed right-hand side; ‖S‖²_F is the sum of the squares of all nine entries.
Rational printed(const Rational& x, const Mat3Q& S) {
  const Rational trace = S.trace();
  Rational frobenius2 = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) frobenius2 += S(i, j) * S(i, j);
  return x * x * x - trace * x * x + (trace * trace - frobenius2) / 2 * x - det3(S);
}

Outcome check(const ClaimContext&) {
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
    const Rational lhs = det3(xE_minus_S), rhs = printed(x, S);
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
  out.verdict = Verdict::confirmed;
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
}  // namespace affinterp::claims::sym3
