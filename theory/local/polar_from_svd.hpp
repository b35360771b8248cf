#pragma once
// Kaji Appendix: from A = R_α D R_β, the polar decomposition is R_θ = R_{α+β}, S = R_{−β} D R_β, and
// S^t = R_{−β} D^t R_β.
#include "theory/local/polar_decomposition.hpp"
#include "theory/local/svd.hpp"

#include <cmath>

namespace affinterp::local {

/// (θ, S) = (α+β, R_{−β} D R_β); θ is returned as α+β, not reduced to (−π, π].
template <class Scalar>
Polar<Scalar> polar_from_svd(const Svd<Scalar>& svd) {
  return Polar<Scalar>{svd.alpha + svd.beta, rotation<Scalar>(-svd.beta) * svd.D() * rotation(svd.beta)};
}

/// S^t = R_{−β} D^t R_β for S = R_{−β} D R_β (a symmetric positive definite S, written as its SVD with α = −β).
template <class Scalar>
Mat2<Scalar> spd_power(const Svd<Scalar>& S_svd, const Scalar& t) {
  using std::pow;
  Mat2<Scalar> D_t;
  D_t << pow(S_svd.x, t), Scalar(0), Scalar(0), pow(S_svd.y, t);
  return rotation<Scalar>(-S_svd.beta) * D_t * rotation(S_svd.beta);
}

}  // namespace affinterp::local
