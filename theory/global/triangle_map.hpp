#pragma once
// The linear part B of the affine map of eq. (1) (Kaji §3) as a linear function of the image vertices:
// the triangle with source corners p_0, p_1, p_2 goes to v_0, v_1, v_2 under the affine map whose
// linear part is B = V D, V = [v_0 v_1 v_2] (2×3), D = [[−1, −1], [1, 0], [0, 1]] [p_1 − p_0, p_2 − p_0]⁻¹.
// This is the "observation vital" of Kaji §4: the entries of B_i(t) are linear in the v_k(t).
#include <Eigen/Core>
#include <Eigen/LU>

namespace affinterp::global {

template <class Scalar>
using Corners = Eigen::Matrix<Scalar, 2, 3>;  ///< the corners of one triangle, column c = corner c

/// D with B = V D for every image V of the triangle `p` (eq. (1)); `p` must not be degenerate.
template <class Scalar>
Eigen::Matrix<Scalar, 3, 2> linear_part_operator(const Corners<Scalar>& p) {
  Eigen::Matrix<Scalar, 2, 2> edges;
  edges.col(0) = p.col(1) - p.col(0);
  edges.col(1) = p.col(2) - p.col(0);
  Eigen::Matrix<Scalar, 3, 2> difference;
  difference << Scalar(-1), Scalar(-1), Scalar(1), Scalar(0), Scalar(0), Scalar(1);
  const Eigen::Matrix<Scalar, 2, 2> inverse = edges.inverse();
  return difference.lazyProduct(inverse);  // lazyProduct: Eigen's product evaluator rejects cpp_rational
}

/// M with vec(B) = M x for x = (v_0x, v_0y, v_1x, v_1y, v_2x, v_2y) and vec column-major: M = Dᵀ ⊗ I₂.
template <class Scalar>
Eigen::Matrix<Scalar, 4, 6> vectorised_linear_part_operator(const Eigen::Matrix<Scalar, 3, 2>& D) {
  Eigen::Matrix<Scalar, 4, 6> M = Eigen::Matrix<Scalar, 4, 6>::Zero();
  for (int column = 0; column < 2; ++column)
    for (int k = 0; k < 3; ++k)
      for (int r = 0; r < 2; ++r) M(2 * column + r, 2 * k + r) = D(k, column);
  return M;
}

/// The linear part of the affine map sending the corners p to the corners q (eq. (1)).
template <class Scalar>
Eigen::Matrix<Scalar, 2, 2> linear_part(const Corners<Scalar>& p, const Corners<Scalar>& q) {
  return q.lazyProduct(linear_part_operator(p));
}

/// Column-major vec of a 2×2 matrix.
template <class Scalar>
Eigen::Matrix<Scalar, 4, 1> vec(const Eigen::Matrix<Scalar, 2, 2>& B) {
  Eigen::Matrix<Scalar, 4, 1> b;
  b << B(0, 0), B(1, 0), B(0, 1), B(1, 1);
  return b;
}

}  // namespace affinterp::global
