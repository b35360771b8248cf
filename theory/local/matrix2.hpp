#pragma once
// 2×2 and 3×3 matrices over any scalar (double, exact::Real50, exact::Rational, ...), the shapes of the
// local theory: linear parts A ∈ GL+(2), affine maps Â ∈ Aff(2), triangles as three column vertices.
#include <Eigen/Core>

namespace affinterp::local {

template <class Scalar>
using Mat2 = Eigen::Matrix<Scalar, 2, 2>;
template <class Scalar>
using Vec2 = Eigen::Matrix<Scalar, 2, 1>;
template <class Scalar>
using Mat3 = Eigen::Matrix<Scalar, 3, 3>;
/// A triangle (p1, p2, p3) as the columns of a 2×3 matrix.
template <class Scalar>
using Triangle = Eigen::Matrix<Scalar, 2, 3>;

/// The identity I of the homotopies A(0) = I.
template <class Scalar>
Mat2<Scalar> identity2() {
  Mat2<Scalar> I;
  I << Scalar(1), Scalar(0), Scalar(0), Scalar(1);
  return I;
}

/// s·M. (Boost 1.74's cpp_rational cannot meet Eigen's scalar-times-matrix operators nor its product
/// evaluator; scaled() and lazyProduct() work for every scalar, so templates that run over exact::Rational
/// use them.)
template <class Scalar, class Derived>
auto scaled(const Scalar& s, const Eigen::MatrixBase<Derived>& M) {
  return M.unaryExpr([s](const Scalar& m) { return Scalar(s * m); });
}

/// Entrywise equality (for exact scalars; Eigen's operator== does not compile over cpp_rational).
template <class DerivedA, class DerivedB>
bool exactly_equal(const Eigen::MatrixBase<DerivedA>& a, const Eigen::MatrixBase<DerivedB>& b) {
  for (Eigen::Index i = 0; i < a.rows(); ++i)
    for (Eigen::Index j = 0; j < a.cols(); ++j)
      if (!(a(i, j) == b(i, j))) return false;
  return true;
}

/// det of a 2×2 matrix, written out so that it is exact for exact scalars.
template <class Scalar>
Scalar det2(const Mat2<Scalar>& A) {
  return A(0, 0) * A(1, 1) - A(0, 1) * A(1, 0);
}

}  // namespace affinterp::local
