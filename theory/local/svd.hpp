#pragma once
// The singular value decomposition with rotations only, A = R_α D R_β, D = diag(x, y), x ≥ y > 0, of
// A ∈ GL+(2) (Kaji Appendix; thesis §2.2.2).
//
// Closed form: writing D = ((x+y)/2) I + ((x−y)/2) K with K = diag(1, −1), and using K R_β = R_{−β} K,
//   R_α D R_β = ((x+y)/2) R_{α+β} + ((x−y)/2) R_{α−β} K,
// so with E = (a11+a22)/2, H = (a21−a12)/2, F = (a11−a22)/2, G = (a21+a12)/2:
//   (x+y)/2 = √(E²+H²), α+β = atan2(H, E),   (x−y)/2 = √(F²+G²), α−β = atan2(G, F).
// When x = y the split of α+β is free; we take α = β.
#include "theory/local/rotation.hpp"

#include <cmath>
#include <stdexcept>

namespace affinterp::local {

template <class Scalar>
struct Svd {
  Scalar alpha;  ///< left rotation angle, in (−π, π]
  Scalar x;      ///< larger singular value
  Scalar y;      ///< smaller singular value, > 0
  Scalar beta;   ///< right rotation angle, in (−π, π]

  Mat2<Scalar> D() const {
    Mat2<Scalar> D;
    D << x, Scalar(0), Scalar(0), y;
    return D;
  }
  /// R_α D R_β.
  Mat2<Scalar> matrix() const { return rotation(alpha) * D() * rotation(beta); }
};

/// A = R_α D R_β with x ≥ y > 0; throws std::invalid_argument unless det A > 0.
template <class Scalar>
Svd<Scalar> svd(const Mat2<Scalar>& A) {
  using std::atan2;
  using std::hypot;
  if (!(det2(A) > Scalar(0))) throw std::invalid_argument("rotation-only SVD needs det A > 0");
  const Scalar E = (A(0, 0) + A(1, 1)) / 2, H = (A(1, 0) - A(0, 1)) / 2;
  const Scalar F = (A(0, 0) - A(1, 1)) / 2, G = (A(1, 0) + A(0, 1)) / 2;
  const Scalar mean = hypot(E, H), half_gap = hypot(F, G);
  const Scalar sum_angle = atan2(H, E);
  const Scalar difference_angle = half_gap == Scalar(0) ? Scalar(0) : atan2(G, F);
  return Svd<Scalar>{(sum_angle + difference_angle) / 2, mean + half_gap, mean - half_gap,
                     (sum_angle - difference_angle) / 2};
}

}  // namespace affinterp::local
