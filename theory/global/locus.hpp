#pragma once
// A user-specified locus u(t) through given points (Kaji §4: loci "given by B-spline curves"): the
// B-spline of degree min(3, N − 1) interpolating P_0 … P_{N−1} at t = 0, 1/(N−1), …, 1, with knots by
// averaging of those parameters (de Boor, *A Practical Guide to Splines*, ch. XIII) — Eigen's
// SplineFitting::Interpolate. Two points give the straight segment, and any cubic polynomial curve sampled
// at those times is reproduced exactly. Beyond [0, 1] the end polynomial pieces continue (extrapolation).
// Reversing the points reverses the curve: u_reversed(t) = u(1 − t). In the plane (Locus) and in space (Locus3).
#include <Eigen/Core>
#include <unsupported/Eigen/Splines>

namespace affinterp::global {

template <int Dim>
class BasicLocus {
 public:
  using Points = Eigen::Matrix<double, Dim, Eigen::Dynamic>;
  using Point = Eigen::Matrix<double, Dim, 1>;

  /// Throws std::invalid_argument for fewer than two points or non-finite coordinates.
  explicit BasicLocus(Points points);
  Point at(double t) const;
  const Points& points() const { return points_; }

 private:
  Points points_;
  Eigen::Spline<double, Dim> spline_;
};

using Locus = BasicLocus<2>;
using Locus3 = BasicLocus<3>;

extern template class BasicLocus<2>;
extern template class BasicLocus<3>;

}  // namespace affinterp::global
