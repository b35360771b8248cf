#include "theory/sym3/wide_range.hpp"

#include "theory/exact/rational.hpp"

#include <boost/multiprecision/cpp_bin_float.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <type_traits>

namespace affinterp::sym3::wide_range {
namespace {

namespace mp = boost::multiprecision;
template <unsigned Bits>
using Real = mp::number<mp::cpp_bin_float<Bits, mp::digit_base_2>, mp::et_off>;

/// √x (x ≥ 0) by Newton's iteration from the double square root of the mantissa: Boost's own sqrt is
/// much slower at these precisions.
template <unsigned Bits>
Real<Bits> square_root(const Real<Bits>& x) {
  if (!(x > 0)) return Real<Bits>(0);
  int e = 0;
  Real<Bits> m = frexp(x, &e);  // x = m·2^e, m ∈ [1/2, 1)
  if (e % 2 != 0) m = ldexp(m, 1), --e;
  Real<Bits> y = std::sqrt(static_cast<double>(m));
  for (int bits = 48; bits < static_cast<int>(Bits) + 16; bits *= 2) y = ldexp(y + m / y, -1);
  return ldexp(y, e / 2);
}

/// S = V diag(lambda) Vᵀ at Bits bits.
template <unsigned Bits>
struct Decomposition {
  std::array<Real<Bits>, 3> lambda;
  std::array<std::array<Real<Bits>, 3>, 3> V;  ///< V[i][k]: entry i of the k-th eigenvector
  Real<Bits> norm;                             ///< ‖S‖_F
};

/// Cyclic Jacobi (Golub & Van Loan, Alg. 8.5.2). An off-diagonal entry is annihilated while it exceeds
/// 2^−(Bits+8) √|a_pp a_qq| (the criterion of Demmel & Veselić, which gives positive definite matrices
/// their small eigenvalues to relative accuracy), or 2^−2·Bits ‖S‖_F for indefinite diagonals.
template <unsigned Bits>
Decomposition<Bits> jacobi(const Mat3& S) {
  using R = Real<Bits>;
  R a[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) a[i][j] = R(S(std::min(i, j), std::max(i, j)));  // the upper triangle, exactly
  Decomposition<Bits> out;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) out.V[i][j] = i == j ? 1 : 0;
  R norm2 = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) norm2 += a[i][j] * a[i][j];
  out.norm = square_root(norm2);
  // Compared in squares: a_pq² against 2^−2(Bits+8) |a_pp a_qq| and (2^−2·Bits ‖S‖_F)².
  const R floor2 = ldexp(norm2, -4 * static_cast<int>(Bits));
  constexpr std::array<std::array<int, 2>, 3> pairs{{{0, 1}, {0, 2}, {1, 2}}};
  for (int sweep = 0; sweep < 100; ++sweep) {
    bool rotated = false;
    for (const auto [p, q] : pairs) {
      const R apq = a[p][q];
      const R apq2 = apq * apq;
      if (apq2 <= floor2 || apq2 <= ldexp(abs(a[p][p] * a[q][q]), -2 * static_cast<int>(Bits) - 16)) continue;
      rotated = true;
      const R theta = (a[q][q] - a[p][p]) / (2 * apq);
      R t = 1 / (abs(theta) + square_root(theta * theta + 1));
      if (theta < 0) t = -t;
      const R c = 1 / square_root(t * t + 1), s = t * c;
      a[p][p] -= t * apq;
      a[q][q] += t * apq;
      a[p][q] = a[q][p] = 0;
      const int r = 3 - p - q;
      const R g = a[r][p], h = a[r][q];
      a[r][p] = a[p][r] = c * g - s * h;
      a[r][q] = a[q][r] = s * g + c * h;
      for (int i = 0; i < 3; ++i) {
        const R vp = out.V[i][p], vq = out.V[i][q];
        out.V[i][p] = c * vp - s * vq;
        out.V[i][q] = s * vp + c * vq;
      }
    }
    if (!rotated) break;
  }
  for (int k = 0; k < 3; ++k) out.lambda[k] = a[k][k];
  return out;
}

/// Σ_k f_k v_k v_kᵀ, rounded once to double.
template <unsigned Bits>
Mat3 assemble(const Decomposition<Bits>& d, const std::array<Real<Bits>, 3>& f) {
  Mat3 X;
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j) {
      Real<Bits> sum = 0;
      for (int k = 0; k < 3; ++k) sum += f[k] * d.V[i][k] * d.V[j][k];
      X(i, j) = X(j, i) = static_cast<double>(sum);
    }
  return X;
}

/// e^y for y in long double (64-bit mantissa), clamped where the double result is settled anyway:
/// e^1000 overflows every entry it reaches, e^−1100 is below half the smallest subnormal.
template <class R>
R exp_of(long double y) {
  if (y < -1100) return 0;
  return R(std::exp(std::min(y, 1000.0L)));
}

/// log λ for λ > 0 in long double: log λ = k log 2 + log1p(m − 1), m = λ 2^−k ∈ [√½, √2).
template <unsigned Bits>
long double log_of(const Real<Bits>& lambda) {
  int k = 0;
  Real<Bits> m = frexp(lambda, &k);
  if (m < Real<Bits>(0.70710678118654752)) m = ldexp(m, 1), --k;
  return k * 0.693147180559945309417232121458176568L + std::log1p(static_cast<long double>(m - 1));
}

/// det S, exactly (the double entries taken as rationals).
exact::Rational determinant(const Mat3& S) {
  using exact::from_double;
  const exact::Rational a = from_double(S(0, 0)), b = from_double(S(0, 1)), c = from_double(S(0, 2)),
                        d = from_double(S(1, 1)), e = from_double(S(1, 2)), f = from_double(S(2, 2));
  return a * (d * f - e * e) - b * (b * f - e * c) + c * (b * e - d * c);
}

/// Positive definiteness decided exactly: Sylvester's criterion on the leading principal minors.
bool positive_definite(const Mat3& S) {
  using exact::from_double;
  const exact::Rational a = from_double(S(0, 0)), b = from_double(S(0, 1)), d = from_double(S(1, 1));
  return a > 0 && a * d - b * b > 0 && determinant(S) > 0;
}

/// The decomposition of an SPD matrix with its smallest eigenvalue to 64 bits or more: 1152 bits
/// when they give it (λ_min ≥ 2^−1088 ‖S‖_F, always enough for κ₂ below 2¹⁰⁸⁸), else 2304.
template <class F>
Mat3 spd_function(const Mat3& S, F f) {
  if (!positive_definite(S)) throw std::domain_error("sym3: matrix is not symmetric positive definite");
  const auto apply = [&](const auto& d) {
    using R = std::decay_t<decltype(d.norm)>;
    std::array<R, 3> values;
    for (int k = 0; k < 3; ++k) values[k] = f(d.lambda[k]);
    return assemble(d, values);
  };
  const auto d = jacobi<1152>(S);
  if (*std::min_element(d.lambda.begin(), d.lambda.end()) >= ldexp(d.norm, -1088)) return apply(d);
  auto wide = jacobi<2304>(S);
  // Beyond even 2304 bits (κ₂ > 2²²⁴⁰, possible only for nearly singular matrices with entries across
  // the whole range) a rounded-away smallest eigenvalue is recovered from the exact determinant.
  for (int k = 0; k < 3; ++k) {
    if (wide.lambda[k] > 0) continue;
    using R = Real<2304>;
    const exact::Rational det = determinant(S);
    const R others = wide.lambda[(k + 1) % 3] * wide.lambda[(k + 2) % 3];
    wide.lambda[k] = R(mp::numerator(det)) / R(mp::denominator(det)) / others;
  }
  return apply(wide);
}

}  // namespace

Mat3 exp(const Mat3& S) {
  const auto d = jacobi<1152>(S);
  std::array<Real<1152>, 3> f;
  for (int k = 0; k < 3; ++k) f[k] = exp_of<Real<1152>>(static_cast<long double>(d.lambda[k]));
  return assemble(d, f);
}

Vec3 eigenvalues(const Mat3& S) {
  auto d = jacobi<1152>(S);
  std::sort(d.lambda.begin(), d.lambda.end());
  return Vec3(static_cast<double>(d.lambda[0]), static_cast<double>(d.lambda[1]), static_cast<double>(d.lambda[2]));
}

Mat3 pow_spd(const Mat3& S, double t) {
  return spd_function(S, [t](const auto& lambda) {
    using R = std::decay_t<decltype(lambda)>;
    return exp_of<R>(t * log_of(lambda));
  });
}

Mat3 log_spd(const Mat3& S) {
  return spd_function(S, [](const auto& lambda) {
    using R = std::decay_t<decltype(lambda)>;
    return R(log_of(lambda));
  });
}

}  // namespace affinterp::sym3::wide_range
