#pragma once
// The decompositions of A ∈ GL⁺(3) the 3D homotopies are built from: the singular value decomposition with
// rotations only, A = U Σ Vᵀ with U, V ∈ SO(3) and Σ = diag(σ1, σ2, σ3), σ1 ≥ σ2 ≥ σ3 > 0 (the 3D counterpart
// of theory/local/svd.hpp's A = R_α D R_β), and from it the polar decomposition A = R S with R = U Vᵀ ∈ SO(3),
// S = V Σ Vᵀ symmetric positive definite, and log S = V log Σ Vᵀ.
#include "theory/local3/rotation3.hpp"

#include <Eigen/SVD>

#include <cmath>
#include <stdexcept>

namespace affinterp::local3 {

template <class Scalar>
struct Svd3 {
  Mat3<Scalar> U;      ///< ∈ SO(3)
  Vec3<Scalar> sigma;  ///< σ1 ≥ σ2 ≥ σ3 > 0
  Mat3<Scalar> V;      ///< ∈ SO(3)

  Mat3<Scalar> matrix() const { return U * sigma.asDiagonal() * V.transpose(); }
};

/// A = U Σ Vᵀ from Eigen's two-sided Jacobi SVD (accurate for 3×3), its last columns of U and V negated together
/// when det U = det V = −1 (det A > 0 makes their signs equal), which leaves U Σ Vᵀ unchanged. Throws
/// std::invalid_argument unless det A > 0 and A is finite.
template <class Scalar>
Svd3<Scalar> svd3(const Mat3<Scalar>& A) {
  if (!A.allFinite() || !(A.determinant() > Scalar(0)))
    throw std::invalid_argument("rotation-only SVD needs a finite A with det A > 0");
  const Eigen::JacobiSVD<Mat3<Scalar>> svd(A, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Svd3<Scalar> d{svd.matrixU(), svd.singularValues(), svd.matrixV()};
  if (d.U.determinant() < Scalar(0)) {
    d.U.col(2) = -d.U.col(2);
    d.V.col(2) = -d.V.col(2);
  }
  return d;
}

template <class Scalar>
struct Polar3 {
  Mat3<Scalar> R;  ///< ∈ SO(3)
  Mat3<Scalar> S;  ///< symmetric positive definite
};

/// A = R S with R = U Vᵀ, S = V Σ Vᵀ from svd3(A).
template <class Scalar>
Polar3<Scalar> polar3(const Svd3<Scalar>& d) {
  Mat3<Scalar> S = d.V * d.sigma.asDiagonal() * d.V.transpose();
  S = (S + S.transpose()).eval() / 2;
  return {d.U * d.V.transpose(), S};
}

/// log S = V diag(log σ) Vᵀ for the S of polar3(d): the principal logarithm of the SPD factor.
template <class Scalar>
Mat3<Scalar> log_stretch(const Svd3<Scalar>& d) {
  const Vec3<Scalar> log_sigma = d.sigma.array().log().matrix();
  Mat3<Scalar> L = d.V * log_sigma.asDiagonal() * d.V.transpose();
  return (L + L.transpose()) / 2;
}

}  // namespace affinterp::local3
