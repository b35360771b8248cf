#pragma once
// The rotation nearest to a 3 × 3 matrix M: the R ∈ SO(3) maximising tr(Rᵀ M), equivalently minimising ‖R − M‖_F
// (the orthogonal Procrustes problem with a proper rotation; Kabsch 1976): R = U diag(1, 1, det(U Vᵀ)) Vᵀ from
// any SVD M = U Σ Vᵀ. For det M > 0 it is the polar factor of svd3.hpp; unlike polar3 it takes any M, including
// the rank-2 products a triangle's in-plane map gives (unique while σ2 > 0).
#include "theory/local3/rotation3.hpp"

#include <Eigen/SVD>

namespace affinterp::local3 {

template <class Scalar>
Mat3<Scalar> nearest_rotation(const Mat3<Scalar>& M) {
  const Eigen::JacobiSVD<Mat3<Scalar>> svd(M, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Mat3<Scalar> U = svd.matrixU();
  if ((U * svd.matrixV().transpose()).determinant() < Scalar(0)) U.col(2) = -U.col(2);
  return U * svd.matrixV().transpose();
}

}  // namespace affinterp::local3
