#include "theory/global3/interpolation3.hpp"

#include "theory/global/parallel_ranges.hpp"
#include "theory/global3/element_maps3.hpp"
#include "theory/global3/element_paths3.hpp"
#include "theory/global3/frame_threads3.hpp"
#include "theory/global3/mesh3_validation.hpp"

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

namespace affinterp::global3 {

struct Interpolation3::Engine {
  Interpolation3Options options;
  Eigen::Matrix3Xd source, target;
  ElementPaths3 paths;
  PoissonSystem3 system;
  std::size_t threads;

  Engine(const Mesh3& s, const Mesh3& t, Interpolation3Options o)
      : options(std::move(o)),
        source(s.vertices),
        target(t.vertices),
        paths(element_maps(s, t), options.homotopy, options.rotation_branch, dual_graph3(s.elements)),
        system(s, options.area_weighted, options.constraints, options.back_end),
        threads(frame_threads3(options.frame_threads, s)) {}

  void require_time(double t) const {
    if (!std::isfinite(t)) throw std::out_of_range("the time must be finite, not " + std::to_string(t));
  }
  Eigen::Matrix3Xd frame(double t, std::size_t threads_, FrameTimings* timings) const;
};

namespace {

/// Validates before the engine's members decompose anything.
const Mesh3& validated(const Mesh3& source, const Mesh3& target) {
  check_reference(source, "source");
  check_pose(source, target, "target");
  return source;
}

}  // namespace

Eigen::Matrix3Xd Interpolation3::Engine::frame(double t, std::size_t threads_, FrameTimings* timings) const {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  std::vector<Eigen::Matrix3d> A(static_cast<std::size_t>(paths.element_count()));
  paths.maps_at(t, A, threads_, options.exp);
  const auto mapped = Clock::now();
  PoissonSystem3::Block b = system.right_hand_side(A, threads_);
  const auto assembled = Clock::now();
  Eigen::Matrix3Xd v = system.solve(
      std::move(b), weighted_targets(options.constraints, {&source, &target}, Eigen::Vector2d(1 - t, t)), threads_);
  if (timings) {
    const auto seconds = [](auto from, auto to) { return std::chrono::duration<double>(to - from).count(); };
    *timings = {seconds(start, mapped), seconds(mapped, assembled), seconds(assembled, Clock::now())};
  }
  return v;
}

Interpolation3::Interpolation3(const Mesh3& source, const Mesh3& target, Interpolation3Options options)
    : engine_(std::make_unique<Engine>(validated(source, target), target, std::move(options))) {}
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

ConstraintTargets3 Interpolation3::targets_at(double t) const {
  return weighted_targets(engine_->options.constraints, {&engine_->source, &engine_->target},
                          Eigen::Vector2d(1 - t, t));
}

double Interpolation3::energy_at(double t, const Eigen::Matrix3Xd& v) const {
  if (v.cols() != engine_->system.vertex_count()) throw std::invalid_argument("energy_at: v needs one column a vertex");
  return engine_->system.energy(local_maps_at(t), v, targets_at(t));
}

const Eigen::Matrix3Xd& Interpolation3::rotation_logs() const { return engine_->paths.rotation_logs(); }
const PoissonSystem3& Interpolation3::system() const { return engine_->system; }
const Interpolation3Options& Interpolation3::options() const { return engine_->options; }

}  // namespace affinterp::global3
