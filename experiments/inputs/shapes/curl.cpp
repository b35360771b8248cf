#include "experiments/inputs/shapes/curl.hpp"

#include <array>
#include <cmath>

namespace affinterp::shapes {

double Curl::theta(double s) const { return theta_end * std::pow(s / length, power); }

Eigen::Vector2d Curl::apply(const Eigen::Vector2d& point, double t) const {
  // c_t(s) by composite 5-point Gauss–Legendre quadrature on panels of length ≤ L/256: θ is a
  // polynomial in s of low degree, so the error is at the rounding level.
  static constexpr std::array<double, 5> node = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831,
                                                 0.9061798459386640};
  static constexpr std::array<double, 5> weight = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                                                   0.4786286704993665, 0.2369268850561891};
  const double s = point.x(), y = point.y();
  const int panels = std::max(1, static_cast<int>(std::ceil(256 * std::abs(s) / length)));
  const double h = s / panels;
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  for (int j = 0; j < panels; ++j)
    for (std::size_t q = 0; q < node.size(); ++q) {
      const double u = (j + 0.5 + 0.5 * node[q]) * h;
      const double angle = t * theta(u);
      centre += 0.5 * h * weight[q] * Eigen::Vector2d(std::cos(angle), std::sin(angle));
    }
  const double angle = t * theta(s);
  return centre + y * Eigen::Vector2d(-std::sin(angle), std::cos(angle));
}

Eigen::Matrix2Xd Curl::apply(const Eigen::Matrix2Xd& points, double t) const {
  Eigen::Matrix2Xd images(2, points.cols());
  for (Eigen::Index k = 0; k < points.cols(); ++k) images.col(k) = apply(Eigen::Vector2d(points.col(k)), t);
  return images;
}

}  // namespace affinterp::shapes
