#include "theory/global/locus.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace affinterp::global {

Locus::Locus(Eigen::Matrix2Xd points) : points_(std::move(points)) {
  if (points_.cols() < 2) throw std::invalid_argument("a locus needs at least two points");
  if (!points_.allFinite()) throw std::invalid_argument("a locus point is not finite");
}

Eigen::Vector2d Locus::tangent(Eigen::Index j) const {
  const Eigen::Index last = points_.cols() - 1;
  if (j == 0) return points_.col(1) - points_.col(0);
  if (j == last) return points_.col(last) - points_.col(last - 1);
  return (points_.col(j + 1) - points_.col(j - 1)) / 2;
}

Eigen::Vector2d Locus::at(double t) const {
  const Eigen::Index segments = points_.cols() - 1;
  const double position = t * static_cast<double>(segments);
  const Eigen::Index j = std::clamp<Eigen::Index>(static_cast<Eigen::Index>(std::floor(position)), 0, segments - 1);
  const double s = position - static_cast<double>(j), s2 = s * s, s3 = s2 * s;
  // Cubic Hermite basis on segment j.
  return (2 * s3 - 3 * s2 + 1) * points_.col(j) + (s3 - 2 * s2 + s) * tangent(j) +
         (-2 * s3 + 3 * s2) * points_.col(j + 1) + (s3 - s2) * tangent(j + 1);
}

}  // namespace affinterp::global
