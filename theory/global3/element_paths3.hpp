#pragma once
// Each element's local homotopy A_i(t) between I and A_i (theory/local3), as the 3D engine evaluates it for all
// elements of a frame: the rotation logarithms chosen once (principal, or consistent: rotation_branches3.hpp),
// the decompositions computed once, and exp-log's S_i^t = exp(t log S_i) for all elements through one batched
// pass (local_maps3.hpp).
//
// Branches per homotopy: polar and exp-log use ω_i, the chosen logarithm of R_i: on the principal branch along
// R_i^t = exp(t [ω_i]×); on the consistent branch along exp(t [ω̄_i]×) exp(t [η_i]×), its carrier and remainder
// (rotation_carrier3.hpp), which is R_i^t wherever the rotations share an axis. SVD uses logarithms of U_i and
// V_iᵀ; with the consistent branch ω_{U,i} is moved to its representative nearest ω_{U,i} + (ω_i − ω_i^principal),
// the 3D form of the 2D engine's α + (θ_branch − θ) (U_i ≈ R_i where V_i ≈ I); it is not a consistency of U_i's
// own field, which the SVD's sign and order choices can break between neighbours. Linear has no branch.
#include "theory/global/options.hpp"
#include "theory/global3/rotation_branches3.hpp"
#include "theory/global3/rotation_carrier3.hpp"
#include "theory/sym3/exp_batch.hpp"

#include <Eigen/Core>

#include <span>
#include <vector>

namespace affinterp::global3 {

class ElementPaths3 {
 public:
  /// A_i ∈ GL⁺(3) for each element (element_maps3.hpp); `graph` the elements' dual graph. Throws
  /// std::invalid_argument if some det A_i ≤ 0.
  ElementPaths3(const std::vector<Eigen::Matrix3d>& maps, global::LocalHomotopy homotopy, global::RotationBranch branch,
                const DualGraph3& graph);
  /// The reverse paths of the symmetrised energy, from the target's element maps A_i⁻¹ (`maps`) back: each ω_i the
  /// representative of R_iᵀ's logarithm nearest −ω_i of `forward` (those of R_iᵀ are those of R_i negated), as the
  /// 2D engine's reverse paths take −θ_i, split along forward's carrier negated.
  ElementPaths3(const std::vector<Eigen::Matrix3d>& maps, global::LocalHomotopy homotopy, const ElementPaths3& forward);

  /// out[i] = A_i(t) for every element, on up to `threads` threads; the same bits on any number. `exp`: the
  /// exp-log homotopy's symmetric exponentials (empty: sym3::exp_batched).
  void maps_at(double t, std::span<Eigen::Matrix3d> out, std::size_t threads, const sym3::SymExpBatch& exp = {}) const;
  /// ω_i (column i), the logarithm of R_i in use.
  const Eigen::Matrix3Xd& rotation_logs() const { return omega_; }
  /// ω_i's carrier and remainder, along which polar and exp-log turn.
  const RotationSplit3& rotation_split() const { return split_; }
  Eigen::Index element_count() const { return omega_.cols(); }

 private:
  global::LocalHomotopy homotopy_;
  global::RotationBranch branch_;
  std::vector<Eigen::Matrix3d> A_;              ///< linear
  Eigen::Matrix3Xd omega_;                      ///< polar, exp-log (and reported for every homotopy)
  RotationSplit3 split_;                        ///< polar, exp-log
  std::vector<Eigen::Matrix3d> stretch_;        ///< polar: S_i; exp-log: log S_i
  Eigen::Matrix3Xd omega_U_, sigma_, omega_V_;  ///< svd

  /// The decompositions; returns the principal logarithms of the R_i.
  Eigen::Matrix3Xd decompose(const std::vector<Eigen::Matrix3d>& maps);
  /// ω from the chosen logarithms, and the SVD's ω_U moved along with them.
  void use_logs(const Eigen::Matrix3Xd& chosen, const Eigen::Matrix3Xd& principal);
  /// Whether polar and exp-log turn along a split of ω.
  bool turns() const { return homotopy_ == global::LocalHomotopy::exp || homotopy_ == global::LocalHomotopy::polar; }
};

}  // namespace affinterp::global3
