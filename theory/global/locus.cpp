#include "theory/global/locus.hpp"

#include <algorithm>
#include <stdexcept>

namespace affinterp::global {
namespace {

Eigen::Spline2d interpolating_spline(const Eigen::Matrix2Xd& points) {
  if (points.cols() < 2) throw std::invalid_argument("a locus needs at least two points");
  if (!points.allFinite()) throw std::invalid_argument("a locus point is not finite");
  const Eigen::Index degree = std::min<Eigen::Index>(3, points.cols() - 1);
  const Eigen::RowVectorXd times = Eigen::RowVectorXd::LinSpaced(points.cols(), 0.0, 1.0);
  return Eigen::SplineFitting<Eigen::Spline2d>::Interpolate(points, degree, times);
}

}  // namespace

Locus::Locus(Eigen::Matrix2Xd points) : points_(std::move(points)), spline_(interpolating_spline(points_)) {}

Eigen::Vector2d Locus::at(double t) const { return spline_(t).matrix(); }

}  // namespace affinterp::global
