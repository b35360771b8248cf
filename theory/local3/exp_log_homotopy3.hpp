#pragma once
// Kaji's homotopy in 3D (eq. (3), the parametrisation of the thesis's reference [6]): A^E(t) = R^t S^t for
// A = R S, with R^t = exp(t[ω]×) and S^t = exp(t log S) = V diag(σ^t) Vᵀ for S = V diag(σ) Vᵀ. Hence
// det A^E(t) = det S^t = exp(t tr log S) > 0 for every real t: the path never leaves GL⁺(3).
// This is the one-element form, for the local theory and tests; the 3D engine evaluates S^t for all elements at
// once through sym3::exp_batched (theory/global3/local_maps3.hpp). Built from (ω, S) so that callers can choose
// the branch ω + 2πk ω/|ω| (rotation_branch3.hpp).
#include "theory/local3/svd3.hpp"

#include <Eigen/Eigenvalues>

namespace affinterp::local3 {

template <class Scalar>
struct ExpLogHomotopy3 {
  Vec3<Scalar> omega;  ///< a logarithm of R
  Mat3<Scalar> V;      ///< S's eigenvectors
  Vec3<Scalar> sigma;  ///< S's eigenvalues, > 0

  /// From a logarithm ω of R and S = V diag(σ) Vᵀ (ascending σ from Eigen's self-adjoint solver). Throws
  /// std::invalid_argument unless S is positive definite.
  ExpLogHomotopy3(const Vec3<Scalar>& omega, const Mat3<Scalar>& S) : omega(omega) {
    const Eigen::SelfAdjointEigenSolver<Mat3<Scalar>> eigen(S);
    V = eigen.eigenvectors();
    sigma = eigen.eigenvalues();
    if (!(sigma.minCoeff() > Scalar(0))) throw std::invalid_argument("S^t needs S positive definite");
  }
  ExpLogHomotopy3(const Vec3<Scalar>& omega, const Svd3<Scalar>& d) : omega(omega), V(d.V), sigma(d.sigma) {}
  /// With the principal logarithm of R.
  static ExpLogHomotopy3 of(const Mat3<Scalar>& A) {
    const Svd3<Scalar> d = svd3(A);
    return ExpLogHomotopy3(rotation_log<Scalar>(d.U * d.V.transpose()), d);
  }

  /// S^t = V diag(σ^t) Vᵀ.
  Mat3<Scalar> stretch_power(const Scalar& t) const {
    using std::pow;
    const Vec3<Scalar> power{pow(sigma[0], t), pow(sigma[1], t), pow(sigma[2], t)};
    return V * power.asDiagonal() * V.transpose();
  }
  Mat3<Scalar> operator()(const Scalar& t) const { return rotation_exp<Scalar>(t * omega) * stretch_power(t); }
};

}  // namespace affinterp::local3
