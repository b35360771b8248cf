#include "experiments/claims/claim.hpp"
#include "theory/local/goodness3.hpp"

#include <algorithm>
#include <stdexcept>

namespace affinterp::claims::atlas3::atlas3_linear_singular_values {
namespace {

using exact::Rational;
using Mat = local::Mat3<Rational>;

Outcome check(const ClaimContext& ctx);

const ClaimDeclaration claim{{
    .id = "atlas3.linear.singular-values",
    .chapter = Chapter::atlas3,
    .where = "beyond the papers (Kaji et al.'s finer evaluators, in 3D)",
    .statement = "Where the linear homotopy (1−t)I + tA is good for singular values (each sorted singular value "
                 "monotone on [0, 1]): open. Proved (LEMMAS.md L25): the norm region (sym A ⪰ I or AᵀA ⪯ sym A) "
                 "lies inside it, strictly; a rotation about an axis leaves it.",
    .strength = Strength::sample,
    .check = check,
}};

// Reading: as atlas3.polar.singular-values, for (1−t)I + tA.
// Method: the cell is open. L25 (c) proves the inner bound by hand (every norm monotone in one direction makes the
//   Gram matrices Loewner-monotone, and Weyl's inequalities order their eigenvalues). The check computes exactly
//   the two maps that bound it from both sides: A = diag(2, 1/2, 1), good for singular values (1 + t, 1 − t/2, 1)
//   and not for norm (goodness3.hpp finds a dipping direction), and the quarter turn about e3, whose two
//   largest singular values dip to √(1/2) at t = 1/2. Their Gram matrices are diagonal, so the sorted singular
//   values squared are read off exactly at t = 0, 1/2, 1.
// Sizes: the same two maps at every size.

/// The squared singular values of (1−t)I + tA, sorted, when its Gram matrix is diagonal (throws otherwise).
std::array<Rational, 3> squared_singular_values(const Mat& A, const Rational& t) {
  const Mat B = local::blend3(A, t);
  std::array<Rational, 3> out;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      Rational g(0);
      for (int k = 0; k < 3; ++k) g += B(k, i) * B(k, j);
      if (i != j && g != 0) throw std::logic_error("the Gram matrix is not diagonal");
      if (i == j) out[i] = g;
    }
  std::sort(out.begin(), out.end(), std::greater<>());
  return out;
}

/// Some sorted singular value rises and falls across t = 0, 1/2, 1.
bool some_singular_value_turns(const Mat& A) {
  const auto s0 = squared_singular_values(A, 0), s1 = squared_singular_values(A, Rational(1, 2)),
             s2 = squared_singular_values(A, 1);
  for (int k = 0; k < 3; ++k)
    if ((s1[k] < s0[k] && s1[k] < s2[k]) || (s1[k] > s0[k] && s1[k] > s2[k])) return true;
  return false;
}

Outcome check(const ClaimContext& ctx) {
  Mat stretch = local::diagonal3<Rational>(2, Rational(1, 2), 1), quarter_turn;
  quarter_turn << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  const bool stretch_norm_good = !local::dipping_direction(stretch, 8).has_value();
  const bool turn_turns = some_singular_value_turns(quarter_turn);
  Outcome o;
  o.verdict = Verdict::inconclusive;
  o.strength = Strength::sample;
  o.summary = std::string("open (LEMMAS.md L25): inside it the norm region (proved); diag(2, 1/2, 1) ") +
              (stretch_norm_good ? "is" : "is not") +
              " good for norm while its singular values 1 + t, 1 - t/2, 1 are monotone (the inclusion is strict); " +
              "the quarter turn about e3 " + (turn_turns ? "leaves" : "does not leave") +
              " it (squared singular values 1, 1/2, 1 at t = 0, 1/2, 1)";
  o.evidence.method =
      "exact rational arithmetic on two maps with diagonal Gram matrices (goodness3.hpp's direction "
      "search for the norm); the inner bound by hand (L25)";
  o.evidence.sample_size = 2;
  o.evidence.seed = ctx.seed;
  o.evidence.details = {{"stretch_good_for_norm", stretch_norm_good},
                        {"quarter_turn_singular_value_turns", turn_turns}};
  o.counterexample = {{"A", {{"0", "-1", "0"}, {"1", "0", "0"}, {"0", "0", "1"}}}, {"t", {"0", "1/2", "1"}}};
  return o;
}

}  // namespace
}  // namespace affinterp::claims::atlas3::atlas3_linear_singular_values
