#pragma once
// Global interpolation in 3D (Kaji §4 with E^F, in the thesis's Xu et al. Poisson form): for each time t, the
// vertices v(t) minimising Σ_i w_i ‖B_i(t) − A_i(t)‖²_F + C(v) (poisson_system3.hpp), A_i(t) the local homotopy
// of element i (theory/local3; element_paths3.hpp) between I and A_i (element_maps3.hpp: tetrahedra's affine maps,
// triangles' Sumner–Popović frames), w_i the source element's area or volume. The set-up (constructor) validates,
// decomposes each A_i and chooses the rotation branches while another thread factors E^F's matrix, once; a frame
// is the local maps, a right-hand side and a solve.
//
// What does not carry over from the 2D engine (theory/global/interpolation.hpp): E^R, E^S and so their blend.
// E^R's closed form (Kaji Appendix) minimises over similarities s R_δ by writing 2D similarities as complex
// numbers, so that min_{s,δ} ‖s R_δ A − B‖² is a Hermitian form in the vertices; 3D similarities s R (R ∈ SO(3))
// form no field, the minimum over R is an orthogonal Procrustes problem whose minimiser is not linear in B, and the
// energy is no longer a quadratic form: no one-solve-per-frame counterpart exists. E^S minimises over the same
// similarities and fails the same way. The nearest sound 3D counterpart is offered: `arap_iterations` local/global
// (as-rigid-as-possible) steps on each frame, E^R with its scale held at 1, with this factor (arap_refinement3.hpp;
// each costs a solve and a rotation fitted to each element).
//
// The symmetrised E′(t) = E(t) + E^{−1}(1 − t) (Kaji's "Improvements", the 2D engine's `symmetric`) carries over
// for E^F: the reverse problem fits the target's elements to their reverse homotopies Ā_i(1 − t) between I and
// A_i⁻¹ (rotation logarithms −ω_i, element_paths3.hpp), its B̄_i is linear in the same vertices through the target's
// edges, so E′ is a quadratic form whose matrix (poisson_system3.hpp, two rest poses) is constant in t: one
// factorisation still serves every frame, and a frame costs two passes of local maps and right-hand side. The
// constraints' term C counts once. Swapping source and target gives the same frames at 1 − t.
#include "theory/global/options.hpp"
#include "theory/global/refused_problem.hpp"
#include "theory/global3/constraints3.hpp"
#include "theory/global3/frame_timings.hpp"
#include "theory/global3/mesh3.hpp"
#include "theory/global3/poisson_system3.hpp"
#include "theory/global3/rotation_carrier3.hpp"
#include "theory/sym3/exp_batch.hpp"

#include <Eigen/Core>

#include <memory>
#include <optional>
#include <vector>

namespace affinterp::global3 {

struct Interpolation3Options {
  /// A_i(t): exp-log R^t S^t by default, as in 2D (the one that never inverts an element: det = e^{t tr log S}).
  global::LocalHomotopy homotopy = global::LocalHomotopy::exp;
  /// consistent by default: a shape turning beyond π (a twisted bar, a turned tail) turns smoothly.
  global::RotationBranch rotation_branch = global::RotationBranch::consistent;
  /// w_i = the source element's area (triangles) or volume (tetrahedra); false: w_i = 1.
  bool area_weighted = true;
  /// E′(t) = E(t) + E^{−1}(1 − t), the source's and the target's elements both fitted (above).
  bool symmetric = false;
  /// Pinned vertices move on (1−t)p_k + t q_k, vertex loci on their B-splines, the barycentre on the line between
  /// the two barycentres or its B-spline (constraints3.hpp).
  Constraints3 constraints;
  std::optional<global::SparseBackEnd> back_end;  ///< none: chosen by the mesh's size
  /// As-rigid-as-possible steps on each E^F frame (arap_refinement3.hpp): each element may turn its A_i(t), so
  /// the frame keeps the local maps' stretches and lets rotations follow constraints and neighbours. 0: none.
  int arap_iterations = 0;
  /// Threads one frame's loops and solve may use; 0: chosen by the mesh's size (small meshes: one).
  std::size_t frame_threads = 0;
  /// exp-log's symmetric exponentials S^t = exp(t log S), one batch per exp_chunk elements; empty:
  /// sym3::exp_batched (the thesis's improved algorithm, SIMD-batched). Another algorithm of theory/sym3 here
  /// prices it inside a real frame (the benchmarks); the frame is then that algorithm's, not bit for bit this one's.
  sym3::SymExpBatch exp;
};

/// Set up once from (source, target, options); then each frame is one batched pass of local maps and one solve.
class Interpolation3 {
 public:
  /// Throws global::RefusedProblem (global::InvalidMesh for the meshes: mesh3_validation.hpp) for meshes that
  /// are not a valid pair, bad constraints, an ill-posed system or an arap_iterations outside
  /// 0 … max_arap_iterations (arap_refinement3.hpp).
  Interpolation3(const Mesh3& source, const Mesh3& target, Interpolation3Options options = {});
  ~Interpolation3();
  Interpolation3(Interpolation3&&) noexcept;
  Interpolation3& operator=(Interpolation3&&) noexcept;

  /// v(t), column k = v_k(t), for any finite t (t ∉ [0, 1] extrapolates the homotopies); throws
  /// std::out_of_range for a non-finite t.
  /// \note const and safe to call from several threads on one object: the set-up is read only, each call
  /// keeps its own buffers. The same vertices, bit for bit, whatever frame_threads is.
  Eigen::Matrix3Xd vertices_at(double t) const;
  /// The same, with the frame's time split into its parts.
  Eigen::Matrix3Xd vertices_at(double t, FrameTimings& timings) const;
  /// v(t) for each of `times`, in their order, computed in parallel (one worker per hardware thread, each frame
  /// on one thread): the same bits as vertices_at(t) one after another. Throws before computing any frame.
  std::vector<Eigen::Matrix3Xd> vertices_at(const std::vector<double>& times) const;

  /// A_i(t) of every element, the local maps the frame fits (one batched pass; symmetrised, the forward ones).
  std::vector<Eigen::Matrix3d> local_maps_at(double t) const;
  /// Where the constraints want the vertices at t.
  ConstraintTargets3 targets_at(double t) const;
  /// The energy vertices_at(t) minimises, at the vertices v (3 × n): E^F (E′ symmetrised) plus C; with
  /// arap_iterations, E^ARAP (arap_refinement3.hpp), which the iterations lower.
  double energy_at(double t, const Eigen::Matrix3Xd& v) const;
  /// ω_i (column i): the rotation logarithm of each element after the branch choice.
  const Eigen::Matrix3Xd& rotation_logs() const;
  /// Polar and exp-log: ω_i's carrier and remainder, along which element i turns (rotation_carrier3.hpp).
  const RotationSplit3& rotation_split() const;
  /// The factored system, for benchmarks timing its steps.
  const PoissonSystem3& system() const;
  const Interpolation3Options& options() const;

 private:
  struct Engine;
  std::unique_ptr<Engine> engine_;
};

}  // namespace affinterp::global3
