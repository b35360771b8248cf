#pragma once
// The local homotopies A_i(t) of all triangles (Kaji §3), from the local theory (theory/local), each
// built from A_i's polar form A = R_θ S with θ on the branch chosen for rotation consistency
// (rotation_branch.hpp): every homotopy is evaluated from (θ, S), so θ + 2πk changes the path.
#include "theory/global/options.hpp"
#include "theory/local/local.hpp"

#include <Eigen/Core>

#include <variant>
#include <vector>

namespace affinterp::global {

/// The angle θ ∈ (−π, π] of R_θ in the polar decomposition A = R_θ S of A ∈ GL⁺(2).
double principal_polar_angle(const Eigen::Matrix2d& A);

class LocalPaths {
 public:
  /// `A` the linear parts, `theta` their polar angles on the chosen branches (θ_i ≡ principal mod 2π).
  LocalPaths(const std::vector<Eigen::Matrix2d>& A, LocalHomotopy homotopy, const Eigen::VectorXd& theta);
  /// No paths yet: a place, referred to by the constraint terms and the assembly, that the set-up assigns.
  LocalPaths() = default;

  /// A_i(t); A_i(0) = I and A_i(1) = A_i.
  Eigen::Matrix2d at(Eigen::Index i, double t) const;

 private:
  /// A^E(t) = R_{tθ} S^t with S^t = R_{−β} diag(λ1^t, λ2^t) R_β = ((λ1^t + λ2^t)/2) I + ((λ1^t − λ2^t)/2) N,
  /// N = R_{−β} diag(1, −1) R_β: the same path as local::ExpLogHomotopy, evaluated with one sincos and two
  /// exp per triangle (the per-frame cost of E^F on large meshes).
  struct ExpPath {
    double theta, log_lambda1, log_lambda2;
    Eigen::Matrix2d N;
    Eigen::Matrix2d operator()(double t) const;
  };
  /// One triangle's path, its angle θ_i on the chosen branch included (the linear path has none).
  using Path =
      std::variant<ExpPath, local::PolarHomotopy<double>, local::LinearHomotopy<double>, local::SvdHomotopy<double>>;
  std::vector<Path> paths_;  ///< one per triangle
};

}  // namespace affinterp::global
