// The AffineLib expSym peer (experiments/inputs/sym3/affinelib_exp_sym.hpp): each branch of its published
// algorithm on matrices whose exponential is known in closed form, and the overflow it is known for.
#include "experiments/inputs/sym3/affinelib_exp_sym.hpp"

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <cmath>
#include <limits>
#include <utility>

namespace affinterp::sym3::affinelib_exp_sym_test {
namespace {

using Mat3 = Eigen::Matrix3d;

/// R diag(λ) Rᵀ and R diag(e^λ) Rᵀ for a fixed rotation R.
std::pair<Mat3, Mat3> rotated_pair(const Eigen::Vector3d& lambda) {
  const Mat3 R = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  return {R * lambda.asDiagonal() * R.transpose(), R * lambda.array().exp().matrix().asDiagonal() * R.transpose()};
}

double relative_error(const Mat3& X, const Mat3& F) { return (X - F).norm() / F.norm(); }

TEST(AffineLibExpSym, SmallMatricesGoToIPlusS) {
  Mat3 S = Mat3::Zero();
  S(0, 1) = S(1, 0) = 1e-3;
  EXPECT_EQ(exp_affinelib(S), Mat3::Identity() + S);  // its first-order shortcut, exactly
}

TEST(AffineLibExpSym, EveryBranchMatchesTheClosedForm) {
  for (const Eigen::Vector3d& lambda : {Eigen::Vector3d(0.5, 1, 2),   // distinct
                                        Eigen::Vector3d(1, 1, 2.5),   // λ₀ = λ₁
                                        Eigen::Vector3d(-1, 2, 2),    // λ₁ = λ₂
                                        Eigen::Vector3d(3, 3, 3)}) {  // all equal
    const auto [S, E] = rotated_pair(lambda);
    // computeDirect's closed-form eigenvalues lose about half the digits at a repeated eigenvalue (√ε).
    EXPECT_LT(relative_error(exp_affinelib(S), E), 1e-7) << lambda.transpose();
  }
}

TEST(AffineLibExpSym, TreatsEigenvaluesWithin1e5AsEqual) {
  // λ₀, λ₁ = 1, 1 + 5·10⁻⁶: taken as equal, the error is of the order of the gap.
  const auto [S, E] = rotated_pair(Eigen::Vector3d(1, 1 + 5e-6, 2));
  const double error = relative_error(exp_affinelib(S), E);
  EXPECT_GT(error, 1e-8);
  EXPECT_LT(error, 1e-5);
}

TEST(AffineLibExpSym, OverflowsWhereExpSIsFinite) {
  // λmax = 710.5 > log DBL_MAX with the eigenvector (1, 1, 1)/√3: exp S's entries are e^{710.5}/3, finite,
  // but expSym forms e^{λmax} first.
  const Mat3 P = Mat3::Constant(1.0 / 3);
  const Mat3 S = 710.5 * P - 300 * (Mat3::Identity() - P);
  ASSERT_LT(710.5 - std::log(3.0), std::log(std::numeric_limits<double>::max()));  // exp S is finite
  EXPECT_FALSE(exp_affinelib(S).allFinite());
}

}  // namespace
}  // namespace affinterp::sym3::affinelib_exp_sym_test
