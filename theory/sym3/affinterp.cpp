#include "theory/sym3/affinterp.hpp"

#include "theory/sym3/spectral_split.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace affinterp::sym3 {
namespace {

split::Sym<double> upper(const Mat3& S) {
  return {S(0, 0), S(1, 1), S(2, 2), S(0, 1), S(0, 2), S(1, 2)};
}

Mat3 to_matrix(const split::Sym<double>& X) {
  Mat3 M;
  M << X.xx, X.xy, X.xz, X.xy, X.yy, X.yz, X.xz, X.yz, X.zz;
  return M;
}

/// The split of an SPD matrix, with its smallest eigenvalue λ_mid − ρ checked to be positive.
split::SpectralSplit<double> spd_split(const Mat3& S) {
  const auto s = split::spectral_split(upper(S));
  if (!(std::min(s.lambda_far, s.lambda_mid - s.rho) > 0.0)) {
    throw std::domain_error("sym3: matrix is not symmetric positive definite");
  }
  return s;
}

}  // namespace

Mat3 exp_affinterp(const Mat3& S) { return to_matrix(split::exp_from_split(split::spectral_split(upper(S)))); }

Vec3 eigenvalues_affinterp(const Mat3& S) {
  const auto s = split::spectral_split(upper(S));
  Vec3 lambda(s.lambda_mid - s.rho, s.lambda_mid + s.rho, s.lambda_far);
  std::sort(lambda.begin(), lambda.end());
  return lambda;
}

Mat3 log_spd(const Mat3& S) {
  const auto s = spd_split(S);
  const double lo = s.lambda_mid - s.rho, gap = 2.0 * s.rho;
  const double z = gap / lo;  // log λ_hi − log λ_lo = log1p(z): no cancellation for small gaps
  const double f_dd = z == 0.0 ? 1.0 / lo : std::log1p(z) / gap;
  const double f_pair = 0.5 * (std::log(lo + gap) + std::log(lo));
  return to_matrix(split::assemble(s, std::log(s.lambda_far), f_pair, f_dd));
}

Mat3 pow_spd(const Mat3& S, double t) {
  const auto s = spd_split(S);
  const double lo = s.lambda_mid - s.rho, gap = 2.0 * s.rho;
  const double z = gap / lo;
  // λ_hi^t − λ_lo^t = λ_lo^t expm1(t log1p(z)), divided by the gap λ_lo z.
  const double f_dd = z == 0.0 ? t * std::pow(lo, t - 1.0) : std::pow(lo, t - 1.0) * std::expm1(t * std::log1p(z)) / z;
  const double f_pair = 0.5 * (std::pow(lo + gap, t) + std::pow(lo, t));
  return to_matrix(split::assemble(s, std::pow(s.lambda_far, t), f_pair, f_dd));
}

}  // namespace affinterp::sym3
