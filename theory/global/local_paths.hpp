#pragma once
// The local homotopies A_i(t) of all triangles (Kaji §3), evaluated from each A_i's polar form
// A = R_θ S with θ on a chosen branch (see rotation_branch.hpp) and S = R_{−β} D R_β (Kaji Appendix).
#include "theory/global/interpolation.hpp"

#include <Eigen/Core>

#include <vector>

namespace affinterp::global {

/// The angle θ ∈ (−π, π] of R_θ in the polar decomposition A = R_θ S of A ∈ GL⁺(2).
double principal_polar_angle(const Eigen::Matrix2d& A);

class LocalPaths {
 public:
  /// `A` the linear parts, `theta` their polar angles (any branch: A = R_θ S for θ + 2πk alike).
  LocalPaths(const std::vector<Eigen::Matrix2d>& A, LocalHomotopy homotopy, const Eigen::VectorXd& theta);

  /// A_i(t); A_i(0) = I and A_i(1) = A_i.
  Eigen::Matrix2d at(Eigen::Index i, double t) const;
  Eigen::Index size() const { return static_cast<Eigen::Index>(polar_.size()); }
  const Eigen::VectorXd& angles() const { return theta_; }

 private:
  struct Polar {
    double theta;                 ///< R_θ
    Eigen::Matrix2d S;            ///< S = R_{−β} diag(d1, d2) R_β
    double cos_beta, sin_beta;    ///< β
    double log_d1, log_d2;        ///< log of S's eigenvalues, for S^t
  };
  LocalHomotopy homotopy_;
  Eigen::VectorXd theta_;
  std::vector<Polar> polar_;
};

}  // namespace affinterp::global
