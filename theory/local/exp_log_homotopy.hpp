#pragma once
// Kaji's homotopy, eq. (3): A^E(t) = R_θ^t S^t = R_{tθ} S^t for A = R_θ S, with S^t = exp(t log S) in
// closed form from the eigen-decomposition S = R_{−β} diag(λ1, λ2) R_β (Kaji Appendix):
// S^t = R_{−β} diag(λ1^t, λ2^t) R_β. Built from (θ, S) so that callers can choose θ + 2πk (Kaji §4);
// the decomposition of S is computed once.
#include "theory/local/polar_from_svd.hpp"

namespace affinterp::local {

template <class Scalar>
struct ExpLogHomotopy {
  Scalar theta;
  Svd<Scalar> S_eigen;  ///< S = R_{−β} diag(λ1, λ2) R_β: x = λ1, y = λ2, alpha = −beta

  ExpLogHomotopy(const Scalar& theta, const Mat2<Scalar>& S) : theta(theta), S_eigen(svd(S)) {}
  /// With the principal angle θ ∈ (−π, π] of polar_decomposition(A).
  static ExpLogHomotopy of(const Mat2<Scalar>& A) {
    const Polar<Scalar> polar = polar_decomposition(A);
    return ExpLogHomotopy(polar.theta, polar.S);
  }

  Mat2<Scalar> operator()(const Scalar& t) const { return rotation<Scalar>(t * theta) * spd_power(S_eigen, t); }
};

}  // namespace affinterp::local
