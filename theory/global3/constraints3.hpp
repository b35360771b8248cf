#pragma once
// The constraint function C of Kaji §4 in 3D: pinned vertices and the barycentre, each a term c ‖ℓ(v) − r‖² whose
// target r a frame gives (ConstraintTargets3): for an interpolation the straight line from source to target,
// (1−t)p_k + t q_k; for a blend the weighted sum Σ_k w_k p_k over the poses. Vertex loci along curves, edge
// directions and a barycentre along a B-spline (2D options.hpp) are not offered in 3D yet.
#include "theory/global/options.hpp"

#include <Eigen/Core>

#include <optional>
#include <vector>

namespace affinterp::global3 {

/// The barycentre Σ v_k / n should be at the frame's barycentre target: adds c_o ‖Σ v/n − u_o‖². On E^F without
/// pins it only fixes the translation (the minimiser's shape does not depend on c_o).
struct BarycentreLine3 {
  double weight = 1.0;  ///< c_o > 0
};

struct Constraints3 {
  /// Vertex k should be at its target: adds c ‖v_k − r_k‖² (global::PinnedVertex's vertex and weight c > 0).
  std::vector<global::PinnedVertex> pinned;
  /// On by default: without it a pinned vertex must fix the translation.
  std::optional<BarycentreLine3> barycentre = BarycentreLine3{};
};

/// Where a frame's constraints want the vertices: column j of `pinned` for Constraints3::pinned[j], and the
/// barycentre's point.
struct ConstraintTargets3 {
  Eigen::Matrix3Xd pinned;
  Eigen::Vector3d barycentre = Eigen::Vector3d::Zero();
};

/// The targets of the poses' weighted sum: pinned vertex k at Σ_j w_j (pose j's vertex k), the barycentre at
/// Σ_j w_j (pose j's barycentre). `poses` are 3 × n vertex matrices, as many as `w` has entries.
ConstraintTargets3 weighted_targets(const Constraints3& constraints, const std::vector<const Eigen::Matrix3Xd*>& poses,
                                    const Eigen::VectorXd& w);

}  // namespace affinterp::global3
