#include "theory/sym3/viete.hpp"

#include <Eigen/LU>
#include <algorithm>

namespace affinterp::sym3 {
namespace {

VieteParameters<double> parameters(const Mat3& S) {
  return viete_parameters(S.trace(), S.squaredNorm(), S.determinant());
}

Vec3 ascending(const std::array<double, 3>& lambda) {
  Vec3 out(lambda[0], lambda[1], lambda[2]);
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

std::array<double, 3> viete_printed_order(const Mat3& S) { return viete_printed(parameters(S)); }

Vec3 eigenvalues_viete(const Mat3& S) { return ascending(viete_printed_order(S)); }

std::array<double, 3> viete_clamped_order(const Mat3& S) {
  auto v = parameters(S);
  v.p = std::min(v.p, 0.0);
  v.r = std::sqrt(-12.0 * v.p);
  if (v.r == 0.0) v.p = 0.0;
  v.k = std::clamp(v.k, -1.0, 1.0);
  return viete_printed(v);
}

Vec3 eigenvalues_viete_clamped(const Mat3& S) { return ascending(viete_clamped_order(S)); }

}  // namespace affinterp::sym3
