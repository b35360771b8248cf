#include "theory/sym3/affinterp.hpp"

#include "theory/sym3/spectral_split.hpp"
#include "theory/sym3/wide_range.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

namespace affinterp::sym3 {
namespace {

split::Sym<double> upper(const Mat3& S) { return {S(0, 0), S(1, 1), S(2, 2), S(0, 1), S(0, 2), S(1, 2)}; }

Mat3 to_matrix(const split::Sym<double>& X) {
  Mat3 M;
  M << X.xx, X.xy, X.xz, X.xy, X.yy, X.yz, X.xz, X.yz, X.zz;
  return M;
}

/// S = 2^k Ŝ with the largest entry of Ŝ in [1/2, 1) when S's lies outside [2⁻⁵⁰⁰, kWideEntry], so that
/// the split of Ŝ is computed in double; k = 0 otherwise (and for S = 0).
struct Prescaled {
  split::Sym<double> S;
  int k = 0;
};

Prescaled prescaled(const Mat3& S) {
  Prescaled out{upper(S), 0};
  const double a = split::max_abs(out.S);
  if (a == 0.0 || (a >= 0x1p-500 && a <= split::kWideEntry) || !std::isfinite(a)) return out;
  std::frexp(a, &out.k);
  for (double* x : {&out.S.xx, &out.S.yy, &out.S.zz, &out.S.xy, &out.S.xz, &out.S.yz}) *x = std::ldexp(*x, -out.k);
  return out;
}

/// Above this condition number S^t and log S leave the double path (errors ≈ ε κ₂) for wide_range.
constexpr double kSpdConditionLimit = 0x1p20;

/// The split of the prescaled SPD matrix when its eigenvalues are positive with κ₂ ≤ kSpdConditionLimit,
/// which the double eigenvalues (errors ≲ 4ε ‖Ŝ‖) certify; nullopt otherwise.
std::optional<split::SpectralSplit<double>> well_conditioned_spd_split(const split::Sym<double>& S) {
  const auto s = split::spectral_split(S);
  const double lo = std::min(s.lambda_far, s.lambda_mid - s.rho), hi = std::max(s.lambda_far, s.lambda_mid + s.rho);
  if (!(lo > hi / kSpdConditionLimit)) return std::nullopt;
  return s;
}

}  // namespace

Mat3 exp_affinterp(const Mat3& S) {
  const auto u = upper(S);
  if (split::max_abs(u) > split::kWideEntry) return wide_range::exp(S);
  return to_matrix(split::exp_from_split(split::spectral_split(u)));
}

Vec3 eigenvalues_affinterp(const Mat3& S) {
  const Prescaled p = prescaled(S);
  const auto s = split::spectral_split(p.S);
  Vec3 lambda(s.lambda_mid - s.rho, s.lambda_mid + s.rho, s.lambda_far);
  for (double& x : lambda) x = std::ldexp(x, p.k);
  std::sort(lambda.begin(), lambda.end());
  return lambda;
}

Mat3 log_spd(const Mat3& S) {
  const Prescaled p = prescaled(S);
  const auto split = well_conditioned_spd_split(p.S);
  if (!split) return wide_range::log_spd(S);
  const auto& s = *split;
  // log S = log Ŝ + k log 2 · I; the divided difference is scale-invariant.
  const double shift = p.k * 0.69314718055994530942;
  const double lo = s.lambda_mid - s.rho, gap = 2.0 * s.rho;
  const double z = gap / lo;  // log λ_hi − log λ_lo = log1p(z): no cancellation for small gaps
  const double f_dd = z == 0.0 ? 1.0 / lo : std::log1p(z) / gap;
  const double f_pair = 0.5 * (std::log(lo + gap) + std::log(lo)) + shift;
  return to_matrix(split::assemble(s, std::log(s.lambda_far) + shift, f_pair, f_dd));
}

Mat3 pow_spd(const Mat3& S, double t) {
  const Prescaled p = prescaled(S);
  const auto split = well_conditioned_spd_split(p.S);
  if (!split) return wide_range::pow_spd(S, t);
  const auto& s = *split;
  const double lo = s.lambda_mid - s.rho, gap = 2.0 * s.rho;
  const double z = gap / lo;
  // λ_hi^t − λ_lo^t = λ_lo^t expm1(t log1p(z)), divided by the gap λ_lo z.
  const double f_dd = z == 0.0 ? t * std::pow(lo, t - 1.0) : std::pow(lo, t - 1.0) * std::expm1(t * std::log1p(z)) / z;
  const double f_pair = 0.5 * (std::pow(lo + gap, t) + std::pow(lo, t));
  Mat3 X = to_matrix(split::assemble(s, std::pow(s.lambda_far, t), f_pair, f_dd));
  if (p.k != 0) {
    // S^t = 2^{kt} Ŝ^t: 2^{kt} = 2^n 2^f with n integral, f = kt − n computed exactly by fma.
    const double n = std::floor(p.k * t), f = std::fma(p.k, t, -n);
    X *= std::exp2(f);
    for (double& x : X.reshaped()) x = std::ldexp(x, static_cast<int>(std::clamp(n, -4000.0, 4000.0)));
  }
  return X;
}

}  // namespace affinterp::sym3
