#include "theory/global/interpolation.hpp"

#include "theory/global/constraint_terms.hpp"
#include "theory/global/frame_assembly.hpp"
#include "theory/global/local_paths.hpp"
#include "theory/global/mesh_validation.hpp"
#include "theory/global/rotation_branch.hpp"
#include "theory/global/sparse_minimiser.hpp"
#include "theory/global/well_posedness.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>

namespace affinterp::global {
namespace {

/// The input of Kaji §2 that the engine needs (mesh_validation.hpp): well formed, one triangle list, one
/// piece (else the minimiser is not unique), and det A_i > 0 on every triangle.
void require_valid_meshes(const Mesh& source, const Mesh& target) {
  check_well_formed(source);
  check_well_formed(target);
  check_compatible(source, target);
  check_connected(source);
  check_orientation_preserved(source, target);
}

void require_valid_options(const InterpolationOptions& options, Eigen::Index triangles) {
  if (!(options.t_begin <= options.t_end) || !std::isfinite(options.t_begin) || !std::isfinite(options.t_end))
    throw RefusedProblem("the time range must be finite with t_begin <= t_end");
  if (options.energy != Energy::blend) return;
  const bool per_triangle = options.blend_weights.size() > 0;
  if (per_triangle && options.blend_weights.size() != triangles)
    throw RefusedProblem("the blend needs one weight w_i per triangle (" + std::to_string(triangles) + "), got " +
                         std::to_string(options.blend_weights.size()));
  const Eigen::VectorXd w = per_triangle ? options.blend_weights : Eigen::VectorXd::Constant(1, options.blend_weight);
  if (!w.allFinite() || (w.array() < 0).any() || (w.array() > 1).any())
    throw RefusedProblem("blend weights w_i must lie in [0, 1]");
}

std::vector<Eigen::Matrix2d> linear_parts(const Mesh& from, const Mesh& to) {
  std::vector<Eigen::Matrix2d> A;
  A.reserve(static_cast<std::size_t>(from.triangle_count()));
  for (Eigen::Index i = 0; i < from.triangle_count(); ++i) {
    Corners<double> p, q;
    for (int c = 0; c < 3; ++c) p.col(c) = from.corner(i, c), q.col(c) = to.corner(i, c);
    A.push_back(linear_part(p, q));
  }
  return A;
}

bool has_frobenius_part(const InterpolationOptions& options) {
  if (options.energy == Energy::frobenius) return true;
  if (options.energy != Energy::blend) return false;
  return options.blend_weights.size() > 0 ? (options.blend_weights.array() > 0).any() : options.blend_weight > 0;
}

}  // namespace

struct Interpolation::Engine {
  InterpolationOptions options;
  Eigen::VectorXd theta;  ///< θ_i of each A_i on its chosen branch (rotation_branch.hpp)
  LocalPaths forward;
  std::optional<LocalPaths> reverse;  // the reverse problem Q → P, for E′(t) = E(t) + E^{-1}(1 − t)
  std::optional<FrameAssembly> assembly;
  /// H = L real and fixed: factored once, x and y solved as two real columns.
  SparseMinimiser<double> fixed;
  /// H(t) complex Hermitian: its values refilled and refactorised per frame in a workspace, its pattern
  /// analysed once.
  struct Workspace {
    FrameAssembly::SparseMatrix H;
    SparseMinimiser<std::complex<double>> minimiser;
  };
  /// The workspace of vertices_at(t): the only state a frame changes, hence mutable, and guarded so that
  /// the const vertices_at is safe to call concurrently. The batch call copies it, one per worker.
  struct PerFrame : Workspace {
    std::mutex mutex;
  };
  mutable PerFrame per_frame;

  /// v(t) at a t in range, when H is fixed: L [x y] = [Re b, Im b], both columns in one solve.
  Eigen::Matrix2Xd isotropic_frame(double t) const {
    const Eigen::VectorXcd b = assembly->right_hand_side_at(t);  // H z = −ũ/2 (hermitian_form.hpp)
    Eigen::MatrixXd xy(b.size(), 2);
    xy << b.real(), b.imag();
    return fixed.solve(xy).transpose();
  }
  /// v(t) at a t in range, when H(t) changes with A_i(t): a numeric factorisation per frame in `work`.
  Eigen::Matrix2Xd frame_in(Workspace& work, double t) const {
    assembly->matrix_at(t, work.H);
    work.minimiser.factorise(work.H);
    const Eigen::VectorXcd z = work.minimiser.solve(assembly->right_hand_side_at(t));
    Eigen::Matrix2Xd v(2, z.size());
    v << z.real().transpose(), z.imag().transpose();  // z_k = v_kx + i v_ky
    return v;
  }
  template <class Scalar>
  void analyse(SparseMinimiser<Scalar>& minimiser, const Eigen::SparseMatrix<Scalar>& K) const {
    if (options.back_end)
      minimiser.analyse(K, assembly->dense_term(), *options.back_end);
    else
      minimiser.analyse(K, assembly->dense_term());
  }
  void require_in_range(double t) const {
    if (!(t >= options.t_begin && t <= options.t_end))
      throw std::out_of_range("t = " + std::to_string(t) + " is outside the time range [" +
                              std::to_string(options.t_begin) + ", " + std::to_string(options.t_end) + "]");
  }

  Engine(const Mesh& source, const Mesh& target, InterpolationOptions opts, Eigen::VectorXd angles)
      : options(std::move(opts)),
        theta(std::move(angles)),
        forward(linear_parts(source, target), options.homotopy, theta) {
    if (options.symmetric) reverse.emplace(linear_parts(target, source), options.homotopy, -theta);
    auto terms = constraint_terms(options.constraints, source, target, forward);
    require_well_posed(source, terms, !has_frobenius_part(options), "E^" + to_string(options.energy));
    assembly.emplace(source, target, options, forward, reverse ? &*reverse : nullptr, std::move(terms));
    FrameAssembly::SparseMatrix H = assembly->pattern();
    assembly->matrix_at(options.t_begin, H);
    if (assembly->isotropic()) {
      Eigen::SparseMatrix<double> L = H.real();
      L.makeCompressed();
      analyse(fixed, L);
      fixed.factorise(L);
    } else {
      analyse(per_frame.minimiser, H);
      per_frame.minimiser.factorise(H);
      per_frame.H = std::move(H);
    }
  }
};

Interpolation::Interpolation(const Mesh& source, const Mesh& target, InterpolationOptions options) {
  require_valid_meshes(source, target);
  require_valid_options(options, source.triangle_count());
  const std::vector<Eigen::Matrix2d> A = linear_parts(source, target);
  Eigen::VectorXd theta(static_cast<Eigen::Index>(A.size()));
  for (std::size_t i = 0; i < A.size(); ++i) theta[static_cast<Eigen::Index>(i)] = principal_polar_angle(A[i]);
  if (options.rotation_branch == RotationBranch::consistent) theta = consistent_angles(source.triangles, theta);
  engine_ = std::make_unique<Engine>(source, target, std::move(options), std::move(theta));
}

Interpolation::~Interpolation() = default;
Interpolation::Interpolation(Interpolation&&) noexcept = default;
Interpolation& Interpolation::operator=(Interpolation&&) noexcept = default;

Eigen::Matrix2Xd Interpolation::vertices_at(double t) const {
  const Engine& engine = *engine_;  // const all through, but for the per-frame workspace
  engine.require_in_range(t);
  if (engine.assembly->isotropic()) return engine.isotropic_frame(t);
  const std::lock_guard lock(engine.per_frame.mutex);
  return engine.frame_in(engine.per_frame, t);
}

std::vector<Eigen::Matrix2Xd> Interpolation::vertices_at(const std::vector<double>& times) const {
  const Engine& engine = *engine_;
  for (const double t : times) engine.require_in_range(t);
  std::vector<Eigen::Matrix2Xd> frames(times.size());
  const bool isotropic = engine.assembly->isotropic();
  std::size_t workers = std::min<std::size_t>(std::max(1u, std::thread::hardware_concurrency()), times.size());
  if (!isotropic) {  // a factor per worker, within 1 GiB
    const double bytes = std::max(1.0, engine.per_frame.minimiser.factor().factor_bytes());
    workers = std::min(workers, static_cast<std::size_t>(std::max(1.0, std::floor(1073741824.0 / bytes))));
  }
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  auto work = [&] {
    try {
      std::optional<Engine::Workspace> own;
      if (!isotropic) {
        const std::lock_guard lock(engine.per_frame.mutex);
        own.emplace(engine.per_frame);
      }
      for (std::size_t k; (k = next++) < times.size();)
        frames[k] = isotropic ? engine.isotropic_frame(times[k]) : engine.frame_in(*own, times[k]);
    } catch (...) {
      const std::lock_guard lock(failure_mutex);
      if (!failure) failure = std::current_exception();
      next = times.size();
    }
  };
  std::vector<std::thread> threads;
  for (std::size_t w = 1; w < workers; ++w) threads.emplace_back(work);
  work();
  for (std::thread& thread : threads) thread.join();
  if (failure) std::rethrow_exception(failure);
  return frames;
}

FrameEnergy Interpolation::energy_at(double t, const Eigen::Matrix2Xd& v) const {
  if (v.cols() != engine_->assembly->pattern().rows())
    throw std::invalid_argument("energy_at: " + std::to_string(v.cols()) + " vertices for a mesh of " +
                                std::to_string(engine_->assembly->pattern().rows()));
  return engine_->assembly->energy_at(t, v);
}

FrameQuadratic Interpolation::quadratic_at(double t) const { return engine_->assembly->dense_quadratic_at(t); }
bool Interpolation::factored_once() const { return engine_->assembly->isotropic(); }
const Eigen::VectorXd& Interpolation::rotation_angles() const { return engine_->theta; }
Eigen::Matrix2d Interpolation::local_map(Eigen::Index i, double t) const { return engine_->forward.at(i, t); }
const InterpolationOptions& Interpolation::options() const { return engine_->options; }

}  // namespace affinterp::global
