#pragma once
// The polar homotopy in 3D ([ACOL00]; Kaji eq. (2) with R_θ^t replaced by the axis-angle power):
// A^P(t) = R^t((1−t)I + tS) for A = R S, R^t = exp(t[ω]×). Built from (ω, S) so that callers can choose the
// branch ω + 2πk ω/|ω| (rotation_branch3.hpp).
#include "theory/local3/svd3.hpp"

namespace affinterp::local3 {

template <class Scalar>
struct PolarHomotopy3 {
  Vec3<Scalar> omega;  ///< a logarithm of R
  Mat3<Scalar> S;

  /// With the principal logarithm of R.
  static PolarHomotopy3 of(const Mat3<Scalar>& A) {
    const Polar3<Scalar> polar = polar3(svd3(A));
    return PolarHomotopy3{rotation_log(polar.R), polar.S};
  }

  Mat3<Scalar> operator()(const Scalar& t) const {
    return rotation_exp<Scalar>(t * omega) * ((Scalar(1) - t) * Mat3<Scalar>::Identity() + t * S);
  }
};

}  // namespace affinterp::local3
