#pragma once
// The SVD homotopy of [ACOL00] (thesis Def. 2.2.4): A_s(t) = R_{tα}((1−t)I + tD)R_{tβ} for
// A = R_α D R_β. The path depends on the chosen angles (α, β), not only on A, so it is built from them.
#include "theory/local/svd.hpp"

namespace affinterp::local {

template <class Scalar>
struct SvdHomotopy {
  Svd<Scalar> decomposition;  ///< (α, x, y, β); α, β may be any representatives

  /// With the principal angles of svd(A).
  static SvdHomotopy of(const Mat2<Scalar>& A) { return SvdHomotopy{svd(A)}; }

  Mat2<Scalar> operator()(const Scalar& t) const {
    const Mat2<Scalar> blend = (Scalar(1) - t) * identity2<Scalar>() + t * decomposition.D();
    return rotation<Scalar>(t * decomposition.alpha) * blend * rotation<Scalar>(t * decomposition.beta);
  }
};

}  // namespace affinterp::local
