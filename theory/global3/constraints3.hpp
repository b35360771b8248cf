#pragma once
// The constraint function C of Kaji §4 in 3D: pinned vertices, vertex loci and the barycentre, each a term
// c ‖ℓ(v) − r‖² whose target r a frame gives (ConstraintTargets3). For an interpolation: a pinned vertex on the
// straight line from source to target, (1−t)p_k + t q_k; a vertex locus on the B-spline through its points at
// t = 0 … 1 (global/locus.hpp, as in 2D); the barycentre on the line between the two barycentres or on the
// B-spline through its points. For a blend, the weighted sum Σ_k w_k p_k over the poses (pins and the barycentre's
// line only: a locus has no time there). Edge directions (2D options.hpp) are not offered in 3D.
#include "theory/global/locus.hpp"
#include "theory/global/options.hpp"
#include "theory/global3/mesh3.hpp"

#include <Eigen/Core>

#include <optional>
#include <vector>

namespace affinterp::global3 {

/// Vertex `vertex` should trace u(t), the B-spline through `points` (3 × N, N ≥ 2) at t = 0, 1/(N−1), …, 1:
/// adds c ‖v_k − u(t)‖².
struct VertexLocus3 {
  Eigen::Index vertex = 0;
  Eigen::Matrix3Xd points;
  double weight = 1.0;  ///< c > 0
};

/// The barycentre Σ v_k / n should be at u_o(t): the line between the source's and the target's barycentres (no
/// points), or the B-spline through `points`. Adds c_o ‖Σ v/n − u_o‖². On E^F without pins or loci it only fixes
/// the translation (the minimiser's shape does not depend on c_o).
struct BarycentreLocus3 {
  double weight = 1.0;  ///< c_o > 0
  Eigen::Matrix3Xd points;
};

struct Constraints3 {
  /// Vertex k should be at its target: adds c ‖v_k − r_k‖² (global::PinnedVertex's vertex and weight c > 0).
  std::vector<global::PinnedVertex> pinned;
  std::vector<VertexLocus3> loci;
  /// On by default: without it a pinned vertex or a locus must fix the translation.
  std::optional<BarycentreLocus3> barycentre = BarycentreLocus3{};
};

/// The vertex terms of `constraints` in the order ConstraintTargets3 lists their targets: the pins, then the loci
/// (vertex and weight each).
std::vector<global::PinnedVertex> vertex_terms(const Constraints3& constraints);

/// Where a frame's constraints want the vertices: column j of `vertices` for vertex_terms(…)[j], and the
/// barycentre's point.
struct ConstraintTargets3 {
  Eigen::Matrix3Xd vertices;
  Eigen::Vector3d barycentre = Eigen::Vector3d::Zero();
};

/// The targets of an interpolation from `source` to `target` (3 × n each), as above: what a frame needs of the
/// poses and the loci's B-splines kept from the set-up, so that a frame evaluates them only.
class InterpolationTargets3 {
 public:
  /// Throws std::invalid_argument for a locus of fewer than two points or with a non-finite one.
  InterpolationTargets3(const Constraints3& constraints, const Eigen::Matrix3Xd& source,
                        const Eigen::Matrix3Xd& target);
  ConstraintTargets3 at(double t) const;

 private:
  Eigen::Matrix3Xd pinned_source_, pinned_target_;  ///< each pinned vertex in the two poses
  std::vector<global::Locus3> loci_;
  Eigen::Vector3d barycentre_source_, barycentre_target_;
  std::optional<global::Locus3> barycentre_locus_;  ///< the barycentre's B-spline, when it has points
};

/// The targets of a blend of `poses` (one element list) with weights w, one per pose: pinned vertex k at
/// Σ_j w_j (pose j's vertex k), the barycentre at Σ_j w_j (pose j's barycentre); the poses' pinned vertices and
/// barycentres kept from the set-up. Throws std::invalid_argument for loci or a barycentre through points, which
/// have no weighted sum.
class BlendTargets3 {
 public:
  BlendTargets3(const Constraints3& constraints, const std::vector<Mesh3>& poses);
  ConstraintTargets3 at(const Eigen::VectorXd& w) const;

 private:
  std::vector<Eigen::Matrix3Xd> pinned_;  ///< per pose: its pinned vertices
  Eigen::Matrix3Xd barycentres_;          ///< column j: pose j's barycentre
};

}  // namespace affinterp::global3
