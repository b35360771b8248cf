#pragma once
// RapidCheck generators for the local theory: GL+(2) matrices (through their SVD parameters, so that
// conditioning and angles are controlled), symmetric positive definite S, and non-degenerate triangles,
// including adversarial families: near-singular, overall scales 1e±8, angles near ±π, repeated singular
// values.
#include "theory/local/svd.hpp"

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <numbers>
#include <ostream>

namespace affinterp::local::testing {

/// A double on a uniform grid of `steps` points in [lo, hi].
inline rc::Gen<double> uniform(double lo, double hi, int steps = 1 << 20) {
  return rc::gen::map(rc::gen::inRange(0, steps + 1),
                      [=](int k) { return lo + (hi - lo) * static_cast<double>(k) / steps; });
}

/// An angle in (−π, π], with a quarter of the draws within 1e-9 of ±π or 0.
inline rc::Gen<double> angle() {
  using std::numbers::pi;
  return rc::gen::weightedOneOf<double>({
      {3, uniform(-pi, pi)},
      {1, rc::gen::map(rc::gen::pair(rc::gen::element(pi, -pi, 0.0), uniform(-1e-9, 1e-9)),
                       [](std::pair<double, double> p) { return p.first + p.second; })},
  });
}

/// Singular values x ≥ y > 0: generic (ratio up to 1e3), repeated, or near-singular (ratio up to 1e8);
/// all times an overall scale 10^k, |k| ≤ 8.
inline rc::Gen<std::pair<double, double>> singular_values() {
  const auto scale = rc::gen::map(rc::gen::inRange(-8, 9), [](int k) { return std::pow(10.0, k); });
  const auto ratio = rc::gen::weightedOneOf<double>({
      {4, rc::gen::map(uniform(0, 3), [](double e) { return std::pow(10.0, -e); })},
      {1, rc::gen::just(1.0)},
      {1, rc::gen::map(uniform(6, 8), [](double e) { return std::pow(10.0, -e); })},
  });
  return rc::gen::map(rc::gen::tuple(uniform(-1, 1), ratio, scale), [](std::tuple<double, double, double> p) {
    const auto [log_x, ratio, scale] = p;
    const double x = std::pow(10.0, log_x) * scale;
    return std::pair{x, x * ratio};
  });
}

/// A = R_α diag(x, y) R_β ∈ GL+(2) from adversarial parameters.
inline rc::Gen<Svd<double>> gl_plus_parameters() {
  return rc::gen::map(rc::gen::tuple(angle(), singular_values(), angle()),
                      [](std::tuple<double, std::pair<double, double>, double> p) {
                        const auto& [alpha, xy, beta] = p;
                        return Svd<double>{alpha, xy.first, xy.second, beta};
                      });
}

inline rc::Gen<Mat2<double>> gl_plus() {
  return rc::gen::map(gl_plus_parameters(), [](const Svd<double>& p) { return p.matrix(); });
}

/// S = R_{−β} diag(x, y) R_β, symmetric positive definite.
inline rc::Gen<Mat2<double>> spd() {
  return rc::gen::map(gl_plus_parameters(), [](const Svd<double>& p) {
    Mat2<double> S = Svd<double>{-p.beta, p.x, p.y, p.beta}.matrix();
    S(0, 1) = S(1, 0) = (S(0, 1) + S(1, 0)) / 2;
    return S;
  });
}

/// A non-degenerate triangle: vertices in [−1, 1]² shifted by up to 3, times 10^k (|k| ≤ 4), with
/// area at least 1e-3 of its squared diameter (so that eq. (1) is well conditioned).
inline rc::Gen<Triangle<double>> triangle() {
  return rc::gen::map(rc::gen::tuple(rc::gen::container<std::vector<double>>(6, uniform(-1, 1)),
                                     rc::gen::inRange(-4, 5), uniform(-3, 3)),
                      [](const std::tuple<std::vector<double>, int, double>& p) {
                        const auto& [coordinates, exponent, shift] = p;
                        Triangle<double> T;
                        for (int k = 0; k < 6; ++k)
                          T(k % 2, k / 2) = (coordinates[k] + shift) * std::pow(10.0, exponent);
                        return T;
                      });
}

inline double area_ratio(const Triangle<double>& T) {
  const Eigen::Vector2d e1 = T.col(1) - T.col(0), e2 = T.col(2) - T.col(0), e3 = T.col(2) - T.col(1);
  const double diameter2 = std::max({e1.squaredNorm(), e2.squaredNorm(), e3.squaredNorm()});
  return std::abs(e1.x() * e2.y() - e1.y() * e2.x()) / diameter2;
}

}  // namespace affinterp::local::testing

namespace Eigen {
// Full precision when RapidCheck prints a counterexample.
template <class Scalar>
void showValue(const Matrix<Scalar, 2, 2>& m, std::ostream& os) {
  os << std::setprecision(17) << "[[" << m(0, 0) << ", " << m(0, 1) << "], [" << m(1, 0) << ", " << m(1, 1) << "]]";
}
}  // namespace Eigen
