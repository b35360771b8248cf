#include "theory/global/local_paths.hpp"

#include "theory/global/parallel_ranges.hpp"

#include <cmath>
#include <stdexcept>

namespace affinterp::global {

double principal_polar_angle(const Eigen::Matrix2d& A) { return local::polar_decomposition<double>(A).theta; }

LocalPaths::LocalPaths(const std::vector<Eigen::Matrix2d>& A, LocalHomotopy homotopy, const Eigen::VectorXd& theta) {
  auto path_of = [&](std::size_t i) -> Path {
    const local::Polar<double> polar = local::polar_decomposition<double>(A[i]);
    const double branch = theta[static_cast<Eigen::Index>(i)];  // polar.theta + 2πk
    switch (homotopy) {
      case LocalHomotopy::exp: {  // A^E(t) = R_{tθ} S^t, Kaji eq. (3), evaluated as in ExpPath
        const local::ExpLogHomotopy<double> path(branch, polar.S);  // S = R_{−β} diag(λ1, λ2) R_β
        const double beta = path.S_eigen.beta;
        const Eigen::Matrix2d N = local::rotation<double>(-beta) * (Eigen::Matrix2d() << 1, 0, 0, -1).finished() *
                                  local::rotation<double>(beta);
        return ExpPath{branch, std::log(path.S_eigen.x), std::log(path.S_eigen.y), N};
      }
      case LocalHomotopy::polar:  // A^P(t) = R_{tθ}((1−t)I + tS), Kaji eq. (2)
        return local::PolarHomotopy<double>{branch, polar.S};
      case LocalHomotopy::linear:  // (1−t)I + tA: no angle, so no branch
        return local::LinearHomotopy<double>{A[i]};
      case LocalHomotopy::svd: {  // A = R_α D R_β with α + β = principal θ: move α to the branch
        local::Svd<double> decomposition = local::svd<double>(A[i]);
        decomposition.alpha += branch - polar.theta;
        return local::SvdHomotopy<double>{decomposition};
      }
    }
    throw std::invalid_argument("unknown local homotopy");
  };
  paths_.resize(A.size());
  // each triangle's path on its own: split over threads for large meshes (parallel_ranges.hpp)
  for_each_range(paths_.size(), ranges_for(paths_.size(), 1 << 15), [&](std::size_t first, std::size_t last) {
    for (std::size_t i = first; i < last; ++i) paths_[i] = path_of(i);
  });
}

Eigen::Matrix2d LocalPaths::ExpPath::operator()(double t) const {
  const double l1 = std::exp(t * log_lambda1), l2 = std::exp(t * log_lambda2);
  const double c = std::cos(t * theta), s = std::sin(t * theta);
  const Eigen::Matrix2d St = (l1 + l2) / 2 * Eigen::Matrix2d::Identity() + (l1 - l2) / 2 * N;  // S^t
  return (Eigen::Matrix2d() << c, -s, s, c).finished() * St;                                   // R_{tθ} S^t, eq. (3)
}

Eigen::Matrix2d LocalPaths::at(Eigen::Index i, double t) const {
  return std::visit([t](const auto& path) -> Eigen::Matrix2d { return path(t); }, paths_[static_cast<std::size_t>(i)]);
}

}  // namespace affinterp::global
