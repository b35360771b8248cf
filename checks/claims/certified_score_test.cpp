// How thesis.exp.accuracy judges one result against its certified truth
// (experiments/claims/sym3/certified_score.hpp): certified errors, non-finite results where exp S is
// finite, finite results where it overflows, and exclusions.
#include "experiments/claims/sym3/certified_score.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace affinterp::claims::sym3::certified_score_test {
namespace {

TEST(CertifiedScore, CertifiesTheErrorOfAnInexactResult) {
  const Mat3 S = Eigen::Vector3d(0.5, 1, 2).asDiagonal();
  const CertifiedTruth truth = certified_truth(S);
  EXPECT_EQ(truth.norm, 2);
  Mat3 X = Eigen::Vector3d(std::exp(0.5), std::exp(1.0), std::exp(2.0)).asDiagonal();
  X(2, 2) *= 1 + 1e-10;
  const Score s = score(X, truth);
  ASSERT_EQ(s.judgement, Judgement::certified);
  const double expected = std::exp(2.0) * 1e-10 / std::sqrt(std::exp(1.0) + std::exp(2.0) + std::exp(4.0));
  EXPECT_NEAR(s.error, expected, 1e-6 * expected);
  EXPECT_GE(s.error_upper, s.error);
  EXPECT_GT(s.over_own_bound, 1);  // 10⁻¹⁰ is far beyond ours' 2·10⁻¹⁵ · 2
}

TEST(CertifiedScore, AnExactResultHasACertifiedZeroError) {
  const Mat3 S = Mat3::Zero();
  const Score s = score(Mat3::Identity(), certified_truth(S));
  EXPECT_EQ(s.judgement, Judgement::certified);
  EXPECT_EQ(s.error, 0);
}

TEST(CertifiedScore, NonFiniteAndOverflowMismatchesAreWrong) {
  const Mat3 finite_S = Mat3::Identity();
  Mat3 nan = Mat3::Identity();
  nan(0, 1) = NAN;
  const Score wrong = score(nan, certified_truth(finite_S));
  EXPECT_EQ(wrong.judgement, Judgement::non_finite);
  EXPECT_TRUE(std::isinf(wrong.error));

  const Mat3 huge = 800 * Mat3::Identity();  // exp S = e⁸⁰⁰ I overflows in double
  const CertifiedTruth overflowing = certified_truth(huge);
  EXPECT_EQ(score(Mat3::Identity(), overflowing).judgement, Judgement::finite_where_overflow);
  EXPECT_EQ(score(Mat3::Constant(INFINITY), overflowing).judgement, Judgement::overflow_agreed);
}

TEST(CertifiedScore, AnErrorBelowTheBallsResolutionIsExcluded) {
  // S with off-diagonal 10⁻³⁰⁰: X = I + S misses only S²/2 ≈ 10⁻⁶⁰⁰, far below the ball's radius (about
  // 2⁻¹¹⁰ ‖exp S‖_F), so the ball cannot certify that error: it is excluded, with a tiny upper bound.
  Mat3 S = Mat3::Zero();
  S(0, 1) = S(1, 0) = 1e-300;
  const Score s = score(Mat3::Identity() + S, certified_truth(S));
  EXPECT_EQ(s.judgement, Judgement::error_not_certified);
  EXPECT_LE(s.error_upper, 1e-30);
}

}  // namespace
}  // namespace affinterp::claims::sym3::certified_score_test
