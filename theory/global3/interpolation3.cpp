#include "theory/global3/interpolation3.hpp"

#include "theory/global/parallel_ranges.hpp"
#include "theory/global3/arap_refinement3.hpp"
#include "theory/global3/element_maps3.hpp"
#include "theory/global3/element_paths3.hpp"
#include "theory/global3/frame_solve3.hpp"
#include "theory/global3/frame_threads3.hpp"
#include "theory/global3/mesh3_validation.hpp"

#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace affinterp::global3 {

namespace {

/// Validates before the engine's members decompose anything.
const Mesh3& validated(const Mesh3& source, const Mesh3& target) {
  check_reference(source, "source");
  check_pose(source, target, "target");
  return source;
}

/// The rest poses E^F's sum runs over: the source, and the target when symmetrised.
std::vector<const Mesh3*> rest_poses(const Mesh3& source, const Mesh3& target, bool symmetric) {
  if (symmetric) return {&source, &target};
  return {&source};
}

/// The set-up's two independent halves: each element's path (decompositions, rotation branches, carrier) and E^F's
/// system (assembly, factorisation), built side by side, the paths on the caller's thread (and the decompositions'
/// own), the factorisation on another. Neither reads what the other writes: the same as one after the other.
struct SetUp3 {
  ElementPaths3 paths;
  PoissonSystem3 system;
};

SetUp3 set_up(const Mesh3& s, const Mesh3& t, const Interpolation3Options& o) {
  std::optional<ElementPaths3> paths;
  std::optional<PoissonSystem3> system;
  global::side_by_side(
      [&] { paths.emplace(element_maps(s, t), o.homotopy, o.rotation_branch, dual_graph3(s.elements)); },
      [&] { system.emplace(rest_poses(s, t, o.symmetric), o.area_weighted, o.constraints, o.back_end); });
  return {std::move(*paths), std::move(*system)};
}

}  // namespace

struct Interpolation3::Engine {
  Interpolation3Options options;
  ElementPaths3 paths;
  std::optional<ElementPaths3> reverse;  ///< symmetrised: the paths from the target, I to A_i⁻¹
  PoissonSystem3 system;
  InterpolationTargets3 targets;  ///< after the system, which refuses bad constraints with its own messages
  std::size_t threads;

  Engine(const Mesh3& s, const Mesh3& t, const Interpolation3Options& o) : Engine(s, t, o, set_up(s, t, o)) {}
  Engine(const Mesh3& s, const Mesh3& t, const Interpolation3Options& o, SetUp3&& built)
      : options(o),
        paths(std::move(built.paths)),
        system(std::move(built.system)),
        targets(options.constraints, s.vertices, t.vertices),
        threads(frame_threads3(options.frame_threads, s)) {
    require_arap_iterations(options.arap_iterations);
    if (options.symmetric) reverse.emplace(element_maps(t, s), options.homotopy, paths);
  }

  void require_time(double t) const {
    if (!std::isfinite(t)) throw std::out_of_range("the time must be finite, not " + std::to_string(t));
  }
  /// The maps of every term of E (E′): A_i(t), then, symmetrised, Ā_i(1 − t).
  std::vector<Eigen::Matrix3d> term_maps(double t, std::size_t threads_) const {
    const auto m = static_cast<std::size_t>(paths.element_count());
    std::vector<Eigen::Matrix3d> A(reverse ? 2 * m : m);
    paths.maps_at(t, std::span(A).first(m), threads_, options.exp);
    if (reverse) reverse->maps_at(1 - t, std::span(A).subspan(m), threads_, options.exp);
    return A;
  }
  Eigen::Matrix3Xd frame(double t, std::size_t threads_, FrameTimings* timings) const;
};

Eigen::Matrix3Xd Interpolation3::Engine::frame(double t, std::size_t threads_, FrameTimings* timings) const {
  return solve_frame(
      system, [&] { return term_maps(t, threads_); }, targets.at(t), options.arap_iterations, threads_, timings);
}

Interpolation3::Interpolation3(const Mesh3& source, const Mesh3& target, Interpolation3Options options)
    : engine_(std::make_unique<Engine>(validated(source, target), target, options)) {}
Interpolation3::~Interpolation3() = default;
Interpolation3::Interpolation3(Interpolation3&&) noexcept = default;
Interpolation3& Interpolation3::operator=(Interpolation3&&) noexcept = default;

Eigen::Matrix3Xd Interpolation3::vertices_at(double t) const {
  engine_->require_time(t);
  return engine_->frame(t, engine_->threads, nullptr);
}

Eigen::Matrix3Xd Interpolation3::vertices_at(double t, FrameTimings& timings) const {
  engine_->require_time(t);
  return engine_->frame(t, engine_->threads, &timings);
}

std::vector<Eigen::Matrix3Xd> Interpolation3::vertices_at(const std::vector<double>& times) const {
  for (double t : times) engine_->require_time(t);
  std::vector<Eigen::Matrix3Xd> frames(times.size());
  global::for_each_range(times.size(), global::ranges_for(times.size(), 1), [&](std::size_t first, std::size_t last) {
    for (std::size_t f = first; f < last; ++f) frames[f] = engine_->frame(times[f], 1, nullptr);
  });
  return frames;
}

std::vector<Eigen::Matrix3d> Interpolation3::local_maps_at(double t) const {
  engine_->require_time(t);
  std::vector<Eigen::Matrix3d> A(static_cast<std::size_t>(engine_->paths.element_count()));
  engine_->paths.maps_at(t, A, engine_->threads, engine_->options.exp);
  return A;
}

ConstraintTargets3 Interpolation3::targets_at(double t) const { return engine_->targets.at(t); }

double Interpolation3::energy_at(double t, const Eigen::Matrix3Xd& v) const {
  if (v.cols() != engine_->system.vertex_count()) throw std::invalid_argument("energy_at: v needs one column a vertex");
  engine_->require_time(t);
  const std::vector<Eigen::Matrix3d> A = engine_->term_maps(t, engine_->threads);
  if (engine_->options.arap_iterations > 0) return arap_energy(engine_->system, A, v, targets_at(t));
  return engine_->system.energy(A, v, targets_at(t));
}

const Eigen::Matrix3Xd& Interpolation3::rotation_logs() const { return engine_->paths.rotation_logs(); }
const RotationSplit3& Interpolation3::rotation_split() const { return engine_->paths.rotation_split(); }
const PoissonSystem3& Interpolation3::system() const { return engine_->system; }
const Interpolation3Options& Interpolation3::options() const { return engine_->options; }

}  // namespace affinterp::global3
