#include "theory/local/svd_norm_goodness.hpp"

#include <stdexcept>

namespace affinterp::local {

bool svd_good_for_norm_at_pi_multiple(const exact::Rational& x, const exact::Rational& y,
                                      const exact::Rational& beta_over_pi) {
  using exact::Rational;
  // G(1) = a − π² c (svd_norm_margin with β² = π² r²).
  const Rational a = svd_norm_margin<Rational>(x, y, 0);
  const Rational c = a - svd_norm_margin<Rational>(x, y, beta_over_pi * beta_over_pi);
  if (c == 0) return a >= 0;
  // π to 40 decimals, truncated: π_lo < π < π_lo + 10^−40.
  static const Rational pi_lo = exact::parse_rational(
      "31415926535897932384626433832795028841971/"
      "10000000000000000000000000000000000000000");
  static const Rational pi_hi =
      pi_lo + Rational(1) / exact::parse_rational("10000000000000000000000000000000000000000");
  const Rational ratio = a / c;  // c > 0: good iff π² ≤ a / c, and π² ≠ a / c
  if (ratio < pi_lo * pi_lo) return false;
  if (ratio > pi_hi * pi_hi) return true;
  throw std::domain_error("svd_good_for_norm_at_pi_multiple: 4xy(x-1)(y-1) / (r(x-y)(x+y))^2 is within 1e-39 of pi^2");
}

}  // namespace affinterp::local
