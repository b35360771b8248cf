#include "experiments/claims/sym3/exact_spectrum.hpp"

namespace affinterp::claims::sym3 {

using affinterp::sym3::Mat3R100;
using exact::Real100;

namespace {

/// A · B over the rationals. (Eigen's operators on cpp_rational matrices do not compile with Boost
/// 1.74: its operator templates probe Eigen expressions as byte containers, a hard error.)
Mat3Q product(const Mat3Q& A, const Mat3Q& B) {
  Mat3Q C;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) C(i, j) = A(i, 0) * B(0, j) + A(i, 1) * B(1, j) + A(i, 2) * B(2, j);
  return C;
}

/// The inverse of an invertible rational 3×3 matrix: adjugate / determinant.
Mat3Q inverse(const Mat3Q& A) {
  Mat3Q adj;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      const int r0 = (j + 1) % 3, r1 = (j + 2) % 3, c0 = (i + 1) % 3, c1 = (i + 2) % 3;
      adj(i, j) = A(r0, c0) * A(r1, c1) - A(r0, c1) * A(r1, c0);
    }
  }
  const Rational det = A(0, 0) * adj(0, 0) + A(0, 1) * adj(1, 0) + A(0, 2) * adj(2, 0);
  adj /= det;
  return adj;
}

}  // namespace

Mat3Q cayley(const Vec3Q& k) {
  Mat3Q I_minus_K, I_plus_K;
  I_minus_K << 1, k(2), -k(1), -k(2), 1, k(0), k(1), -k(0), 1;
  I_plus_K << 1, -k(2), k(1), k(2), 1, -k(0), -k(1), k(0), 1;
  return product(I_minus_K, inverse(I_plus_K));
}

ExactSpectrum with_exact_eigenvalues(const Vec3Q& lambda, const Vec3Q& k) {
  ExactSpectrum e{lambda, cayley(k), {}};
  Mat3Q Q_Lambda = e.Q;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) Q_Lambda(i, j) *= lambda(j);
  e.S = product(Q_Lambda, e.Q.transpose());
  return e;
}

Rational small_rational(Rng& rng, int max_numerator, int max_denominator) {
  return Rational(rng.integer(-max_numerator, max_numerator)) / rng.integer(1, max_denominator);
}

Vec3Q small_axis(Rng& rng) {
  return Vec3Q(small_rational(rng, 3, 2), small_rational(rng, 3, 2), small_rational(rng, 3, 2));
}

Mat3R100 exact_exp(const ExactSpectrum& e) {
  const Mat3R100 Q = affinterp::sym3::to_real100(e.Q);
  Mat3R100 D = Mat3R100::Zero();
  for (int i = 0; i < 3; ++i) D(i, i) = exp(Real100(e.lambda(i)));
  return Q * D * Q.transpose();
}

Real100 relative_deviation(const Mat3R100& A, const Mat3R100& B) {
  Real100 diff = 0, norm = 0;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      diff += (A(i, j) - B(i, j)) * (A(i, j) - B(i, j));
      norm += B(i, j) * B(i, j);
    }
  }
  return sqrt(diff / norm);
}

}  // namespace affinterp::claims::sym3
