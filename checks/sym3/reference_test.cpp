// The two high-precision references agree with each other, and with exactly known exponentials.
#include "theory/sym3/reference.hpp"
#include "experiments/inputs/sym3/families.hpp"
#include "theory/linalg/symmetric.hpp"

#include <gtest/gtest.h>

namespace affinterp::sym3::reference_test {
namespace {

using exact::Real100;
using exact::Real50;

Real50 relative_difference(const Mat3R50& A, const Mat3R50& B) { return (A - B).norm() / B.norm(); }

TEST(Sym3Reference, JacobiAndTaylorAgreeOnEveryFamily) {
  for (const Family& family : families()) {
    if (family.whole_double_range) continue;  // beyond these references (families.hpp)
    for (const Mat3& S : family.draw(family, 3, 2)) {
      EXPECT_LT(relative_difference(reference_exp(S), reference_exp_taylor(S)), Real50("1e-45")) << family.name;
    }
  }
}

TEST(Sym3Reference, DiagonalMatrixGivesExponentialsOfTheDiagonal) {
  Mat3R100 S = Mat3R100::Zero();
  S(0, 0) = Real100(1) / 3, S(1, 1) = -2, S(2, 2) = Real100(7) / 2;
  for (const Mat3R100& E : {exp_by_eigen(S), exp_by_taylor(S)}) {
    for (int i = 0; i < 3; ++i) EXPECT_LT(abs(E(i, i) - exp(S(i, i))), Real100("1e-95") * exp(S(i, i)));
    EXPECT_EQ(E(0, 1), 0);
  }
}

TEST(Sym3Reference, JacobiFindsKnownEigenvalues) {
  // [[b+c, 0, 0], [0, b, c], [0, c, b]] has eigenvalues b − c, b + c, b + c; rotate it by an exact
  // rational rotation (3/5, 4/5) in the (x, y) plane.
  Mat3R100 S;
  S << 3, 0, 0, 0, 1, 2, 0, 2, 1;
  Mat3R100 Q;
  Q << Real100(3) / 5, Real100(-4) / 5, 0, Real100(4) / 5, Real100(3) / 5, 0, 0, 0, 1;
  const ReferenceEigen e = reference_eigen(linalg::mirror_upper(Q * S * Q.transpose()));
  EXPECT_LT(abs(e.lambda(0) + 1), Real100("1e-95"));
  EXPECT_LT(abs(e.lambda(1) - 3), Real100("1e-95"));
  EXPECT_LT(abs(e.lambda(2) - 3), Real100("1e-95"));
}

}  // namespace
}  // namespace affinterp::sym3::reference_test
