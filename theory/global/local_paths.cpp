#include "theory/global/local_paths.hpp"

#include <cmath>

namespace affinterp::global {
namespace {

Eigen::Matrix2d rotation(double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return (Eigen::Matrix2d() << c, -s, s, c).finished();
}

}  // namespace

double principal_polar_angle(const Eigen::Matrix2d& A) {
  // R_θ ᵀA is symmetric exactly when tan θ = (a21 − a12)/(a11 + a22); det A > 0 makes S positive definite.
  return std::atan2(A(1, 0) - A(0, 1), A(0, 0) + A(1, 1));
}

LocalPaths::LocalPaths(const std::vector<Eigen::Matrix2d>& A, LocalHomotopy homotopy, const Eigen::VectorXd& theta)
    : homotopy_(homotopy), theta_(theta) {
  polar_.reserve(A.size());
  for (std::size_t i = 0; i < A.size(); ++i) {
    Polar p;
    p.theta = theta[static_cast<Eigen::Index>(i)];
    p.S = rotation(-p.theta) * A[i];
    p.S = (p.S + p.S.transpose()) / 2;
    // Eigen-decomposition of the symmetric 2×2 S: eigenvector of d1 at angle φ = −β.
    const double a = p.S(0, 0), b = p.S(0, 1), c = p.S(1, 1);
    const double phi = std::atan2(2 * b, a - c) / 2;
    const double mean = (a + c) / 2, radius = std::hypot((a - c) / 2, b);
    p.cos_beta = std::cos(-phi), p.sin_beta = std::sin(-phi);
    p.log_d1 = std::log(mean + radius), p.log_d2 = std::log(mean - radius);
    polar_.push_back(p);
  }
}

Eigen::Matrix2d LocalPaths::at(Eigen::Index i, double t) const {
  const Polar& p = polar_[static_cast<std::size_t>(i)];
  const Eigen::Matrix2d R_beta = (Eigen::Matrix2d() << p.cos_beta, -p.sin_beta, p.sin_beta, p.cos_beta).finished();
  switch (homotopy_) {
    case LocalHomotopy::exp: {  // eq. (3): R_{tθ} S^t, S^t = R_{−β} D^t R_β
      const Eigen::Vector2d Dt(std::exp(t * p.log_d1), std::exp(t * p.log_d2));
      return rotation(t * p.theta) * R_beta.transpose() * Dt.asDiagonal() * R_beta;
    }
    case LocalHomotopy::polar:  // A^P(t) = R_{tθ}((1−t)I + tS)
      return rotation(t * p.theta) * ((1 - t) * Eigen::Matrix2d::Identity() + t * p.S);
    case LocalHomotopy::linear:  // A^L(t) = (1−t)I + tA
      return (1 - t) * Eigen::Matrix2d::Identity() + t * rotation(p.theta) * p.S;
    case LocalHomotopy::svd: {  // A = R_α D R_β with α = θ − β: R_{tα}((1−t)I + tD)R_{tβ}
      const double beta = std::atan2(p.sin_beta, p.cos_beta);
      const Eigen::Vector2d D(std::exp(p.log_d1), std::exp(p.log_d2));
      const Eigen::Vector2d Dt = (1 - t) * Eigen::Vector2d::Ones() + t * D;
      return rotation(t * (p.theta - beta)) * Dt.asDiagonal() * rotation(t * beta);
    }
  }
  return Eigen::Matrix2d::Identity();
}

}  // namespace affinterp::global
