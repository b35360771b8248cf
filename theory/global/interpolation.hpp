#pragma once
// Global interpolation (Kaji §4): for each time t, the piecewise affine map B(t) — equivalently the vertex
// positions v_1(t) … v_n(t) — minimising the global error function
//     E_t(B) = Σ_i E_i(A_i(t), B_i(t)) + C(v_1(t), …, v_n(t)),
// where A_i(t) is the local homotopy of triangle τ_i (Kaji §3), B_i(t) the linear part of B(t) on τ_i
// (linear in the v_k by eq. (1)), E_i a local error function and C a quadratic constraint function.
// E_t is the quadratic form vᵀ G(t) v + vᵀ u(t) + c (Kaji Appendix, "Efficiency"), minimised by
// solving 2 G(t) v = −u(t) — as the n × n complex Hermitian system H(t) z = −ũ(t)/2 of hermitian_form.hpp —
// with a sparse Cholesky factorisation.
//
// This facade includes what its callers need: the options (options.hpp), the error (refused_problem.hpp),
// the frame's quadratic form (frame_quadratic.hpp) and its value (frame_energy.hpp). The engine's own
// headers include those, never this.
#include "theory/global/frame_energy.hpp"
#include "theory/global/frame_quadratic.hpp"
#include "theory/global/mesh.hpp"
#include "theory/global/options.hpp"
#include "theory/global/refused_problem.hpp"

#include <Eigen/Core>

#include <memory>
#include <vector>

namespace affinterp::global {

/// Set up once from (source, target, options); then each frame is one sparse solve.
class Interpolation {
 public:
  /// Throws RefusedProblem for meshes that are not a valid pair (then an InvalidMesh: mesh_validation.hpp),
  /// bad options, or an ill-posed problem.
  Interpolation(const Mesh& source, const Mesh& target, InterpolationOptions options);
  ~Interpolation();
  Interpolation(Interpolation&&) noexcept;
  Interpolation& operator=(Interpolation&&) noexcept;

  /// v_1(t) … v_n(t), column k = v_k(t). Throws std::out_of_range outside [t_begin, t_end], and
  /// RefusedProblem when G(t) is singular at this t.
  /// \note const as in the standard library: no visible change, and safe to call from several threads on
  /// one object. When G depends on t (factored_once() is false) each call refactorises G(t) in one
  /// workspace that the object keeps for its frames, behind a mutex: concurrent calls on one object take
  /// turns; the batch call below computes frames in parallel. On large meshes the frame's own loops use
  /// the hardware threads (the same vertices whatever their number).
  Eigen::Matrix2Xd vertices_at(double t) const;
  /// v(t) for each of `times`, in their order: the same vertices as vertices_at(t) one after another,
  /// computed in parallel by one worker per hardware thread. When G depends on t each worker refactorises
  /// in a workspace of its own (two frames at a time in two, factorised in one pass, where the sparse back-end
  /// can: SparseFactor::factorise_two), as many workers as keep their factors within 1.25 GiB together; the object
  /// keeps the workspaces for its next batch. Throws as vertices_at(t) does; a time out of range before any
  /// frame is computed.
  std::vector<Eigen::Matrix2Xd> vertices_at(const std::vector<double>& times) const;

  /// The global error function E_t (Kaji §4; E′(t) when symmetrised) that vertices_at(t) minimises, at the
  /// vertices `v` (2 × n), with its parts. Throws std::invalid_argument when `v` has not n columns.
  FrameEnergy energy_at(double t, const Eigen::Matrix2Xd& v) const;
  /// The quadratic form minimised at time t (dense; for tests and claims on small meshes).
  FrameQuadratic quadratic_at(double t) const;
  /// Whether G is the same for every t, so that it is factored once (true exactly when no triangle
  /// carries an E^R or E^S part: see the claim kaji.global.G-time-independent).
  bool factored_once() const;
  /// The polar angle θ_i used for each triangle (after the rotation-branch choice).
  const Eigen::VectorXd& rotation_angles() const;
  /// A_i(t) of triangle i, the local homotopy the energy compares against.
  Eigen::Matrix2d local_map(Eigen::Index i, double t) const;

  const InterpolationOptions& options() const;

 private:
  struct Engine;
  std::unique_ptr<Engine> engine_;
};

}  // namespace affinterp::global
