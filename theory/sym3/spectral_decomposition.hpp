#pragma once
// Thesis §3.1.2 (Algorithm 2, spectral decomposition): exp S = xS² + yS + zE with x, y, z from the
// eigenvalues, in three cases by multiplicity, eigenvalues counted equal when |λ − λ'| < 10⁻⁶.
// Written over any real type (double for the algorithm, Real100 for deciding thesis.sd.case1..3).
#include "theory/sym3/algorithms.hpp"

#include <array>
#include <cmath>

namespace affinterp::sym3 {

/// exp S = xS² + yS + zE.
template <class Real>
struct SdCoefficients {
  Real x, y, z;
};

/// The printed case 3 has x = s + t + u, but its t and u carry the opposite sign to the Lagrange
/// coefficients (t's denominator is (λ2 − λ3)(λ1 − λ2) = −(λ2 − λ1)(λ2 − λ3), likewise u's), which
/// y and z take into account and x does not: the corrected x is s − t − u.
enum class SdReading { printed, corrected };

/// Case 1, all three eigenvalues equal: x = y = 0, z = exp(λ1).
template <class Real>
SdCoefficients<Real> sd_case1(const Real& lambda1) {
  using std::exp;
  return {Real(0), Real(0), exp(lambda1)};
}

/// Case 2, λ1 = λ2 ≠ λ3: x = 0, y = s − t, z = tλ2 − sλ3, s = e^{λ2}/(λ2 − λ3), t = e^{λ3}/(λ2 − λ3).
template <class Real>
SdCoefficients<Real> sd_case2(const Real& lambda2, const Real& lambda3) {
  using std::exp;
  const Real s = exp(lambda2) / (lambda2 - lambda3);
  const Real t = exp(lambda3) / (lambda2 - lambda3);
  return {Real(0), s - t, t * lambda2 - s * lambda3};
}

/// Case 3, all distinct: x = s + t + u (printed) or s − t − u (corrected),
/// y = −s(λ2 + λ3) + t(λ3 + λ1) + u(λ1 + λ2), z = sλ2λ3 − tλ3λ1 − uλ1λ2, with
/// s = e^{λ1}/((λ1 − λ2)(λ1 − λ3)), t = e^{λ2}/((λ2 − λ3)(λ1 − λ2)), u = e^{λ3}/((λ2 − λ3)(λ3 − λ1)).
template <class Real>
SdCoefficients<Real> sd_case3(const Real& l1, const Real& l2, const Real& l3, SdReading reading) {
  using std::exp;
  const Real s = exp(l1) / ((l1 - l2) * (l1 - l3));
  const Real t = exp(l2) / ((l2 - l3) * (l1 - l2));
  const Real u = exp(l3) / ((l2 - l3) * (l3 - l1));
  const Real x = reading == SdReading::printed ? Real(s + t + u) : Real(s - t - u);
  return {x, -s * (l2 + l3) + t * (l3 + l1) + u * (l1 + l2), s * l2 * l3 - t * l3 * l1 - u * l1 * l2};
}

/// The thesis's equality threshold: two eigenvalues are "same" when they differ by less than 10⁻⁶.
inline constexpr double sd_threshold = 1e-6;

/// The case analysis of §3.1.2 on eigenvalues (λ1, λ2, λ3) in the order an eigenvalue algorithm gives
/// them: case 1 when all pairs are "same", case 2 for the first "same" pair (relabelled as λ1 = λ2),
/// else case 3.
SdCoefficients<double> sd_coefficients(const std::array<double, 3>& lambda, SdReading reading);

/// xS² + yS + zE.
template <class Real>
Eigen::Matrix<Real, 3, 3> sd_polynomial(const Eigen::Matrix<Real, 3, 3>& S, const SdCoefficients<Real>& c) {
  using M = Eigen::Matrix<Real, 3, 3>;
  return M(c.x * (S * S) + c.y * S + c.z * M::Identity());
}

/// "thesis-sd-printed" / "thesis-sd-corrected": eigenvalues from Eigen's QR solver, then §3.1.2.
Mat3 exp_sd_printed(const Mat3& S);
Mat3 exp_sd_corrected(const Mat3& S);
/// "thesis-improved-sd": the printed Viète eigenvalues (§3.2), then §3.1.2 (corrected case 3).
Mat3 exp_improved_sd(const Mat3& S);
/// "thesis-improved-sd-clamped": the same with the rounding-guarded Viète formula.
Mat3 exp_improved_sd_clamped(const Mat3& S);

}  // namespace affinterp::sym3
