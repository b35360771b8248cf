#include "theory/sym3/spectral_decomposition.hpp"

#include "theory/sym3/diagonalisation.hpp"
#include "theory/sym3/viete.hpp"

namespace affinterp::sym3 {
namespace {

bool same(double a, double b) { return std::abs(a - b) < sd_threshold; }

std::array<double, 3> as_array(const Vec3& v) { return {v[0], v[1], v[2]}; }

}  // namespace

SdCoefficients<double> sd_coefficients(const std::array<double, 3>& lambda, SdReading reading) {
  const auto [l1, l2, l3] = lambda;
  if (same(l1, l2) && same(l2, l3) && same(l1, l3)) return sd_case1(l1);
  if (same(l1, l2)) return sd_case2(l2, l3);
  if (same(l2, l3)) return sd_case2(l3, l1);
  if (same(l1, l3)) return sd_case2(l3, l2);
  return sd_case3(l1, l2, l3, reading);
}

Mat3 exp_sd_printed(const Mat3& S) {
  return sd_polynomial(S, sd_coefficients(as_array(eigenvalues_eigen_qr(S)), SdReading::printed));
}

Mat3 exp_sd_corrected(const Mat3& S) {
  return sd_polynomial(S, sd_coefficients(as_array(eigenvalues_eigen_qr(S)), SdReading::corrected));
}

Mat3 exp_improved_sd(const Mat3& S) {
  return sd_polynomial(S, sd_coefficients(viete_printed_order(S), SdReading::corrected));
}

Mat3 exp_improved_sd_clamped(const Mat3& S) {
  return sd_polynomial(S, sd_coefficients(viete_clamped_order(S), SdReading::corrected));
}

}  // namespace affinterp::sym3
