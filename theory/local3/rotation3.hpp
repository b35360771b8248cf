#pragma once
// Rotations of ℝ³ by their axis-angle vector ω (R = exp [ω]×, the rotation by |ω| about ω/|ω|): the
// exponential by Rodrigues' formula and its principal logarithm |ω| ≤ π, the 3D counterparts of
// theory/local/rotation.hpp's R_θ and principal angle. Templated over the scalar (double, long double, and
// Boost.Multiprecision floats with ADL sin/cos/atan2/sqrt).
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <boost/math/constants/constants.hpp>

#include <cmath>
#include <type_traits>

namespace affinterp::local3 {

template <class Scalar>
using Mat3 = Eigen::Matrix<Scalar, 3, 3>;
template <class Scalar>
using Vec3 = Eigen::Matrix<Scalar, 3, 1>;

template <class Scalar>
Scalar pi() {
  return boost::math::constants::pi<Scalar>();
}

/// [ω]×, the skew-symmetric matrix with [ω]× v = ω × v.
template <class Scalar>
Mat3<Scalar> cross_matrix(const Vec3<Scalar>& omega) {
  Mat3<Scalar> K;
  K << Scalar(0), -omega.z(), omega.y(), omega.z(), Scalar(0), -omega.x(), -omega.y(), omega.x(), Scalar(0);
  return K;
}

/// exp [ω]× = I + (sin θ/θ) K + ((1 − cos θ)/θ²) K², θ = |ω|, K = [ω]× (Rodrigues). Any |ω|, so that a branch
/// ω + 2πk ω/|ω| gives the same rotation. Both coefficients come from the half angle, s = sin(θ/2), c = cos(θ/2):
/// sin θ/θ = 2sc/θ and (1 − cos θ)/θ² = 2s²/θ², which, unlike 1 − cos θ, keep their relative accuracy as θ → 0
/// (one sine and one cosine a rotation); both are their limits at θ = 0.
template <class Scalar>
Mat3<Scalar> rotation_exp(const Vec3<Scalar>& omega) {
  using std::cos;
  using std::sin;
  const Scalar theta = omega.norm();
  const Mat3<Scalar> K = cross_matrix(omega);
  Scalar a(1), b(0.5);
  if (theta > Scalar(0)) {
    const Scalar half = theta / 2, s = sin(half), sinc_half = s / half;
    a = sinc_half * cos(half);
    b = sinc_half * sinc_half / 2;
  }
  return Mat3<Scalar>::Identity() + a * K + b * (K * K);
}

/// exp [ω]× exp [η]×, the rotation by η then by ω, through unit quaternions: q(ω) = (cos(θ/2), (sin(θ/2)/θ) ω) with
/// θ = |ω| (its limit (1, ω/2) at θ = 0), the product q = q(ω) q(η) written out, and R = (w² − |v|²) I + 2 v vᵀ +
/// 2w [v]× for q = (w, v); no 3 × 3 product: the rotation paths' carrier and remainder
/// (theory/global3/rotation_carrier3.hpp) in every frame. In double, a half-angle h = θ/2 ≤ 1/4 (a remainder's, as a
/// rule) takes cos h and sin(h)/h from their Taylor series in h² to h¹⁴, whose first omitted term is below 10⁻²²:
/// no square root and no call to the sine and cosine.
template <class Scalar>
Mat3<Scalar> rotation_exp_product(const Vec3<Scalar>& omega, const Vec3<Scalar>& eta) {
  using std::cos;
  using std::sin;
  const auto half_turn = [](const Vec3<Scalar>& x, Scalar& w, Vec3<Scalar>& v) {
    if constexpr (std::is_same_v<Scalar, double>) {
      if (const double h2 = x.squaredNorm() / 4; h2 <= 1.0 / 16) {
        w = 1 +
            h2 * (-1. / 2 +
                  h2 * (1. / 24 + h2 * (-1. / 720 +
                                        h2 * (1. / 40320 + h2 * (-1. / 3628800 +
                                                                 h2 * (1. / 479001600 + h2 * (-1. / 87178291200.)))))));
        const double sinc =
            1 + h2 * (-1. / 6 +
                      h2 * (1. / 120 +
                            h2 * (-1. / 5040 +
                                  h2 * (1. / 362880 + h2 * (-1. / 39916800 +
                                                            h2 * (1. / 6227020800 + h2 * (-1. / 1307674368000.)))))));
        v = (sinc / 2) * x;
        return;
      }
    }
    const Scalar theta = x.norm();
    Scalar scale(0.5);
    w = Scalar(1);
    if (theta > Scalar(0)) {
      const Scalar half = theta / 2;
      scale = sin(half) / theta;
      w = cos(half);
    }
    v = scale * x;
  };
  Scalar a, b;
  Vec3<Scalar> u, v;
  half_turn(omega, a, u);
  half_turn(eta, b, v);
  const Scalar w = a * b - u.dot(v);
  const Vec3<Scalar> q = a * v + b * u + u.cross(v);
  Mat3<Scalar> R = (w * w - q.squaredNorm()) * Mat3<Scalar>::Identity() + 2 * (q * q.transpose());
  R += 2 * w * cross_matrix(q);
  return R;
}

/// The principal logarithm of R ∈ SO(3): ω with exp [ω]× = R and θ = |ω| ∈ [0, π]. θ = atan2(|v|, c) with
/// c = (tr R − 1)/2 = cos θ and v = vee(R − Rᵀ)/2 = sin θ · axis, accurate at every angle. The axis comes from v
/// where c ≥ 0; where c < 0 (θ > π/2) from the symmetric part (R + Rᵀ)/2 − cI = (1 − c) axis axisᵀ, whose largest
/// column does not lose accuracy as θ → π (v → 0 does), with its sign taken from v. At θ = π exactly both ±π·axis
/// are principal; the one whose largest-magnitude component is positive is returned.
template <class Scalar>
Vec3<Scalar> rotation_log(const Mat3<Scalar>& R) {
  using std::atan2;
  using std::sqrt;
  const Vec3<Scalar> v{(R(2, 1) - R(1, 2)) / 2, (R(0, 2) - R(2, 0)) / 2, (R(1, 0) - R(0, 1)) / 2};
  const Scalar c = (R.trace() - 1) / 2, s = v.norm();
  const Scalar theta = atan2(s, c);
  if (c >= Scalar(0)) return s > Scalar(0) ? Vec3<Scalar>((theta / s) * v) : Vec3<Scalar>::Zero();
  const Mat3<Scalar> B = (R + R.transpose()) / 2 - c * Mat3<Scalar>::Identity();
  Eigen::Index j = 0;
  B.diagonal().maxCoeff(&j);
  Vec3<Scalar> axis = B.col(j) / sqrt(B(j, j) * (1 - c));
  axis.normalize();
  if (axis.dot(v) < Scalar(0)) axis = -axis;
  return theta * axis;
}

}  // namespace affinterp::local3
