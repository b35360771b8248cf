#pragma once
// Symmetric matrices built symmetric by construction: each product that must be symmetric is computed
// on its upper triangle only and mirrored. Computing both triangles and averaging them, (S + Sᵀ)/2, is
// not enough: under -ffp-contract=fast (GCC's default for C++) and wide vectors the compiler may fuse the
// two copies of an entry into different FMA chains, so S(i, j) and S(j, i) differ in the last bit
// (seen with -march=x86-64-v3 and AVX-512). A mirrored triangle is the same number twice on every CPU.
#include <Eigen/Core>

namespace affinterp::linalg {

/// The symmetric matrix whose upper triangle (diagonal included) is that of M; the lower one is ignored.
template <class Derived>
typename Derived::PlainObject mirror_upper(const Eigen::MatrixBase<Derived>& M) {
  typename Derived::PlainObject S = M;
  for (Eigen::Index j = 0; j < S.cols(); ++j)
    for (Eigen::Index i = j + 1; i < S.rows(); ++i) S(i, j) = S(j, i);
  return S;
}

/// Whether M equals its transpose exactly.
template <class Derived>
bool is_symmetric(const Eigen::MatrixBase<Derived>& M) {
  return M.rows() == M.cols() && M == M.transpose();
}

/// Q diag(λ) Qᵀ (a symmetric matrix with eigenvalues λ and eigenvectors the columns of Q), exactly symmetric.
template <class DerivedQ, class DerivedL>
Eigen::Matrix<typename DerivedQ::Scalar, DerivedQ::RowsAtCompileTime, DerivedQ::RowsAtCompileTime> congruence(
    const Eigen::MatrixBase<DerivedQ>& Q, const Eigen::MatrixBase<DerivedL>& lambda) {
  using Scalar = typename DerivedQ::Scalar;
  Eigen::Matrix<Scalar, DerivedQ::RowsAtCompileTime, DerivedQ::RowsAtCompileTime> S(Q.rows(), Q.rows());
  for (Eigen::Index i = 0; i < Q.rows(); ++i)
    for (Eigen::Index j = i; j < Q.rows(); ++j) {
      Scalar s(0);
      for (Eigen::Index k = 0; k < Q.cols(); ++k) s += Q(i, k) * lambda(k) * Q(j, k);
      S(i, j) = s;
    }
  return mirror_upper(S);
}

/// X Xᵀ, exactly symmetric (X Xᵀ is the Gram matrix of X's rows; pass Mᵀ for Mᵀ M).
template <class Derived>
Eigen::Matrix<typename Derived::Scalar, Derived::RowsAtCompileTime, Derived::RowsAtCompileTime> outer_gram(
    const Eigen::MatrixBase<Derived>& X) {
  using Scalar = typename Derived::Scalar;
  Eigen::Matrix<Scalar, Derived::RowsAtCompileTime, Derived::RowsAtCompileTime> S(X.rows(), X.rows());
  for (Eigen::Index i = 0; i < X.rows(); ++i)
    for (Eigen::Index j = i; j < X.rows(); ++j) S(i, j) = X.row(i).dot(X.row(j));
  return mirror_upper(S);
}

}  // namespace affinterp::linalg
