// Per-frame metrics (theory/global/metrics): flips, det B_i extremes, σ1/σ2 distortion, area change.
#include "theory/global/metrics.hpp"

#include "checks/global/strip.hpp"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <Eigen/SVD>

#include <cmath>

namespace metrics_test {

namespace {

using namespace affinterp::global;

using affinterp::global::testing::unit_square;

TEST(FrameMetrics, OfTheSourceItselfAreNeutral) {
  const FrameMetrics m = frame_metrics(unit_square(), unit_square().vertices);
  EXPECT_EQ(m.flipped_triangles, 0);
  EXPECT_DOUBLE_EQ(m.min_det, 1);
  EXPECT_DOUBLE_EQ(m.max_det, 1);
  EXPECT_DOUBLE_EQ(m.max_distortion, 1);
  EXPECT_DOUBLE_EQ(m.mean_distortion, 1);
  EXPECT_DOUBLE_EQ(m.area_ratio, 1);
}

TEST(FrameMetrics, OfAGlobalLinearMapAreItsDeterminantAndSingularValues) {
  Eigen::Matrix2d A;
  A << 2, 1, -0.5, 1.5;
  const Eigen::Matrix2Xd frame = (A * unit_square().vertices).colwise() + Eigen::Vector2d(3, -4);
  const FrameMetrics m = frame_metrics(unit_square(), frame);
  const Eigen::Vector2d sigma = Eigen::JacobiSVD<Eigen::Matrix2d>(A).singularValues();
  EXPECT_NEAR(triangle_linear_map(unit_square(), frame, 1)(0, 1), 1, 1e-14);
  EXPECT_NEAR(m.min_det, A.determinant(), 1e-14);
  EXPECT_NEAR(m.max_det, A.determinant(), 1e-14);
  EXPECT_NEAR(m.max_distortion, sigma(0) / sigma(1), 1e-13);
  EXPECT_NEAR(m.mean_distortion, sigma(0) / sigma(1), 1e-13);
  EXPECT_NEAR(m.area_ratio, A.determinant(), 1e-14);
}

TEST(FrameMetrics, CountFlipsAndCollapses) {
  Eigen::Matrix2Xd frame = unit_square().vertices;
  frame.col(3) = Eigen::Vector2d(2, 0);  // triangle 1 = (0,0), (1,1), (2,0): clockwise
  FrameMetrics m = frame_metrics(unit_square(), frame);
  EXPECT_EQ(m.flipped_triangles, 1);
  EXPECT_DOUBLE_EQ(m.min_det, -2);
  EXPECT_DOUBLE_EQ(m.area_ratio, (1.0 - 2.0) / 2.0);
  frame.col(3) = Eigen::Vector2d(0.5, 0.5);  // collapsed onto the diagonal
  m = frame_metrics(unit_square(), frame);
  EXPECT_EQ(m.flipped_triangles, 1);
  EXPECT_TRUE(std::isinf(m.max_distortion));
}

}  // namespace

}  // namespace metrics_test
