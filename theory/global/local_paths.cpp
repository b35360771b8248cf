#include "theory/global/local_paths.hpp"

#include <cmath>

namespace affinterp::global {

double principal_polar_angle(const Eigen::Matrix2d& A) { return local::polar_decomposition<double>(A).theta; }

LocalPaths::LocalPaths(const std::vector<Eigen::Matrix2d>& A, LocalHomotopy homotopy, const Eigen::VectorXd& theta)
    : homotopy_(homotopy), theta_(theta) {
  for (std::size_t i = 0; i < A.size(); ++i) {
    const local::Polar<double> polar = local::polar_decomposition<double>(A[i]);
    const double branch = theta[static_cast<Eigen::Index>(i)];  // polar.theta + 2πk
    switch (homotopy) {
      case LocalHomotopy::exp: {
        const local::ExpLogHomotopy<double> path(branch, polar.S);  // S = R_{−β} diag(λ1, λ2) R_β
        const double beta = path.S_eigen.beta;
        const Eigen::Matrix2d N = local::rotation<double>(-beta) * (Eigen::Matrix2d() << 1, 0, 0, -1).finished() *
                                  local::rotation<double>(beta);
        exp_.push_back({branch, std::log(path.S_eigen.x), std::log(path.S_eigen.y), N});
        break;
      }
      case LocalHomotopy::polar: polar_.push_back({branch, polar.S}); break;
      case LocalHomotopy::linear: linear_.push_back({A[i]}); break;
      case LocalHomotopy::svd: {  // A = R_α D R_β with α + β = principal θ: move α to the branch
        local::Svd<double> decomposition = local::svd<double>(A[i]);
        decomposition.alpha += branch - polar.theta;
        svd_.push_back({decomposition});
        break;
      }
    }
  }
}

Eigen::Matrix2d LocalPaths::at(Eigen::Index i, double t) const {
  const auto k = static_cast<std::size_t>(i);
  switch (homotopy_) {
    case LocalHomotopy::exp: {
      const ExpPath& p = exp_[k];
      const double l1 = std::exp(t * p.log_lambda1), l2 = std::exp(t * p.log_lambda2);
      const double c = std::cos(t * p.theta), s = std::sin(t * p.theta);
      const Eigen::Matrix2d St = (l1 + l2) / 2 * Eigen::Matrix2d::Identity() + (l1 - l2) / 2 * p.N;
      return (Eigen::Matrix2d() << c, -s, s, c).finished() * St;
    }
    case LocalHomotopy::polar: return polar_[k](t);
    case LocalHomotopy::linear: return linear_[k](t);
    case LocalHomotopy::svd: return svd_[k](t);
  }
  return Eigen::Matrix2d::Identity();
}

}  // namespace affinterp::global
