#pragma once
// The rotation nearest to a 3 × 3 matrix M: the R ∈ SO(3) maximising tr(Rᵀ M), equivalently minimising ‖R − M‖_F
// (the orthogonal Procrustes problem with a proper rotation; Kabsch 1976): R = U diag(1, 1, det(U Vᵀ)) Vᵀ from
// any SVD M = U Σ Vᵀ. For det M > 0 it is the polar factor of svd3.hpp; unlike polar3 it takes any M, including
// the rank-2 products a triangle's in-plane map gives (unique while σ2 > 0).
#include "theory/local3/rotation3.hpp"

#include <Eigen/SVD>

#include <cmath>

namespace affinterp::local3 {

template <class Scalar>
Mat3<Scalar> nearest_rotation(const Mat3<Scalar>& M) {
  const Eigen::JacobiSVD<Mat3<Scalar>> svd(M, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Mat3<Scalar> U = svd.matrixU();
  if ((U * svd.matrixV().transpose()).determinant() < Scalar(0)) U.col(2) = -U.col(2);
  return U * svd.matrixV().transpose();
}

/// The rotation R minimising Σ_k ‖(q_k − q̄) − R (p_k − p̄)‖² over the columns k of p and q (3 × k each; Kabsch
/// 1976): the rotation nearest to the centred cross-covariance Σ_k (q_k − q̄)(p_k − p̄)ᵀ, summed column by column in
/// order, so the same bits whatever the vector width.
template <class Scalar>
Mat3<Scalar> fitted_rotation(const Eigen::Matrix<Scalar, 3, Eigen::Dynamic>& p,
                             const Eigen::Matrix<Scalar, 3, Eigen::Dynamic>& q) {
  Vec3<Scalar> p_mean = Vec3<Scalar>::Zero(), q_mean = Vec3<Scalar>::Zero();
  for (Eigen::Index k = 0; k < p.cols(); ++k) p_mean += p.col(k), q_mean += q.col(k);
  p_mean /= Scalar(p.cols()), q_mean /= Scalar(p.cols());
  Mat3<Scalar> H = Mat3<Scalar>::Zero();
  for (Eigen::Index k = 0; k < p.cols(); ++k) H += (q.col(k) - q_mean) * (p.col(k) - p_mean).transpose();
  return nearest_rotation(H);
}

namespace detail {

/// The largest of the three cross products of a, b, c taken in pairs: the normal of the plane they span, as
/// accurate as the three allow.
template <class Scalar>
Vec3<Scalar> plane_normal(const Vec3<Scalar>& a, const Vec3<Scalar>& b, const Vec3<Scalar>& c) {
  Vec3<Scalar> n = a.cross(b);
  for (const Vec3<Scalar>& other : {Vec3<Scalar>(b.cross(c)), Vec3<Scalar>(c.cross(a))})
    if (other.squaredNorm() > n.squaredNorm()) n = other;
  return n;
}

/// A unit vector orthogonal to the unit vector n.
template <class Scalar>
Vec3<Scalar> orthogonal_unit(const Vec3<Scalar>& n) {
  Eigen::Index k = 0;
  n.cwiseAbs().minCoeff(&k);
  return n.cross(Vec3<Scalar>::Unit(k)).normalized();
}

}  // namespace detail

/// nearest_rotation(M) for an M of rank 2 (a triangle's in-plane products), without the SVD. Its column space (the
/// plane with unit normal n_x) and its row space (n_z) have orthonormal bases f1, f2 and e1, e2; the maximiser maps
/// the row space onto the column space, so R = [f1, s f2] Q [e1 e2]ᵀ + s n_x n_zᵀ with s = ±1 and Q a rotation of the
/// plane, and tr(Rᵀ M) = tr(Qᵀ diag(1, s) K), K = [f1 f2]ᵀ M [e1 e2]. Its maximum over Q is the 2 × 2 polar
/// problem: Q ∝ [[p, −q], [q, p]] with p = K11 + s K22, q = s K21 − K12, of value √(p² + q²), the larger for
/// s = sign det K. Where M is not numerically of rank 2 (its second singular value below 10⁻⁸ of its norm, as
/// measured by the normals) the SVD's answer is returned.
template <class Scalar>
Mat3<Scalar> nearest_rotation_of_rank_two(const Mat3<Scalar>& M) {
  using std::sqrt;
  Vec3<Scalar> n_x = detail::plane_normal<Scalar>(M.col(0), M.col(1), M.col(2));
  Vec3<Scalar> n_z = detail::plane_normal<Scalar>(M.row(0).transpose(), M.row(1).transpose(), M.row(2).transpose());
  const Scalar size = M.squaredNorm(), floor = Scalar(1e-8) * size;
  if (!(n_x.norm() > floor && n_z.norm() > floor)) return nearest_rotation(M);
  n_x.normalize();
  n_z.normalize();
  const Vec3<Scalar> e1 = detail::orthogonal_unit(n_z), e2 = n_z.cross(e1);
  const Vec3<Scalar> f1 = detail::orthogonal_unit(n_x), f2 = n_x.cross(f1);
  const Vec3<Scalar> Me1 = M * e1, Me2 = M * e2;
  const Scalar K11 = f1.dot(Me1), K12 = f1.dot(Me2), K21 = f2.dot(Me1), K22 = f2.dot(Me2);
  const Scalar s = K11 * K22 - K12 * K21 < Scalar(0) ? Scalar(-1) : Scalar(1);
  const Scalar p = K11 + s * K22, q = s * K21 - K12, r = sqrt(p * p + q * q);
  if (!(r > Scalar(0))) return nearest_rotation(M);
  const Scalar c = p / r, sine = q / r;
  const Vec3<Scalar> g2 = s * f2;
  return (c * f1 + sine * g2) * e1.transpose() + (c * g2 - sine * f1) * e2.transpose() + (s * n_x) * n_z.transpose();
}

}  // namespace affinterp::local3
