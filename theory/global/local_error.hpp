#pragma once
// The local error functions of Kaji §4 and the Appendix, as closed forms in (A, B) and as quadratic
// forms in the six vertex coordinates x = (v_0x, v_0y, v_1x, v_1y, v_2x, v_2y) of one triangle:
//     E_i(x) = xᵀ H x + gᵀ x + c.
// Templated on the scalar so that the claims can assemble them in exact rationals (hence lazyProduct and
// local::scaled: Boost 1.74's cpp_rational meets neither Eigen's product evaluator nor scalar operators).
#include "theory/global/triangle_map.hpp"
#include "theory/local/matrix2.hpp"

#include <Eigen/Core>

namespace affinterp::global {

template <class Scalar>
using Mat2 = Eigen::Matrix<Scalar, 2, 2>;

/// J = R_{π/2}: (xI + yJ) ranges over all s R_δ (Kaji Appendix).
template <class Scalar>
Mat2<Scalar> rotation_J() {
  Mat2<Scalar> J;
  J << Scalar(0), Scalar(-1), Scalar(1), Scalar(0);
  return J;
}

/// ⟨A, B⟩ = tr(A ᵀB) (Kaji Appendix).
template <class Derived, class Other>
auto frobenius_inner(const Eigen::MatrixBase<Derived>& A, const Eigen::MatrixBase<Other>& B) {
  return A.cwiseProduct(B).sum();
}

/// E^F(A, B) = ‖A − B‖²_F (Kaji §4, [ACOL00]).
template <class Scalar>
Scalar frobenius_error(const Mat2<Scalar>& A, const Mat2<Scalar>& B) {
  return (A - B).squaredNorm();
}

/// E^R(A, B) = min_{s,δ} ‖s R_δ A − B‖²_F in the Appendix's closed form as printed:
/// ‖B‖² − (‖B ᵀA‖² + 2 det(B ᵀA)) / ‖A‖².
template <class Scalar>
Scalar similarity_error(const Mat2<Scalar>& A, const Mat2<Scalar>& B) {
  const Mat2<Scalar> BAt = B.lazyProduct(A.transpose());
  return B.squaredNorm() - (BAt.squaredNorm() + Scalar(2) * BAt.determinant()) / A.squaredNorm();
}

/// The same minimum by the Appendix's derivation: ‖B‖² − (⟨A, B⟩² + ⟨JA, B⟩²) / ‖A‖², the residual of
/// projecting B onto span{A, JA} (⟨A, JA⟩ = 0, ‖JA‖ = ‖A‖).
template <class Scalar>
Scalar similarity_error_by_projection(const Mat2<Scalar>& A, const Mat2<Scalar>& B) {
  const Mat2<Scalar> JA = rotation_J<Scalar>().lazyProduct(A);
  const Scalar a = frobenius_inner(A, B), j = frobenius_inner(JA, B);
  return B.squaredNorm() - (a * a + j * j) / A.squaredNorm();
}

/// A quadratic form xᵀ H x + gᵀ x + c in a triangle's six vertex coordinates.
template <class Scalar>
struct TriangleQuadratic {
  Eigen::Matrix<Scalar, 6, 6> H = Eigen::Matrix<Scalar, 6, 6>::Zero();
  Eigen::Matrix<Scalar, 6, 1> g = Eigen::Matrix<Scalar, 6, 1>::Zero();
  Scalar c = Scalar(0);

  TriangleQuadratic& operator+=(const TriangleQuadratic& other) {
    H += other.H, g += other.g, c += other.c;
    return *this;
  }
  TriangleQuadratic operator*(const Scalar& w) const { return {local::scaled(w, H), local::scaled(w, g), c * w}; }
};

/// The operator D of B = V D (triangle_map.hpp) for one triangle.
template <class Scalar>
using LinearPartOperator = Eigen::Matrix<Scalar, 3, 2>;

/// The linear part g = −2 Mᵀ vec A of E^F below, computed as g_k = −2 A D_kᵀ (D_k the k-th row of D): all
/// that changes with t when E^F's G does not.
template <class Scalar>
Eigen::Matrix<Scalar, 6, 1> frobenius_linear_term(const LinearPartOperator<Scalar>& D, const Mat2<Scalar>& A) {
  const Eigen::Matrix<Scalar, 2, 3> ADt = A.lazyProduct(D.transpose());
  Eigen::Matrix<Scalar, 6, 1> g;
  for (int k = 0; k < 6; ++k) g[k] = Scalar(-2) * ADt.data()[k];
  return g;
}

/// E^F(A, B(x)) with vec B = M x, M = Dᵀ ⊗ I₂: H = MᵀM, g = −2 Mᵀ vec A, c = ‖A‖².
template <class Scalar>
TriangleQuadratic<Scalar> frobenius_quadratic(const LinearPartOperator<Scalar>& D, const Mat2<Scalar>& A) {
  const Eigen::Matrix<Scalar, 4, 6> M = vectorised_linear_part_operator(D);
  return {M.transpose().lazyProduct(M), frobenius_linear_term(D, A), A.squaredNorm()};
}

/// E^R(A, B(x)) = ‖B‖² − (⟨A, B⟩² + ⟨JA, B⟩²)/‖A‖²: H = MᵀM − (m_a m_aᵀ + m_j m_jᵀ)/‖A‖² with
/// m_a = Mᵀ vec A, m_j = Mᵀ vec JA; no linear or constant part.
template <class Scalar>
TriangleQuadratic<Scalar> similarity_quadratic(const LinearPartOperator<Scalar>& D, const Mat2<Scalar>& A) {
  const Eigen::Matrix<Scalar, 4, 6> M = vectorised_linear_part_operator(D);
  const Eigen::Matrix<Scalar, 6, 1> m_a = M.transpose().lazyProduct(vec(A));
  const Eigen::Matrix<Scalar, 6, 1> m_j = M.transpose().lazyProduct(vec<Scalar>(rotation_J<Scalar>().lazyProduct(A)));
  const Eigen::Matrix<Scalar, 6, 6> projected = m_a.lazyProduct(m_a.transpose()) + m_j.lazyProduct(m_j.transpose());
  TriangleQuadratic<Scalar> q;
  q.H = M.transpose().lazyProduct(M) - local::scaled(Scalar(1) / A.squaredNorm(), projected);
  return q;
}

/// w E^F + (1 − w) E^R ("Improvements").
template <class Scalar>
TriangleQuadratic<Scalar> blend_quadratic(const LinearPartOperator<Scalar>& D, const Mat2<Scalar>& A, const Scalar& w) {
  TriangleQuadratic<Scalar> q = frobenius_quadratic(D, A) * w;
  q += similarity_quadratic(D, A) * (Scalar(1) - w);
  return q;
}

/// E^S(A, B(x)) = min_{s,δ} Σ_k ‖s R_δ A p̃_k − B p̃_k‖² [WW95], p̃_k = p_k − centroid. With X = A P̃ and
/// Y = B P̃ = V Π (Π = I − 𝟙𝟙ᵀ/3: B p̃_k = v_k − v̄), the Appendix's argument applies verbatim to 2×3
/// matrices: E^S = ‖Y‖² − (⟨X, Y⟩² + ⟨JX, Y⟩²)/‖X‖², so H = Π ⊗ I₂ − (x xᵀ + j jᵀ)/‖X‖².
template <class Scalar>
TriangleQuadratic<Scalar> procrustes_quadratic(const Corners<Scalar>& p, const Mat2<Scalar>& A) {
  const Eigen::Matrix<Scalar, 2, 1> centroid = local::scaled(Scalar(1) / Scalar(3), p.rowwise().sum());
  const Corners<Scalar> centred = p.colwise() - centroid;
  const Corners<Scalar> X = A.lazyProduct(centred), JX = rotation_J<Scalar>().lazyProduct(X);
  const Eigen::Map<const Eigen::Matrix<Scalar, 6, 1>> x(X.data()), j(JX.data());
  TriangleQuadratic<Scalar> q;
  for (int k = 0; k < 3; ++k)
    for (int l = 0; l < 3; ++l)
      for (int r = 0; r < 2; ++r) q.H(2 * k + r, 2 * l + r) = (k == l ? Scalar(2) : Scalar(-1)) / Scalar(3);
  const Eigen::Matrix<Scalar, 6, 6> projected = x.lazyProduct(x.transpose()) + j.lazyProduct(j.transpose());
  q.H -= local::scaled(Scalar(1) / X.squaredNorm(), projected);
  return q;
}

}  // namespace affinterp::global
