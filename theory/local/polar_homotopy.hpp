#pragma once
// The polar homotopy of [ACOL00], Kaji eq. (2) (thesis Def. 2.2.5, A_p(t)): A^P(t) = R_{tθ}((1−t)I + tS)
// for A = R_θ S. It is built from (θ, S) so that callers can choose θ + 2πk (Kaji §4).
#include "theory/local/polar_decomposition.hpp"

namespace affinterp::local {

template <class Scalar>
struct PolarHomotopy {
  Scalar theta;
  Mat2<Scalar> S;

  /// With the principal angle θ ∈ (−π, π] of polar_decomposition(A).
  static PolarHomotopy of(const Mat2<Scalar>& A) {
    const Polar<Scalar> polar = polar_decomposition(A);
    return PolarHomotopy{polar.theta, polar.S};
  }

  Mat2<Scalar> operator()(const Scalar& t) const {
    return rotation<Scalar>(t * theta) * ((Scalar(1) - t) * identity2<Scalar>() + t * S);
  }
};

}  // namespace affinterp::local
