// Ours (exp, eigenvalues, S^t, log; scalar and batched) on the whole double range, against the certified
// references (theory/certified): RapidCheck generators whose entries draw sign, mantissa and exponent
// separately, from subnormal to near the largest double, and spectra around exp's overflow and underflow.
// The bounds tested are the ones theory/sym3/affinterp.hpp states.
#include "theory/certified/sym3.hpp"
#include "theory/linalg/symmetric.hpp"
#include "theory/sym3/affinterp.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <limits>
#include <sstream>
#include <vector>

namespace affinterp::sym3::full_range_test {
namespace {

constexpr double kEps = 0x1p-53;
/// The absolute floor of exp's bound: results near and below the smallest normal double are rounded
/// once per entry (3·2⁻¹⁰⁷⁵ in Frobenius norm); 2⁻¹⁰⁷² leaves room.
constexpr double kExpFloor = 0x1p-1072;

std::string show(const Mat3& S) {
  std::ostringstream out;
  out << std::setprecision(17) << S(0, 0) << " " << S(1, 1) << " " << S(2, 2) << " " << S(0, 1) << " " << S(0, 2) << " "
      << S(1, 2);
  return out.str();
}

/// RapidCheck scales inRange with the test's size; resized to the maximum, every case spans the range.
template <class T>
rc::Gen<T> uniform(T lo, T hi_inclusive) {
  return rc::gen::resize(100, rc::gen::inRange<T>(lo, hi_inclusive + 1));
}

/// ±(1 + m) 2^e: sign, 52-bit mantissa m and exponent e ∈ [lo, hi] drawn separately (ldexp rounds once
/// where 2^e is subnormal).
rc::Gen<double> across(int lo, int hi) {
  return rc::gen::apply(
      [](bool negative, std::uint64_t mantissa, int e) {
        return (negative ? -1.0 : 1.0) * std::ldexp(1.0 + static_cast<double>(mantissa) * 0x1p-52, e);
      },
      rc::gen::arbitrary<bool>(), uniform<std::uint64_t>(0, (std::uint64_t{1} << 52) - 1), uniform(lo, hi));
}

Mat3 symmetric(const std::vector<double>& e) {
  Mat3 S;
  S << e[0], e[3], e[4], e[3], e[1], e[5], e[4], e[5], e[2];
  return S;
}

/// Six entries with exponents anywhere in [−1074, 1023].
rc::Gen<Mat3> whole_range() {
  return rc::gen::map(rc::gen::container<std::vector<double>>(6, across(-1074, 1023)), symmetric);
}

/// Tiny and subnormal entries: a common exponent e ∈ [−1074, −30], each entry within 60 binades below.
rc::Gen<Mat3> tiny() {
  return rc::gen::mapcat(uniform(-1074, -30), [](int e) {
    return rc::gen::map(rc::gen::container<std::vector<double>>(6, across(e - 60, e)), symmetric);
  });
}

/// A uniform double in [lo, hi] on a grid of 2²⁰ steps.
rc::Gen<double> between(double lo, double hi) {
  return rc::gen::map(uniform(0, 1 << 20), [lo, hi](int k) { return lo + (hi - lo) * k * 0x1p-20; });
}

/// Q diag(λ) Qᵀ (exactly symmetric) with λmax ∈ [top_lo, top_hi], the others in [bottom, λmax].
rc::Gen<Mat3> spectrum_near(double top_lo, double top_hi, double bottom) {
  return rc::gen::apply(
      [bottom](double top, int a, int b, const std::vector<int>& q) {
        const Eigen::Vector3d lambda(top, bottom + (top - bottom) * a * 0x1p-20, bottom + (top - bottom) * b * 0x1p-20);
        Eigen::Quaterniond quaternion(q[0] + 0.5, q[1], q[2], q[3]);
        return Mat3(linalg::congruence(quaternion.normalized().toRotationMatrix(), lambda));
      },
      between(top_lo, top_hi), uniform(0, 1 << 20), uniform(0, 1 << 20),
      rc::gen::container<std::vector<int>>(4, uniform(-1000, 1000)));
}

/// −(1 + m) 2^e (e ∈ [30, 1023]) on the diagonal beside a 2×2 block with moderate diagonal and
/// off-diagonal entries down to subnormal, coupled by entries of 2^[−1074, −500] or 0.
rc::Gen<Mat3> mixed_scales() {
  return rc::gen::apply(
      [](double huge, double a, double b, double c, double couple1, double couple2, bool zero1, bool zero2) {
        return symmetric({-std::abs(huge), a, b, zero1 ? 0.0 : couple1, zero2 ? 0.0 : couple2, c});
      },
      across(30, 1023), between(-5, 5), between(-5, 5), across(-1074, 2), across(-1074, -500), across(-1074, -500),
      rc::gen::arbitrary<bool>(), rc::gen::arbitrary<bool>());
}

/// [[−a, ±ac], [±ac, −a]] ⊕ z with a = (1 + m) 2^e, e ∈ [512, 1022]: a² overflows, exp S is finite.
rc::Gen<Mat3> squares_overflow() {
  return rc::gen::apply(
      [](double a, int c, double z) {
        const double off = std::abs(a) * (c * 0x1p-20);
        return symmetric({-std::abs(a), -std::abs(a), z, a < 0 ? -off : off, 0, 0});
      },
      across(512, 1022), uniform(-(1 << 20), 1 << 20), between(-5, 5));
}

/// Every kind above.
rc::Gen<Mat3> any_kind() {
  return rc::gen::oneOf(whole_range(), tiny(), spectrum_near(700, 711, -1000), spectrum_near(-760, -690, -800),
                        mixed_scales(), squares_overflow());
}

/// ‖S‖₂ from the certified eigenvalues.
double spectral_norm(const certified::CertifiedEigenvalues& lambda) {
  return std::max(std::abs(lambda.value.mid(0)), std::abs(lambda.value.mid(2)));
}

/// exp's statement (affinterp.hpp): non-finite exactly where exp S overflows; elsewhere
/// ‖X − exp S‖_F ≤ 2·10⁻¹⁵ max(1, ‖S‖₂) ‖exp S‖_F + 2⁻¹⁰⁷².
void check_exp(const Mat3& S, const Mat3& X) {
  RC_LOG() << "S = " << show(S) << "\n";
  const certified::CertifiedMatrix truth = certified::exp(S);
  RC_ASSERT(truth.status != certified::Status::too_wide);
  if (truth.status == certified::Status::overflows) {
    RC_ASSERT(!X.allFinite());
    return;
  }
  RC_ASSERT(X.allFinite());
  const double norm = spectral_norm(certified::eigenvalues(S));
  const double error = certified::absolute_error(X, truth.value).upper();
  const double bound = 2e-15 * std::max(1.0, norm) * truth.value.frobenius_norm().upper() + kExpFloor;
  RC_LOG() << "error " << error << " bound " << bound << "\n";
  RC_ASSERT(error <= bound);
}

RC_GTEST_PROP(Sym3FullRange, ExpWholeRange, ()) {
  const Mat3 S = *whole_range();
  check_exp(S, exp_affinterp(S));
}
RC_GTEST_PROP(Sym3FullRange, ExpTinyAndSubnormal, ()) {
  const Mat3 S = *tiny();
  check_exp(S, exp_affinterp(S));
}
RC_GTEST_PROP(Sym3FullRange, ExpNearOverflow, ()) {
  const Mat3 S = *spectrum_near(700, 711, -1000);
  check_exp(S, exp_affinterp(S));
}
RC_GTEST_PROP(Sym3FullRange, ExpNearUnderflow, ()) {
  const Mat3 S = *spectrum_near(-760, -690, -800);
  check_exp(S, exp_affinterp(S));
}
RC_GTEST_PROP(Sym3FullRange, ExpMixedScales, ()) {
  const Mat3 S = *mixed_scales();
  check_exp(S, exp_affinterp(S));
}
RC_GTEST_PROP(Sym3FullRange, ExpSquaresOverflow, ()) {
  const Mat3 S = *squares_overflow();
  check_exp(S, exp_affinterp(S));
}

RC_GTEST_PROP(Sym3FullRange, BatchedMeetsTheSameBoundAndAgreesWithScalar, ()) {
  // 31 matrices: for every SIMD width W the build may use (2, 4, 8), pairs of batches (exp_batched's steps of 2W),
  // a single batch and a scalar tail.
  const auto in = *rc::gen::container<std::vector<Mat3>>(31, any_kind());
  std::vector<Mat3> out(in.size());
  exp_batched(in, out);
  for (std::size_t i = 0; i < in.size(); ++i) {
    const Mat3 X = exp_affinterp(in[i]);
    RC_ASSERT(X.allFinite() == out[i].allFinite());
    check_exp(in[i], out[i]);
  }
}

RC_GTEST_PROP(Sym3FullRange, EigenvaluesWithinRoundoffOfTheNorm, ()) {
  const Mat3 S = *any_kind();
  RC_LOG() << "S = " << show(S) << "\n";
  const certified::CertifiedEigenvalues lambda = certified::eigenvalues(S);
  RC_ASSERT(lambda.status == certified::Status::certified);
  RC_PRE(spectral_norm(lambda) < 1e308);  // beyond, ours returns ±∞ (checked below)
  RC_ASSERT(certified::eigenvalue_error(eigenvalues_affinterp(S), lambda.value).upper() <= 4e-15);
}

TEST(Sym3FullRange, EigenvaluesBeyondTheDoubleRangeAreInfinite) {
  const Mat3 S = symmetric({1e308, -1e308, 1e308, 1e308, 1e308, 0});  // λmax ≈ 2.1·10³⁰⁸
  const Vec3 lambda = eigenvalues_affinterp(S);
  EXPECT_EQ(lambda(2), INFINITY);
  EXPECT_TRUE(std::isfinite(lambda(1)));
}

/// SPD matrices D C D across the range: C = MᵀM + I/10 with M on a grid, D = diag(2^e), e ∈ [−500, 500]
/// (exact scaling); κ₂ up to about 2²⁰⁰⁰.
rc::Gen<Mat3> graded_spd() {
  return rc::gen::apply(
      [](const std::vector<int>& m, const std::vector<int>& e) {
        Mat3 M;
        for (int i = 0; i < 9; ++i) M(i) = m[i] / 1000.0;
        const Mat3 C = linalg::outer_gram(M.transpose()) + 0.1 * Mat3::Identity();
        const Eigen::Vector3d d(std::ldexp(1.0, e[0]), std::ldexp(1.0, e[1]), std::ldexp(1.0, e[2]));
        return Mat3(d.asDiagonal() * C * d.asDiagonal());
      },
      rc::gen::container<std::vector<int>>(9, uniform(-2000, 2000)),
      rc::gen::container<std::vector<int>>(3, rc::gen::oneOf(uniform(-500, 500), uniform(-20, 20), rc::gen::just(0))));
}

/// κ₂ from the certified eigenvalues (S positive definite).
double condition(const Mat3& S) {
  const auto lambda = certified::eigenvalues(S, {.relative_radius = 0x1p-60, .start_bits = 128, .max_bits = 16384});
  return lambda.value.mid(2) / lambda.value.mid(0);
}

/// log's statement: ‖X − log S‖_F ≤ 16 ε (‖log S‖_F + min(κ₂, 2²⁰)).
RC_GTEST_PROP(Sym3FullRange, LogOfGradedSpd, ()) {
  const Mat3 S = *graded_spd();
  RC_LOG() << "S = " << show(S) << "\n";
  const certified::CertifiedMatrix truth = certified::log_spd(S);
  RC_ASSERT(truth.status == certified::Status::certified);
  const double error = certified::absolute_error(log_spd(S), truth.value).upper();
  const double bound = 16 * kEps * (truth.value.frobenius_norm().upper() + std::min(condition(S), 0x1p20));
  RC_LOG() << "error " << error << " bound " << bound << "\n";
  RC_ASSERT(error <= bound);
}

/// S^t's statement: ‖X − S^t‖_F ≤ 16 ε (1 + |t|) min(κ₂, 2²⁰)^{clamp(1 − t, 0, 1)} ‖S^t‖_F, where S^t
/// is finite in double.
RC_GTEST_PROP(Sym3FullRange, PowerOfGradedSpd, ()) {
  const Mat3 S = *graded_spd();
  const double t = *between(-2, 2);
  RC_LOG() << "S = " << show(S) << ", t = " << t << "\n";
  const certified::CertifiedMatrix truth = certified::pow_spd(S, t);
  RC_ASSERT(truth.status == certified::Status::certified);
  const double norm = truth.value.frobenius_norm().upper();
  RC_PRE(norm < 1e307);
  const Mat3 X = pow_spd(S, t);
  RC_ASSERT(X.allFinite());
  const double error = certified::relative_error(X, truth.value).upper();
  const double bound =
      16 * kEps * (1 + std::abs(t)) * std::pow(std::min(condition(S), 0x1p20), std::clamp(1 - t, 0.0, 1.0));
  RC_LOG() << "error " << error << " bound " << bound << "\n";
  RC_ASSERT(error <= bound);
}

TEST(Sym3FullRange, SpdDecidedExactly) {
  Mat3 singular;
  singular << 1, 1, 0, 1, 1, 0, 0, 0, 1;
  EXPECT_THROW(log_spd(singular), std::domain_error);
  EXPECT_THROW(pow_spd(Mat3::Zero(), 0.5), std::domain_error);
  // Positive definite with κ₂ ≈ 2·10³²³ (a subnormal eigenvalue): no throw, the right logarithm.
  const Mat3 D = Eigen::Vector3d(1, 2, 1e-310).asDiagonal();
  EXPECT_NEAR(log_spd(D)(2, 2), std::log(1e-310), 1e-12);
}

TEST(Sym3FullRange, ExamplesFromTheIssue) {
  // Subnormal entries: exp S = I + S to within rounding.
  Mat3 S;
  S << 1e-310, 3e-310, 0, 3e-310, 2e-310, 1e-311, 0, 1e-311, -1e-310;
  const Mat3 E = exp_affinterp(S);
  EXPECT_EQ(E.diagonal(), Vec3(1, 1, 1));
  EXPECT_NEAR(E(0, 1), 3e-310, 1e-322);
  EXPECT_NEAR(E(1, 2), 1e-311, 1e-322);
  // 10³⁰⁰ beside 10⁻³⁰⁰ and moderate entries: exactly the exponentials of the diagonal.
  const Mat3 mixed = Eigen::Vector3d(-1e300, 1e-300, 2).asDiagonal();
  const Mat3 X = exp_affinterp(mixed);
  EXPECT_EQ(X(0, 0), 0.0);
  EXPECT_EQ(X(1, 1), 1.0);
  EXPECT_DOUBLE_EQ(X(2, 2), std::exp(2.0));
  EXPECT_EQ((X - Mat3(X.diagonal().asDiagonal())).norm(), 0.0);
}

}  // namespace
}  // namespace affinterp::sym3::full_range_test
