#pragma once
// The SVD homotopy in 3D ([ACOL00]; thesis Def. 2.2.4 with rotations R_α, R_β replaced by U, Vᵀ ∈ SO(3)):
// A_s(t) = U^t((1−t)I + tΣ)(Vᵀ)^t for A = U Σ Vᵀ, with U^t = exp(t[ω_U]×) and (Vᵀ)^t = exp(t[ω_V]×) for logarithms
// ω_U of U and ω_V of Vᵀ. Like the 2D one the path depends on the chosen factors (the SVD is not unique: signs
// of column pairs, and the order of equal σ), not only on A.
#include "theory/local3/svd3.hpp"

namespace affinterp::local3 {

template <class Scalar>
struct SvdHomotopy3 {
  Vec3<Scalar> omega_U;  ///< a logarithm of U
  Vec3<Scalar> sigma;    ///< Σ's diagonal
  Vec3<Scalar> omega_V;  ///< a logarithm of Vᵀ

  /// With the principal logarithms of svd3(A)'s U and Vᵀ.
  static SvdHomotopy3 of(const Mat3<Scalar>& A) {
    const Svd3<Scalar> d = svd3(A);
    return SvdHomotopy3{rotation_log<Scalar>(d.U), d.sigma, rotation_log<Scalar>(d.V.transpose())};
  }

  Mat3<Scalar> operator()(const Scalar& t) const {
    const Vec3<Scalar> blend = (Scalar(1) - t) * Vec3<Scalar>::Ones() + t * sigma;
    return rotation_exp<Scalar>(t * omega_U) * blend.asDiagonal() * rotation_exp<Scalar>(t * omega_V);
  }
};

}  // namespace affinterp::local3
