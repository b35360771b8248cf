#include "theory/global/interpolation.hpp"

#include "theory/global/constraint_terms.hpp"
#include "theory/global/frame_assembly.hpp"
#include "theory/global/local_paths.hpp"
#include "theory/global/mesh_validation.hpp"
#include "theory/global/parallel_ranges.hpp"
#include "theory/global/rotation_branch.hpp"
#include "theory/global/sparse_minimiser.hpp"
#include "theory/global/well_posedness.hpp"

#include <algorithm>
#include <array>
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

std::vector<Eigen::Matrix2d> linear_parts(const Mesh& from, const Mesh& to) {
  std::vector<Eigen::Matrix2d> A(static_cast<std::size_t>(from.triangle_count()));
  for_each_range(A.size(), ranges_for(A.size(), triangles_per_thread), [&](std::size_t first, std::size_t last) {
    for (std::size_t i = first; i < last; ++i) {
      Corners<double> p, q;
      for (int c = 0; c < 3; ++c)
        p.col(c) = from.corner(static_cast<Eigen::Index>(i), c), q.col(c) = to.corner(static_cast<Eigen::Index>(i), c);
      A[i] = linear_part(p, q);
    }
  });
  return A;
}

bool has_frobenius_part(const InterpolationOptions& options) {
  if (options.energy == Energy::F) return true;
  if (options.energy != Energy::blend) return false;
  return options.blend_weights.size() > 0 ? (options.blend_weights.array() > 0).any() : options.blend_weight > 0;
}

/// The factors of the batch call's workspaces together stay within this many bytes (a 1M-triangle mesh's
/// batch within 2 GB: bench_scale).
constexpr double workspace_bytes = 1.25 * 1073741824.0;

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
    std::mutex mutex;  ///< held by the one call computing a frame in it
    Workspace(FrameAssembly::SparseMatrix matrix, SparseMinimiser<std::complex<double>> factored)
        : H(std::move(matrix)), minimiser(std::move(factored)) {}
    Workspace(const Workspace& other) : H(other.H), minimiser(other.minimiser) {}
  };
  /// The frames' workspaces: [0] that of vertices_at(t), [0, W) those of the batch call (one or two a worker), kept
  /// for the next batch. They are the only state a frame changes, hence mutable; each is guarded by its
  /// mutex, the list (which a batch may lengthen) by its own, and the first stays where it is.
  mutable std::vector<std::unique_ptr<Workspace>> workspaces;
  mutable std::mutex workspaces_mutex;
  Workspace* first_workspace = nullptr;

  /// v(t) at a t in range, when H is fixed: L [x y] = [Re b, Im b], both columns in one solve; the
  /// right-hand side and the solve on up to `threads` threads.
  Eigen::Matrix2Xd isotropic_frame(double t, std::size_t threads) const {
    const Eigen::VectorXcd b = assembly->right_hand_side_at(t, threads);  // H z = −ũ/2 (hermitian_form.hpp)
    Eigen::MatrixXd xy(b.size(), 2);
    xy << b.real(), b.imag();
    return fixed.solve(xy, threads).transpose();
  }
  /// v(t) at a t in range, when H(t) changes with A_i(t): a numeric factorisation per frame in `work`, H(t)'s
  /// assembly, the factorisation and the solve on up to `threads` threads.
  Eigen::Matrix2Xd frame_in(Workspace& work, double t, std::size_t threads) const {
    assembly->matrix_at(t, work.H, threads);
    work.minimiser.factorise(work.H, threads);
    return solution_in(work, t, threads);
  }
  /// v(a) and v(b) on one thread, H(a) and H(b) factorised in one pass (SparseMinimiser::factorise_two) in the
  /// workspaces `at_a` and `at_b`: the frames that frame_in gives.
  std::array<Eigen::Matrix2Xd, 2> frames_in(Workspace& at_a, Workspace& at_b, double a, double b) const {
    assembly->matrix_at(a, at_a.H);
    assembly->matrix_at(b, at_b.H);
    at_a.minimiser.factorise_two(at_a.H, at_b.minimiser, at_b.H);
    return {solution_in(at_a, a, 1), solution_in(at_b, b, 1)};
  }
  /// v(t) with H(t) factorised in `work`.
  Eigen::Matrix2Xd solution_in(const Workspace& work, double t, std::size_t threads) const {
    const Eigen::VectorXcd z = work.minimiser.solve(assembly->right_hand_side_at(t, threads), threads);
    Eigen::Matrix2Xd v(2, z.size());
    v << z.real().transpose(), z.imag().transpose();  // z_k = v_kx + i v_ky
    return v;
  }
  /// The threads worth one frame, and one numeric factorisation (parallel_ranges.hpp).
  std::size_t threads_per_frame() const {
    return frame_threads(static_cast<std::size_t>(assembly->pattern().rows()), !assembly->isotropic());
  }
  std::size_t factor_threads() const {
    return frame_threads(static_cast<std::size_t>(assembly->pattern().rows()), /*factorised_per_frame=*/true);
  }
  /// The first `count` workspaces, the missing ones made as copies of the first.
  std::vector<Workspace*> reserve_workspaces(std::size_t count) const {
    const std::lock_guard lock(workspaces_mutex);
    while (workspaces.size() < count) {
      const std::lock_guard first(first_workspace->mutex);
      workspaces.push_back(std::make_unique<Workspace>(*first_workspace));
    }
    std::vector<Workspace*> reserved;
    for (std::size_t w = 0; w < count; ++w) reserved.push_back(workspaces[w].get());
    return reserved;
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

  /// A_i, their polar angles θ_i on the chosen branches (rotation_branch.hpp) and the local paths, forward
  /// and, when symmetrised, reverse.
  void set_paths(const Mesh& source, const Mesh& target) {
    const std::vector<Eigen::Matrix2d> A = linear_parts(source, target);
    theta.resize(static_cast<Eigen::Index>(A.size()));
    for_each_range(A.size(), ranges_for(A.size(), triangles_per_thread), [&](std::size_t first, std::size_t last) {
      for (std::size_t i = first; i < last; ++i) theta[static_cast<Eigen::Index>(i)] = principal_polar_angle(A[i]);
    });
    if (options.rotation_branch == RotationBranch::consistent) theta = consistent_angles(source.triangles, theta);
    forward = LocalPaths(A, options.homotopy, theta);
    if (reverse) *reverse = LocalPaths(linear_parts(target, source), options.homotopy, -theta);
  }

  Engine(const Mesh& source, const Mesh& target, InterpolationOptions opts) : options(std::move(opts)) {
    if (options.symmetric) reverse.emplace();
    // the constraint terms and the assembly refer to the paths, read frame by frame: set_paths fills them below
    auto terms = constraint_terms(options.constraints, source, target, forward);
    require_well_posed(source, terms, !has_frobenius_part(options), "E^" + to_string(options.energy));
    assembly.emplace(source, target, options, forward, reverse ? &*reverse : nullptr, std::move(terms));
    // Two lines of work side by side: the symbolic analysis, which reads H's pattern only (its ordering the
    // longest step before the first factorisation), and what H's values need, the local maps, branches and paths,
    // then H at t_begin (at 1M triangles each takes a sizeable part of the set-up on one thread)
    FrameAssembly::SparseMatrix H = assembly->pattern();
    auto fill = [&] {
      set_paths(source, target);
      assembly->matrix_at(options.t_begin, H);
    };
    if (assembly->isotropic()) {
      Eigen::SparseMatrix<double> L = assembly->pattern().real();
      L.makeCompressed();
      side_by_side(fill, [&] { analyse(fixed, L); });
      L = H.real();
      L.makeCompressed();
      fixed.factorise(L, factor_threads());
    } else {
      SparseMinimiser<std::complex<double>> minimiser;
      side_by_side(fill, [&] { analyse(minimiser, assembly->pattern()); });
      minimiser.factorise(H, factor_threads());
      workspaces.push_back(std::make_unique<Workspace>(std::move(H), std::move(minimiser)));
      first_workspace = workspaces.front().get();
    }
  }
};

Interpolation::Interpolation(const Mesh& source, const Mesh& target, InterpolationOptions options) {
  require_valid_meshes(source, target);
  require_valid_options(options, source.triangle_count());
  engine_ = std::make_unique<Engine>(source, target, std::move(options));
}

Interpolation::~Interpolation() = default;
Interpolation::Interpolation(Interpolation&&) noexcept = default;
Interpolation& Interpolation::operator=(Interpolation&&) noexcept = default;

Eigen::Matrix2Xd Interpolation::vertices_at(double t) const {
  const Engine& engine = *engine_;  // const all through, but for the frames' workspaces
  engine.require_in_range(t);
  if (engine.assembly->isotropic()) return engine.isotropic_frame(t, engine.threads_per_frame());
  Engine::Workspace& work = *engine.first_workspace;
  const std::lock_guard lock(work.mutex);
  return engine.frame_in(work, t, engine.threads_per_frame());
}

std::vector<Eigen::Matrix2Xd> Interpolation::vertices_at(const std::vector<double>& times) const {
  const Engine& engine = *engine_;
  for (const double t : times) engine.require_in_range(t);
  std::vector<Eigen::Matrix2Xd> frames(times.size());
  const bool isotropic = engine.assembly->isotropic();
  // Where the back-end factorises two frames in one pass (SparseFactor::factorise_two), a worker takes two frames
  // at a time, in two workspaces
  std::size_t per_worker = 1;
  double bytes = 1;
  if (!isotropic) {
    const std::lock_guard lock(engine.first_workspace->mutex);
    const SparseFactor<std::complex<double>>& factor = engine.first_workspace->minimiser.factor();
    if (factor.two_in_one_pass() && times.size() > 1) per_worker = 2;
    bytes = std::max(bytes, factor.factor_bytes());
  }
  std::size_t workers = std::min<std::size_t>(std::max(1u, std::thread::hardware_concurrency()),
                                              (times.size() + per_worker - 1) / per_worker);
  std::vector<Engine::Workspace*> workspaces;
  if (!isotropic) {  // per_worker workspaces a worker, their factors within workspace_bytes
    // two a worker: their two factors and factorise_two's L of both side by side, as large again
    const double worker_bytes = per_worker == 2 ? 4 * bytes : bytes;
    workers = std::min(workers, static_cast<std::size_t>(std::max(1.0, std::floor(workspace_bytes / worker_bytes))));
    workspaces = engine.reserve_workspaces(workers * per_worker);
  }
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  auto work = [&](std::size_t w) {  // worker w takes the next frames, in workspaces [w per_worker, (w + 1) per_worker)
    try {
      std::vector<std::unique_lock<std::mutex>> locks;
      Engine::Workspace* mine[2] = {nullptr, nullptr};
      if (!isotropic)
        for (std::size_t j = 0; j < per_worker; ++j)
          mine[j] = workspaces[w * per_worker + j], locks.emplace_back(mine[j]->mutex);
      for (std::size_t k; (k = next.fetch_add(per_worker)) < times.size();) {
        if (isotropic)
          frames[k] = engine.isotropic_frame(times[k], 1);
        else if (per_worker == 2 && k + 1 < times.size()) {
          auto [a, b] = engine.frames_in(*mine[0], *mine[1], times[k], times[k + 1]);
          frames[k] = std::move(a), frames[k + 1] = std::move(b);
        } else
          frames[k] = engine.frame_in(*mine[0], times[k], 1);
      }
    } catch (...) {
      const std::lock_guard lock(failure_mutex);
      if (!failure) failure = std::current_exception();
      next = times.size();
    }
  };
  std::vector<std::thread> threads;
  for (std::size_t w = 1; w < workers; ++w) threads.emplace_back(work, w);
  if (workers > 0) work(0);
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
