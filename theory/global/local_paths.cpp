#include "theory/global/local_paths.hpp"

namespace affinterp::global {

double principal_polar_angle(const Eigen::Matrix2d& A) { return local::polar_decomposition<double>(A).theta; }

LocalPaths::LocalPaths(const std::vector<Eigen::Matrix2d>& A, LocalHomotopy homotopy, const Eigen::VectorXd& theta)
    : homotopy_(homotopy), theta_(theta) {
  for (std::size_t i = 0; i < A.size(); ++i) {
    const local::Polar<double> polar = local::polar_decomposition<double>(A[i]);
    const double branch = theta[static_cast<Eigen::Index>(i)];  // polar.theta + 2πk
    switch (homotopy) {
      case LocalHomotopy::exp: exp_.emplace_back(branch, polar.S); break;
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
    case LocalHomotopy::exp: return exp_[k](t);
    case LocalHomotopy::polar: return polar_[k](t);
    case LocalHomotopy::linear: return linear_[k](t);
    case LocalHomotopy::svd: return svd_[k](t);
  }
  return Eigen::Matrix2d::Identity();
}

}  // namespace affinterp::global
