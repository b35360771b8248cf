#include "theory/global3/blend3.hpp"

#include "theory/global/parallel_ranges.hpp"
#include "theory/global3/arap_refinement3.hpp"
#include "theory/global3/element_maps3.hpp"
#include "theory/global3/frame_solve3.hpp"
#include "theory/global3/frame_threads3.hpp"
#include "theory/global3/local_maps3.hpp"
#include "theory/global3/mesh3_validation.hpp"
#include "theory/global3/rotation_branches3.hpp"
#include "theory/global3/rotation_carrier3.hpp"
#include "theory/local3/local3.hpp"

#include <cmath>
#include <optional>
#include <string>

namespace affinterp::global3 {

using Eigen::Index;
using Eigen::Matrix3d;
using global::RefusedProblem;

namespace {

/// Per pose, what a frame's pass over the poses reads.
struct PoseLogs3 {
  std::vector<Eigen::Matrix3Xd> omega;  ///< per pose: ω_{k,i}
  /// Per pose, column i: the carrier ω̄_{k,i} and remainder η_{k,i} of ω_{k,i}, then log S_{k,i}'s upper triangle
  /// (xx, xy, xz, yy, yz, zz; two thirds of the matrix's bytes): one contiguous record per element and pose for the
  /// frames' pass over every pose.
  std::vector<Eigen::Matrix<double, 12, Eigen::Dynamic>> logs;
  /// The poses whose records are not all zero: the rest pose itself (A_{k,i} = I) adds nothing to a frame's sums.
  std::vector<std::size_t> moving;

  /// Appends the pose whose element maps are `maps`: its rotations' logarithms on consistent branches (across the
  /// poses too: each pose's walk starts from the previous pose's logarithms) and its stretches' logarithms.
  void add(const std::vector<Matrix3d>& maps, const DualGraph3& graph, global::RotationBranch branch);
};

/// The set-up's two independent halves, built side by side: the poses' logarithms on the caller's thread (and the
/// decompositions' own), E^F's system (assembly, factorisation) on another. Neither reads what the other writes: the
/// same as one after the other.
struct BlendSetUp3 {
  PoseLogs3 poses;
  PoissonSystem3 system;
};

BlendSetUp3 set_up(const Mesh3& rest, const std::vector<Mesh3>& poses, const Blend3Options& o) {
  PoseLogs3 logs;
  std::optional<PoissonSystem3> system;
  global::side_by_side(
      [&] {
        const DualGraph3 graph = dual_graph3(rest.elements);
        for (const Mesh3& pose : poses) logs.add(element_maps(rest, pose), graph, o.rotation_branch);
      },
      [&] { system.emplace(rest, o.area_weighted, o.constraints, o.back_end); });
  return {std::move(logs), std::move(*system)};
}

}  // namespace

struct Blend3::Engine {
  Blend3Options options;
  PoseLogs3 poses;
  PoissonSystem3 system;
  BlendTargets3 targets;  ///< after the system, which refuses bad constraints with its own messages
  std::size_t threads;

  Engine(const Mesh3& rest, const std::vector<Mesh3>& poses, const Blend3Options& o)
      : Engine(rest, poses, o, set_up(rest, poses, o)) {}
  Engine(const Mesh3& rest, const std::vector<Mesh3>& poses_, const Blend3Options& o, BlendSetUp3&& built)
      : options(o),
        poses(std::move(built.poses)),
        system(std::move(built.system)),
        targets(options.constraints, poses_),
        threads(frame_threads3(options.frame_threads, rest)) {
    require_arap_iterations(options.arap_iterations);
  }
  void maps_at(const Eigen::VectorXd& w, std::span<Matrix3d> out, std::size_t threads_) const;
  Eigen::Matrix3Xd frame(const Eigen::VectorXd& w, std::size_t threads_, FrameTimings* timings) const;
};

namespace {

const Mesh3& validated(const Mesh3& rest, const std::vector<Mesh3>& poses) {
  if (poses.size() < 2) throw RefusedProblem("a blend needs at least two poses, not " + std::to_string(poses.size()));
  check_reference(rest, "rest");
  for (std::size_t k = 0; k < poses.size(); ++k) check_pose(rest, poses[k], "pose " + std::to_string(k));
  return rest;
}

/// The options, unless their constraints have a time (loci, a barycentre through points), which a blend has not.
Blend3Options without_loci(Blend3Options options) {
  const Constraints3& c = options.constraints;
  if (!c.loci.empty() || (c.barycentre && c.barycentre->points.cols() > 0))
    throw RefusedProblem("a blend's constraints are pins and the barycentre's weighted sum: a locus has no time there");
  return options;
}

void PoseLogs3::add(const std::vector<Matrix3d>& maps, const DualGraph3& graph, global::RotationBranch branch) {
  const Eigen::Matrix3Xd* previous = omega.empty() ? nullptr : &omega.back();
  const auto m = static_cast<Index>(maps.size());
  Eigen::Matrix3Xd principal(3, m);
  Eigen::Matrix<double, 12, Eigen::Dynamic> record(12, m);
  const auto elements = static_cast<std::size_t>(m);
  global::for_each_range(elements, global::ranges_for(elements, decompositions_per_thread),
                         [&](std::size_t first, std::size_t last) {
                           for (auto i = static_cast<Index>(first); i < static_cast<Index>(last); ++i) {
                             const local3::Svd3<double> d = local3::svd3<double>(maps[static_cast<std::size_t>(i)]);
                             principal.col(i) = local3::rotation_log<double>(d.U * d.V.transpose());
                             const Matrix3d L = local3::log_stretch(d);
                             record.col(i).tail<6>() << L(0, 0), L(0, 1), L(0, 2), L(1, 1), L(1, 2), L(2, 2);
                           }
                         });
  const bool consistent = branch == global::RotationBranch::consistent;
  ConsistentLogs branched =
      consistent ? consistent_logs(graph, principal, previous) : ConsistentLogs{principal, principal};
  const RotationSplit3 split = consistent ? split_rotations(graph, branched) : unsplit_rotations(branched.omega);
  omega.push_back(std::move(branched.omega));
  record.topRows<3>() = split.carrier;
  record.middleRows<3>(3) = split.remainder;
  if (!record.isZero(0)) moving.push_back(logs.size());
  logs.push_back(std::move(record));
}

}  // namespace

void Blend3::Engine::maps_at(const Eigen::VectorXd& w, std::span<Matrix3d> out, std::size_t threads_) const {
  exp_log_maps(
      [&](Index first, Index last, std::span<Eigen::Vector3d> Omega, std::span<Eigen::Vector3d> Eta,
          std::span<Matrix3d> Lambda) {
        for (Index i = first; i < last; ++i) {
          Eigen::Matrix<double, 12, 1> x = Eigen::Matrix<double, 12, 1>::Zero();  // summed in registers
          for (const std::size_t k : poses.moving) x += w[static_cast<Index>(k)] * poses.logs[k].col(i);
          Omega[static_cast<std::size_t>(i - first)] = x.head<3>();
          Eta[static_cast<std::size_t>(i - first)] = x.segment<3>(3);
          const auto Lambda_i = x.tail<6>();
          Lambda[static_cast<std::size_t>(i - first)] << Lambda_i[0], Lambda_i[1], Lambda_i[2],  //
              Lambda_i[1], Lambda_i[3], Lambda_i[4],                                             //
              Lambda_i[2], Lambda_i[4], Lambda_i[5];
        }
      },
      out, threads_);
}

Eigen::Matrix3Xd Blend3::Engine::frame(const Eigen::VectorXd& w, std::size_t threads_, FrameTimings* timings) const {
  const auto maps = [&] {
    std::vector<Matrix3d> A(static_cast<std::size_t>(poses.logs.front().cols()));
    maps_at(w, A, threads_);
    return A;
  };
  return solve_frame(system, maps, targets.at(w), options.arap_iterations, threads_, timings);
}

Blend3::Blend3(const std::vector<Mesh3>& poses, Blend3Options options)
    : Blend3(poses.empty() ? Mesh3{} : poses.front(), poses, std::move(options)) {}
Blend3::Blend3(const Mesh3& rest, const std::vector<Mesh3>& poses, Blend3Options options)
    : engine_(std::make_unique<Engine>(validated(rest, poses), poses, without_loci(std::move(options)))) {}
Blend3::~Blend3() = default;
Blend3::Blend3(Blend3&&) noexcept = default;
Blend3& Blend3::operator=(Blend3&&) noexcept = default;

void Blend3::require_valid_weights(const Eigen::VectorXd& w) const {
  if (w.size() != pose_count())
    throw RefusedProblem("the blend needs " + std::to_string(pose_count()) + " weights, one a pose, not " +
                         std::to_string(w.size()));
  if (!w.allFinite()) throw RefusedProblem("the blend weights must be finite");
  if (!engine_->options.allow_extrapolation && ((w.array() < 0).any() || std::abs(w.sum() - 1) > 1e-9))
    throw RefusedProblem("the blend weights must be non-negative and sum to 1 (or allow extrapolation)");
}

Eigen::Matrix3Xd Blend3::vertices_at(const Eigen::VectorXd& w) const {
  require_valid_weights(w);
  return engine_->frame(w, engine_->threads, nullptr);
}

Eigen::Matrix3Xd Blend3::vertices_at(const Eigen::VectorXd& w, FrameTimings& timings) const {
  require_valid_weights(w);
  return engine_->frame(w, engine_->threads, &timings);
}

std::vector<Eigen::Matrix3Xd> Blend3::vertices_at(const std::vector<Eigen::VectorXd>& weights) const {
  for (const Eigen::VectorXd& w : weights) require_valid_weights(w);
  std::vector<Eigen::Matrix3Xd> frames(weights.size());
  global::for_each_range(weights.size(), global::ranges_for(weights.size(), 1),
                         [&](std::size_t first, std::size_t last) {
                           for (std::size_t f = first; f < last; ++f)
                             frames[f] = engine_->frame(weights[f], 1, nullptr);
                         });
  return frames;
}

std::vector<Matrix3d> Blend3::local_maps_at(const Eigen::VectorXd& w) const {
  require_valid_weights(w);
  std::vector<Matrix3d> A(static_cast<std::size_t>(engine_->poses.logs.front().cols()));
  engine_->maps_at(w, A, engine_->threads);
  return A;
}

Index Blend3::pose_count() const { return static_cast<Index>(engine_->poses.omega.size()); }
const Eigen::Matrix3Xd& Blend3::rotation_logs(Index k) const {
  return engine_->poses.omega.at(static_cast<std::size_t>(k));
}
const PoissonSystem3& Blend3::system() const { return engine_->system; }
const Blend3Options& Blend3::options() const { return engine_->options; }

}  // namespace affinterp::global3
