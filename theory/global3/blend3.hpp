#pragma once
// N-way blending of K ≥ 2 compatible poses (3D; Kaji et al.'s Lie-algebra parametrisation, the thesis's
// reference [6]): with A_{k,i} = R_{k,i} S_{k,i} the map of element i from the rest mesh to pose k
// (element_maps3.hpp), ω_{k,i} a logarithm of R_{k,i} and log S_{k,i} the principal one, a weight vector w gives
//     A_i(w) = exp(Σ_k w_k [ω̄_{k,i}]×) · exp(Σ_k w_k [η_{k,i}]×) · exp(Σ_k w_k log S_{k,i}),
// with ω̄_{k,i} and η_{k,i} the carrier and remainder of ω_{k,i} on the consistent branch (rotation_carrier3.hpp;
// on the principal branch ω̄ = ω and η = 0; the symmetric exponentials through sym3::exp_batched: local_maps3.hpp),
// then the vertices minimising E^F
// against these maps (poisson_system3.hpp), translated so that the barycentre is Σ_k w_k (pose k's barycentre),
// pinned vertices at Σ_k w_k (pose k's vertex). E^F's matrix depends on the rest mesh only: one factorisation for
// every weight vector. With w = e_k the maps are A_{k,i} and the frame is pose k (E^F is zero there).
//
// Rotation branches, in this order: each pose's principal logarithms are made consistent over the dual graph
// (rotation_branches3.hpp); the walk's root (element 0) first takes the representative nearest the
// previous pose's logarithm there (pose 0's: nearest 0, the principal one), and the walk carries that choice to
// every element. So each pose's field is smooth across neighbours, and consecutive poses agree at the root.
// (Aligning every element with the previous pose's after the walk would undo the walk wherever the previous field
// is the rest's, ω = 0: a pose twisted beyond π would be snapped back to its principal logarithms.)
#include "theory/global/options.hpp"
#include "theory/global/refused_problem.hpp"
#include "theory/global3/constraints3.hpp"
#include "theory/global3/frame_timings.hpp"
#include "theory/global3/mesh3.hpp"
#include "theory/global3/poisson_system3.hpp"

#include <Eigen/Core>

#include <memory>
#include <optional>
#include <vector>

namespace affinterp::global3 {

struct Blend3Options {
  global::RotationBranch rotation_branch = global::RotationBranch::consistent;
  bool area_weighted = true;  ///< w_i = the rest element's area or volume; false: 1
  Constraints3 constraints;
  /// Weights off the simplex (a negative entry, or a sum other than 1 beyond 10⁻⁹) are refused unless this is
  /// set: they extrapolate beyond the poses.
  bool allow_extrapolation = false;
  std::optional<global::SparseBackEnd> back_end;
  int arap_iterations = 0;        ///< as Interpolation3Options::arap_iterations
  std::size_t frame_threads = 0;  ///< as Interpolation3Options::frame_threads
};

class Blend3 {
 public:
  /// Rest = poses[0]. Throws global::RefusedProblem for fewer than two poses, invalid or incompatible meshes
  /// (global::InvalidMesh), bad constraints, an arap_iterations outside 0 … max_arap_iterations.
  explicit Blend3(const std::vector<Mesh3>& poses, Blend3Options options = {});
  /// A separate rest mesh; the maps A_{k,i} go from it to each pose.
  Blend3(const Mesh3& rest, const std::vector<Mesh3>& poses, Blend3Options options = {});
  ~Blend3();
  Blend3(Blend3&&) noexcept;
  Blend3& operator=(Blend3&&) noexcept;

  /// The blend for the weights w (K entries). Throws global::RefusedProblem for a wrong count, a non-finite
  /// entry, or weights off the simplex without allow_extrapolation. Const and thread-safe as
  /// Interpolation3::vertices_at.
  Eigen::Matrix3Xd vertices_at(const Eigen::VectorXd& w) const;
  Eigen::Matrix3Xd vertices_at(const Eigen::VectorXd& w, FrameTimings& timings) const;
  /// One frame per weight vector, in parallel, the same bits as one at a time; all checked first.
  std::vector<Eigen::Matrix3Xd> vertices_at(const std::vector<Eigen::VectorXd>& weights) const;
  /// A_i(w) of every element.
  std::vector<Eigen::Matrix3d> local_maps_at(const Eigen::VectorXd& w) const;
  /// Throws as vertices_at does for weights it refuses.
  void require_valid_weights(const Eigen::VectorXd& w) const;

  Eigen::Index pose_count() const;
  /// ω_{k,i} (column i) for pose k, after the branch choice.
  const Eigen::Matrix3Xd& rotation_logs(Eigen::Index k) const;
  const PoissonSystem3& system() const;
  const Blend3Options& options() const;

 private:
  struct Engine;
  std::unique_ptr<Engine> engine_;
};

}  // namespace affinterp::global3
