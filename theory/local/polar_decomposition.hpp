#pragma once
// The polar decomposition A = R_θ S of A ∈ GL+(2) (Kaji §3 after [SD92]; thesis §2.2.3): R_θ a
// rotation with θ ∈ (−π, π], S symmetric positive definite.
//
// Closed form: R_θᵀ A is symmetric iff tan θ = (a21 − a12)/(a11 + a22), and of the two solutions modulo 2π
// the one with cos θ : sin θ = (a11 + a22) : (a21 − a12) gives tr S = √((a11 + a22)² + (a21 − a12)²) > 0,
// which with det S = det A > 0 makes S positive definite.
#include "theory/local/rotation.hpp"

#include <cmath>
#include <stdexcept>

namespace affinterp::local {

template <class Scalar>
struct Polar {
  Scalar theta;    ///< rotation angle, (−π, π] from polar_decomposition(); callers may add 2πk
  Mat2<Scalar> S;  ///< symmetric positive definite factor
};

/// A = R_θ S with θ ∈ (−π, π]; throws std::invalid_argument unless det A > 0.
template <class Scalar>
Polar<Scalar> polar_decomposition(const Mat2<Scalar>& A) {
  using std::atan2;
  if (!(det2(A) > Scalar(0))) throw std::invalid_argument("polar decomposition needs det A > 0");
  const Scalar trace_part = A(0, 0) + A(1, 1), skew_part = A(1, 0) - A(0, 1);
  Polar<Scalar> polar{principal_angle<Scalar>(atan2(skew_part, trace_part)), Mat2<Scalar>()};
  polar.S = rotation<Scalar>(-polar.theta) * A;
  const Scalar off_diagonal = (polar.S(0, 1) + polar.S(1, 0)) / 2;  // equal in exact arithmetic
  polar.S(0, 1) = polar.S(1, 0) = off_diagonal;
  return polar;
}

}  // namespace affinterp::local
