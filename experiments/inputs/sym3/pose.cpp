#include "experiments/inputs/sym3/pose.hpp"

#include <Eigen/Geometry>

#include <numbers>

namespace affinterp::sym3 {

Mesh3 twisted_pose(const Mesh3& source) {
  const Eigen::Vector3d lo = source.vertices.rowwise().minCoeff(), hi = source.vertices.rowwise().maxCoeff();
  const Eigen::Vector3d center = (lo + hi) / 2;
  Eigen::Index axis;
  const double half_length = (hi - lo).maxCoeff(&axis) / 2;
  const Eigen::Vector3d direction = Eigen::Vector3d::Unit(axis);

  Mesh3 target = source;
  for (Eigen::Index k = 0; k < source.vertex_count(); ++k) {
    const Eigen::Vector3d p = source.vertices.col(k) - center;
    const double along = p.dot(direction);
    const double s = along / half_length;
    const Eigen::Vector3d radial = (1 + s / 4) * (p - along * direction);
    const Eigen::AngleAxisd twist(s * std::numbers::pi / 2, direction);
    target.vertices.col(k) = center + 1.2 * along * direction + twist * radial;
  }
  return target;
}

}  // namespace affinterp::sym3
