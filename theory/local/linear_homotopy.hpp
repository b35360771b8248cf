#pragma once
// The linear homotopy A^L(t) = (1−t)I + tA (Kaji §3; thesis Def. 2.2.3, A_l(t)). Polynomial in t, so
// exact over exact::Rational.
#include "theory/local/matrix2.hpp"

namespace affinterp::local {

template <class Scalar>
struct LinearHomotopy {
  Mat2<Scalar> A;

  Mat2<Scalar> operator()(const Scalar& t) const { return scaled(Scalar(1) - t, identity2<Scalar>()) + scaled(t, A); }
};

}  // namespace affinterp::local
