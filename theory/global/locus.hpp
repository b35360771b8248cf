#pragma once
// A user-specified locus u(t) through given points (Kaji §4: loci "given by B-spline curves"): the
// B-spline of degree min(3, N − 1) interpolating P_0 … P_{N−1} at t = 0, 1/(N−1), …, 1, with knots by
// averaging of those parameters (de Boor, *A Practical Guide to Splines*, ch. XIII) — Eigen's
// SplineFitting::Interpolate. Two points give the straight segment, and any cubic polynomial curve sampled
// at those times is reproduced exactly. Beyond [0, 1] the end polynomial pieces continue (extrapolation).
// Reversing the points reverses the curve: u_reversed(t) = u(1 − t).
#include <Eigen/Core>
#include <unsupported/Eigen/Splines>

namespace affinterp::global {

class Locus {
 public:
  /// Throws std::invalid_argument for fewer than two points or non-finite coordinates.
  explicit Locus(Eigen::Matrix2Xd points);
  Eigen::Vector2d at(double t) const;
  const Eigen::Matrix2Xd& points() const { return points_; }

 private:
  Eigen::Matrix2Xd points_;
  Eigen::Spline2d spline_;
};

}  // namespace affinterp::global
