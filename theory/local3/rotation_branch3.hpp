#pragma once
// The branches of a rotation's logarithm (the 3D rotation consistency problem, Kaji §4's θ + 2πk in 3D): the
// logarithms of R = exp [ω]× ≠ I are the vectors (θ + 2πk) a, k ∈ ℤ, for θ = |ω| and a = ω/|ω| (k = −1 gives the
// turn the other way round, −(2π − θ) a); those of I are 0 and the spheres |ω| = 2πk. A local homotopy built
// from another representative turns the element by more than π on its way to the same endpoint.
#include "theory/local3/rotation3.hpp"

#include <cmath>

namespace affinterp::local3 {

/// Among the logarithms of exp [ω]×, the one nearest `reference`: (θ + 2πk) a with k the integer nearest
/// (reference·a − θ)/2π (the representatives lie on the line ℝa, so the nearest is the nearest on the line).
/// For ω = 0, the multiple 2πk of reference's direction nearest reference.
template <class Scalar>
Vec3<Scalar> nearest_log(const Vec3<Scalar>& omega, const Vec3<Scalar>& reference) {
  using std::round;
  const Scalar two_pi = 2 * pi<Scalar>(), theta = omega.norm();
  if (!(theta > Scalar(0))) {
    const Scalar length = reference.norm();
    const Scalar k = round(length / two_pi);
    return k > Scalar(0) ? Vec3<Scalar>((k * two_pi / length) * reference) : Vec3<Scalar>::Zero();
  }
  const Vec3<Scalar> axis = omega / theta;
  const Scalar k = round((reference.dot(axis) - theta) / two_pi);
  return (theta + k * two_pi) * axis;
}

}  // namespace affinterp::local3
