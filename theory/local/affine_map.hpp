#pragma once
// Kaji et al. eq. (1): the unique affine map Â taking a source triangle onto a target triangle,
//   Â = [x'; y'; 1 1 1] · [x; y; 1 1 1]⁻¹ = [[A, d], [0 0 1]],
// with linear part A and translation part d. Templated on the scalar so that it is exact over
// exact::Rational.
#include "theory/local/matrix2.hpp"

#include <stdexcept>

namespace affinterp::local {

template <class Scalar>
struct AffineMap {
  Mat3<Scalar> A_hat;  ///< the 3×3 matrix of eq. (1)
  Mat2<Scalar> A;      ///< linear part
  Vec2<Scalar> d;      ///< translation part d_Â
};

/// [x1 x2 x3; y1 y2 y3; 1 1 1] of eq. (1).
template <class Scalar>
Mat3<Scalar> homogeneous(const Triangle<Scalar>& p) {
  Mat3<Scalar> H;
  H.template topRows<2>() = p;
  H.row(2).setConstant(Scalar(1));
  return H;
}

/// Inverse by the adjugate, exact over exact scalars; throws std::invalid_argument when singular.
template <class Scalar>
Mat3<Scalar> inverse3(const Mat3<Scalar>& M) {
  Mat3<Scalar> adj;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const int r0 = (j + 1) % 3, r1 = (j + 2) % 3, c0 = (i + 1) % 3, c1 = (i + 2) % 3;
      adj(i, j) = M(r0, c0) * M(r1, c1) - M(r0, c1) * M(r1, c0);  // cyclic order gives the sign
    }
  const Scalar det = M(0, 0) * adj(0, 0) + M(0, 1) * adj(1, 0) + M(0, 2) * adj(2, 0);
  if (det == Scalar(0)) throw std::invalid_argument("degenerate source triangle: eq. (1) has no inverse");
  return scaled(Scalar(1) / det, adj);
}

/// Kaji eq. (1): the affine map with Â p_k = q_k (k = 1, 2, 3) for a non-degenerate source p.
template <class Scalar>
AffineMap<Scalar> affine_map(const Triangle<Scalar>& p, const Triangle<Scalar>& q) {
  AffineMap<Scalar> map;
  map.A_hat = homogeneous(q).lazyProduct(inverse3(homogeneous(p)));
  map.A = map.A_hat.template topLeftCorner<2, 2>();
  map.d = map.A_hat.template topRightCorner<2, 1>();
  return map;
}

}  // namespace affinterp::local
