#pragma once
// A user-specified locus u(t) through given points (Kaji §4: "for example, given by B-spline curves"):
// the uniform Catmull–Rom spline through points P_0 … P_{N−1} at t = 0, 1/(N−1), …, 1, with end tangents
// P_1 − P_0 and P_{N−1} − P_{N−2}. Two points give the straight segment; beyond [0, 1] the end cubics
// continue. Reversing the points reverses the curve: u_reversed(t) = u(1 − t).
#include <Eigen/Core>

namespace affinterp::global {

class Locus {
 public:
  /// Throws std::invalid_argument for fewer than two points or non-finite coordinates.
  explicit Locus(Eigen::Matrix2Xd points);
  Eigen::Vector2d at(double t) const;
  const Eigen::Matrix2Xd& points() const { return points_; }

 private:
  Eigen::Vector2d tangent(Eigen::Index j) const;
  Eigen::Matrix2Xd points_;
};

}  // namespace affinterp::global
