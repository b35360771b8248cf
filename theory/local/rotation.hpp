#pragma once
// The rotation R_θ = [[cos θ, −sin θ], [sin θ, cos θ]] of Kaji §3 and thesis §2.2, and the principal
// branch θ ∈ (−π, π] that Kaji §3 fixes for the polar decomposition.
#include "theory/local/matrix2.hpp"

#include <boost/math/constants/constants.hpp>
#include <cmath>

namespace affinterp::local {

template <class Scalar>
Mat2<Scalar> rotation(const Scalar& theta) {
  using std::cos;
  using std::sin;
  const Scalar c = cos(theta), s = sin(theta);
  Mat2<Scalar> R;
  R << c, -s, s, c;
  return R;
}

template <class Scalar>
Scalar pi() {
  return boost::math::constants::pi<Scalar>();
}

/// The representative of θ modulo 2π in (−π, π].
template <class Scalar>
Scalar principal_angle(Scalar theta) {
  using std::ceil;
  const Scalar two_pi = 2 * pi<Scalar>();
  theta -= two_pi * ceil((theta - pi<Scalar>()) / two_pi);  // now in (−π, π] up to rounding
  if (theta <= -pi<Scalar>()) theta += two_pi;
  return theta;
}

}  // namespace affinterp::local
