// Vertex and barycentre loci (theory/global/locus.hpp): the interpolating B-spline through given points.
#include "theory/global/locus.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <limits>
#include <stdexcept>

namespace affinterp::global::locus_test {
namespace {

/// 2 … 7 points with small integer coordinates.
Eigen::Matrix2Xd some_points() {
  const int n = *rc::gen::inRange(2, 8);
  Eigen::Matrix2Xd points(2, n);
  for (int k = 0; k < n; ++k) points.col(k) = Eigen::Vector2d(*rc::gen::inRange(-9, 10), *rc::gen::inRange(-9, 10));
  return points;
}

RC_GTEST_PROP(Locus, PassesThroughItsPointsAtEvenlySpacedTimes, ()) {
  const Eigen::Matrix2Xd points = some_points();
  const Locus u(points);
  const auto last = static_cast<double>(points.cols() - 1);
  for (Eigen::Index k = 0; k < points.cols(); ++k)
    RC_ASSERT((u.at(static_cast<double>(k) / last) - points.col(k)).norm() < 1e-12);
}

RC_GTEST_PROP(Locus, ReversingThePointsReversesTheCurve, ()) {
  const Eigen::Matrix2Xd points = some_points();
  const Locus u(points), reversed(points.rowwise().reverse());
  for (const double t : {-0.25, 0.1, 0.37, 0.5, 0.9, 1.3}) RC_ASSERT((u.at(t) - reversed.at(1 - t)).norm() < 1e-9);
}

TEST(Locus, ReproducesACubicCurveExactlyAndExtrapolatesIt) {
  auto cubic = [](double t) { return Eigen::Vector2d(2 * t * t * t - t + 1, -t * t + 3 * t); };
  Eigen::Matrix2Xd points(2, 6);
  for (int k = 0; k < 6; ++k) points.col(k) = cubic(k / 5.0);
  const Locus u(points);
  for (const double t : {-0.5, 0.0, 0.13, 0.5, 0.77, 1.0, 1.5}) EXPECT_LT((u.at(t) - cubic(t)).norm(), 1e-12) << t;
}

TEST(Locus, TwoPointsGiveTheStraightSegment) {
  Eigen::Matrix2Xd points(2, 2);
  points << 1, 3, 2, -2;
  const Locus u(points);
  EXPECT_LT((u.at(0.25) - Eigen::Vector2d(1.5, 1)).norm(), 1e-15);
  EXPECT_LT((u.at(2.0) - Eigen::Vector2d(5, -6)).norm(), 1e-14);
}

TEST(Locus, RefusesTooFewOrNonFinitePoints) {
  EXPECT_THROW(Locus(Eigen::Matrix2Xd(2, 1)), std::invalid_argument);
  Eigen::Matrix2Xd points = Eigen::Matrix2Xd::Zero(2, 3);
  points(1, 2) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(Locus{points}, std::invalid_argument);
}

}  // namespace
}  // namespace affinterp::global::locus_test
