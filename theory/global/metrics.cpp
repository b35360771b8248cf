#include "theory/global/metrics.hpp"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <limits>

namespace affinterp::global {

Eigen::Matrix2d triangle_linear_map(const Mesh& source, const Eigen::Matrix2Xd& frame, Eigen::Index i) {
  const auto& t = source.triangles.col(i);
  Eigen::Matrix2d P, V;  // edge vectors from corner 0, source and frame
  P << source.vertices.col(t(1)) - source.vertices.col(t(0)), source.vertices.col(t(2)) - source.vertices.col(t(0));
  V << frame.col(t(1)) - frame.col(t(0)), frame.col(t(2)) - frame.col(t(0));
  return V * P.inverse();
}

namespace {

/// σ1/σ2 of a 2×2 matrix in closed form: σ1,2 = (√((a+d)² + (c−b)²) ± √((a−d)² + (b+c)²)) / 2.
double singular_value_ratio(const Eigen::Matrix2d& B) {
  const double p = std::hypot(B(0, 0) + B(1, 1), B(1, 0) - B(0, 1));
  const double q = std::hypot(B(0, 0) - B(1, 1), B(0, 1) + B(1, 0));
  const double sigma2 = std::abs(p - q) / 2;
  return sigma2 == 0 ? std::numeric_limits<double>::infinity() : (p + q) / 2 / sigma2;
}

}  // namespace

FrameMetrics frame_metrics(const Mesh& source, const Eigen::Matrix2Xd& frame) {
  FrameMetrics m;
  m.min_det = std::numeric_limits<double>::infinity();
  m.max_det = -std::numeric_limits<double>::infinity();
  double source_area = 0, frame_area = 0, distortion_sum = 0;
  for (Eigen::Index i = 0; i < source.triangle_count(); ++i) {
    const Eigen::Matrix2d B = triangle_linear_map(source, frame, i);
    const double det = B.determinant();
    m.flipped_triangles += det <= 0;
    m.min_det = std::min(m.min_det, det);
    m.max_det = std::max(m.max_det, det);
    const double ratio = singular_value_ratio(B);
    m.max_distortion = std::max(m.max_distortion, ratio);
    distortion_sum += ratio;
    source_area += source.doubled_signed_area(i);
    const auto corner = [&](int c) { return frame.col(source.triangles(c, i)); };  // as Mesh::doubled_signed_area
    const Eigen::Vector2d e1 = corner(1) - corner(0), e2 = corner(2) - corner(0);
    frame_area += e1.x() * e2.y() - e1.y() * e2.x();
  }
  m.mean_distortion = distortion_sum / static_cast<double>(source.triangle_count());
  m.area_ratio = frame_area / source_area;
  return m;
}

}  // namespace affinterp::global
