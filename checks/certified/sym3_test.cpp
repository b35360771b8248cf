// The certified references (theory/certified/sym3.hpp) on exactly known cases: zero, diagonal matrices,
// multiples of the identity, exact rational rotations of known spectra (distinct, repeated, triple),
// positive definiteness decided exactly, overflow decided, and the error balls of double results.
#include "checks/certified/helpers.hpp"
#include "theory/sym3/affinterp.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>

namespace affinterp::certified::sym3_test {
namespace {

using sym3::Mat3R100;
using testing::contains;
using testing::Real100;

/// Relative radius every certified result must reach by default (Options::relative_radius = 2⁻¹¹⁰).
constexpr double kTarget = 0x1p-110;

Mat3 diagonal(double a, double b, double c) { return Eigen::Vector3d(a, b, c).asDiagonal().toDenseMatrix(); }

TEST(CertifiedSym3, ZeroIsExactlyTheIdentity) {
  const CertifiedMatrix e = certified::exp(Mat3::Zero());
  ASSERT_EQ(e.status, Status::certified);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      EXPECT_EQ(e.value.mid(i, j), i == j ? 1.0 : 0.0);
      EXPECT_EQ(e.value.radius(i, j), 0.0);
    }
  const CertifiedEigenvalues l = certified::eigenvalues(Mat3::Zero());
  ASSERT_EQ(l.status, Status::certified);
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(l.value.entry(k).mid, 0.0);
    EXPECT_EQ(l.value.radius(k), 0.0);
  }
  EXPECT_EQ(certified::log_spd(Mat3::Zero()).status, Status::not_spd);
}

TEST(CertifiedSym3, DiagonalMatricesGiveFunctionsOfTheDiagonal) {
  const std::array<double, 3> d{1.0 / 3, -2.0, 3.5};
  const Mat3 S = diagonal(d[0], d[1], d[2]);
  const CertifiedMatrix e = certified::exp(S);
  ASSERT_EQ(e.status, Status::certified);
  Mat3R100 E = Mat3R100::Zero();
  for (int i = 0; i < 3; ++i) E(i, i) = exp(Real100(d[i]));
  EXPECT_TRUE(contains(e.value, E, Real100("1e-95")));
  EXPECT_LE(e.value.max_radius(), kTarget * std::exp(3.5) * 2);

  const CertifiedEigenvalues l = certified::eigenvalues(S);
  ASSERT_EQ(l.status, Status::certified);
  const std::array<double, 3> sorted{-2.0, 1.0 / 3, 3.5};
  for (int k = 0; k < 3; ++k) EXPECT_TRUE(l.value.entry(k).contains(sorted[k])) << k;

  const Mat3 P = diagonal(1.0 / 3, 2.0, 1e-300);
  const CertifiedMatrix lg = certified::log_spd(P), root = certified::pow_spd(P, 0.5);
  ASSERT_EQ(lg.status, Status::certified);
  ASSERT_EQ(root.status, Status::certified);
  for (int i = 0; i < 3; ++i) {
    EXPECT_TRUE(contains(lg.value, i, i, log(Real100(P(i, i))), Real100("1e-95"))) << i;
    EXPECT_TRUE(contains(root.value, i, i, sqrt(Real100(P(i, i))), Real100("1e-240"))) << i;
  }
  EXPECT_TRUE(contains(lg.value, 0, 1, Real100(0), Real100(0)));
}

TEST(CertifiedSym3, MultiplesOfTheIdentity) {
  for (const double lambda : {0.7, -3.25, 700.0, -740.0, 1e-310, -1e300}) {
    const Mat3 S = lambda * Mat3::Identity();
    const CertifiedMatrix e = certified::exp(S);
    ASSERT_EQ(e.status, Status::certified) << lambda;
    if (lambda < -1e5) {  // e^λ far below the smallest subnormal
      for (int i = 0; i < 3; ++i)
        EXPECT_TRUE(e.value.entry(i, i).lower() <= 0 && e.value.entry(i, i).upper() <= 1e-323);
    } else {
      const Real100 expected = exp(Real100(lambda));
      const Mat3R100 E = expected * Mat3R100::Identity();
      EXPECT_TRUE(contains(e.value, E, expected * Real100("1e-95"))) << lambda;
    }
    const CertifiedEigenvalues l = certified::eigenvalues(S);
    ASSERT_EQ(l.status, Status::certified);
    for (int k = 0; k < 3; ++k) EXPECT_TRUE(l.value.entry(k).contains(lambda)) << lambda;
  }
  EXPECT_EQ(certified::exp(710 * Mat3::Identity()).status, Status::overflows);
  const CertifiedMatrix near = certified::exp(709.7 * Mat3::Identity());
  EXPECT_EQ(near.status, Status::certified);  // e^709.7 < DBL_MAX
  EXPECT_TRUE(std::isfinite(near.value.mid(0, 0)));
}

/// R = R̃/25 with R̃ the rotation matrix of the quaternion (1, 2, 2, 4) times |q|² = 25: integer entries.
Eigen::Matrix3i rotation_times_25() {
  const int w = 1, x = 2, y = 2, z = 4;
  Eigen::Matrix3i R;
  R << w * w + x * x - y * y - z * z, 2 * (x * y - w * z), 2 * (x * z + w * y),  //
      2 * (x * y + w * z), w * w - x * x + y * y - z * z, 2 * (y * z - w * x),   //
      2 * (x * z - w * y), 2 * (y * z + w * x), w * w - x * x - y * y + z * z;
  return R;
}

/// S = R diag(625 μ) Rᵀ = R̃ diag(μ) R̃ᵀ: exact doubles for dyadic μ; eigenvalues exactly 625 μ.
Mat3 rotated(const std::array<double, 3>& mu) {
  const Eigen::Matrix3d Rt = rotation_times_25().cast<double>();
  Mat3 S;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      S(i, j) = mu[0] * Rt(i, 0) * Rt(j, 0) + mu[1] * Rt(i, 1) * Rt(j, 1) + mu[2] * Rt(i, 2) * Rt(j, 2);
  return S;
}

/// R diag(f(625 μ)) Rᵀ in Real100.
template <class F>
Mat3R100 rotated_function(const std::array<double, 3>& mu, F f) {
  const Eigen::Matrix3i Rt = rotation_times_25();
  Mat3R100 E = Mat3R100::Zero();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) E(i, j) += f(Real100(625) * mu[k]) * Rt(i, k) * Rt(j, k) / Real100(625);
  return E;
}

TEST(CertifiedSym3, ExactRationalRotationsOfKnownSpectra) {
  ASSERT_EQ(rotation_times_25() * rotation_times_25().transpose(), 625 * Eigen::Matrix3i::Identity());
  // Distinct, a repeated pair, a triple (λI in a rotated basis), and a pair 625·2⁻⁴⁰ apart.
  const std::array<std::array<double, 3>, 4> spectra{{{1.0 / 256, 2.0 / 256, -3.0 / 256},
                                                      {1.0 / 256, 1.0 / 256, -3.0 / 256},
                                                      {5.0 / 256, 5.0 / 256, 5.0 / 256},
                                                      {1.0 / 256, 1.0 / 256 + 0x1p-40, 3.0 / 256}}};
  for (const auto& mu : spectra) {
    const Mat3 S = rotated(mu);
    const CertifiedEigenvalues l = certified::eigenvalues(S);
    ASSERT_EQ(l.status, Status::certified);
    std::array<double, 3> lambda{625 * mu[0], 625 * mu[1], 625 * mu[2]};
    std::sort(lambda.begin(), lambda.end());
    for (int k = 0; k < 3; ++k) {
      EXPECT_TRUE(l.value.entry(k).contains(lambda[k])) << k << ": " << l.value.to_string(k);
      EXPECT_LE(l.value.radius(k), kTarget * 625 * 3 / 256.0 * 2);
    }
    const CertifiedMatrix e = certified::exp(S);
    ASSERT_EQ(e.status, Status::certified);
    const Mat3R100 E = rotated_function(mu, [](const Real100& x) { return exp(x); });
    EXPECT_TRUE(contains(e.value, E, Real100("1e-90")));
    EXPECT_LE(e.value.frobenius_radius(), kTarget * 3 * e.value.frobenius_norm().mid);
    if (mu[2] > 0) {
      const CertifiedMatrix lg = certified::log_spd(S), p = certified::pow_spd(S, -0.75);
      ASSERT_EQ(lg.status, Status::certified);
      ASSERT_EQ(p.status, Status::certified);
      EXPECT_TRUE(contains(lg.value, rotated_function(mu, [](const Real100& x) { return log(x); }), Real100("1e-90")));
      EXPECT_TRUE(contains(p.value, rotated_function(mu, [](const Real100& x) { return pow(x, Real100(-0.75)); }),
                           Real100("1e-90")));
    } else {
      EXPECT_EQ(certified::log_spd(S).status, Status::not_spd);
    }
  }
}

TEST(CertifiedSym3, PositiveDefinitenessIsDecidedExactly) {
  Mat3 singular;
  singular << 1, 1, 0, 1, 1, 0, 0, 0, 1;  // eigenvalues 0, 1, 2
  EXPECT_EQ(certified::log_spd(singular).status, Status::not_spd);
  EXPECT_EQ(certified::pow_spd(-Mat3::Identity(), 0.5).status, Status::not_spd);
  // The smallest subnormal as an eigenvalue: positive definite, log certified.
  const double tiny = std::numeric_limits<double>::denorm_min();
  const CertifiedMatrix lg = certified::log_spd(diagonal(1, 2, tiny));
  ASSERT_EQ(lg.status, Status::certified);
  EXPECT_TRUE(contains(lg.value, 2, 2, log(Real100(tiny)), Real100("1e-90")));
  // A graded matrix across the whole range: κ₂ ≈ 10⁶¹⁰ still certified (more bits).
  Mat3 graded;
  graded << 1e300, 1e-5, 0, 1e-5, 1, 1e-160, 0, 1e-160, 1e-310;
  const CertifiedMatrix g = certified::log_spd(graded);
  EXPECT_EQ(g.status, Status::certified);
  EXPECT_GT(g.bits, 1024);
}

TEST(CertifiedSym3, OverflowOfExpIsDecided) {
  EXPECT_EQ(certified::exp(diagonal(710, 0, 0)).status, Status::overflows);  // e^710 > DBL_MAX
  EXPECT_EQ(certified::exp(diagonal(1e300, 0, 0)).status, Status::overflows);
  EXPECT_EQ(certified::exp(diagonal(-1e300, 1, 2)).status, Status::certified);
  // λ = 710.5 on the eigenvector (3, 4, 0)/5: entries 0.36, 0.48 and 0.64 times e^710.5 ≈ 3.7·10³⁰⁸;
  // the (2, 2) entry overflows, and the status says so.
  Mat3 spread = Mat3::Zero();
  spread.block<2, 2>(0, 0) << 0.36, 0.48, 0.48, 0.64;
  EXPECT_EQ(certified::exp(710.5 * spread).status, Status::overflows);
  EXPECT_EQ(certified::exp(709.5 * spread).status, Status::certified);
}

TEST(CertifiedSym3, TaylorAgreesWithTheRotationMethod) {
  Mat3 S;
  S << 2, 1, 0.5, 1, -3, 0.25, 0.5, 0.25, 0.125;
  for (const double scale : {1.0, 1e-200, 40.0}) {
    const CertifiedMatrix a = certified::exp(scale * S), b = certified::exp_taylor(scale * S, 256);
    ASSERT_EQ(a.status, Status::certified);
    ASSERT_EQ(b.status, Status::certified);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const Ball x = a.value.entry(i, j), y = b.value.entry(i, j);
        EXPECT_TRUE(x.lower() <= y.upper() && y.lower() <= x.upper()) << scale << " " << i << j;
      }
  }
}

TEST(CertifiedSym3, ErrorBallsOfDoubleResults) {
  Mat3 S;
  S << 2, 1, 0.5, 1, -3, 0.25, 0.5, 0.25, 0.125;
  const CertifiedMatrix e = certified::exp(S);
  ASSERT_EQ(e.status, Status::certified);
  const Ball error = relative_error(sym3::exp_affinterp(S), e.value);
  EXPECT_LE(error.upper(), 2e-15);
  EXPECT_TRUE(certifies(error)) << error.mid << " ± " << error.rad;
  Mat3 broken = sym3::exp_affinterp(S);
  broken(1, 1) = INFINITY;
  EXPECT_EQ(relative_error(broken, e.value).mid, INFINITY);
  // The midpoints rounded to double are themselves within 2⁻⁵³ of the truth.
  Mat3 rounded;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) rounded(i, j) = e.value.mid(i, j);
  EXPECT_LE(relative_error(rounded, e.value).upper(), 0x1p-53);
  const CertifiedEigenvalues l = certified::eigenvalues(S);
  EXPECT_LE(eigenvalue_error(sym3::eigenvalues_affinterp(S), l.value).upper(), 4e-15);
}

}  // namespace
}  // namespace affinterp::certified::sym3_test
