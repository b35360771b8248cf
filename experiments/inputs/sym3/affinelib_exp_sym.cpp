#include "experiments/inputs/sym3/affinelib_exp_sym.hpp"

#include <Eigen/Eigenvalues>

#include <cmath>

namespace affinterp::sym3 {

namespace {

/// AffineLib's EPSILON ("threshold for being zero", written 10e-6).
constexpr double kEpsilon = 1e-5;

}  // namespace

Eigen::Matrix3d exp_affinelib(const Eigen::Matrix3d& S) {
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  if (S.squaredNorm() < kEpsilon) return I + S;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
  solver.computeDirect(S, Eigen::EigenvaluesOnly);
  const Eigen::Vector3d l = solver.eigenvalues();  // ascending
  const double l01 = l[0] - l[1], l12 = l[1] - l[2], l02 = l[0] - l[2];
  if (std::abs(l01) < kEpsilon) {
    if (std::abs(l12) < kEpsilon) return std::exp(l[1]) * I;
    const double a = std::exp(l[1]) / l12, b = std::exp(l[2]) / l12;
    return (a - b) * S + (l[1] * b - l[2] * a) * I;
  }
  if (std::abs(l12) < kEpsilon) {
    const double a = std::exp(l[0]) / l01, b = std::exp(l[1]) / l01;
    return (a - b) * S + (l[0] * b - l[1] * a) * I;
  }
  const double a = std::exp(l[0]) / (l01 * l02), b = -std::exp(l[1]) / (l12 * l01), c = std::exp(l[2]) / (l02 * l12);
  return (a + b + c) * S * S - (a * (l[1] + l[2]) + b * (l[2] + l[0]) + c * (l[0] + l[1])) * S +
         (a * l[1] * l[2] + b * l[2] * l[0] + c * l[0] * l[1]) * I;
}

}  // namespace affinterp::sym3
