#include "theory/global3/frame_solve3.hpp"

#include "theory/global3/arap_refinement3.hpp"

#include <chrono>

namespace affinterp::global3 {

Eigen::Matrix3Xd solve_frame(const PoissonSystem3& system,
                             const std::function<std::vector<Eigen::Matrix3d>()>& local_maps,
                             const ConstraintTargets3& targets, int arap_iterations, std::size_t threads,
                             FrameTimings* timings) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  const std::vector<Eigen::Matrix3d> A = local_maps();
  const auto mapped = Clock::now();
  PoissonSystem3::Block b = system.right_hand_side(A, threads);
  const auto assembled = Clock::now();
  Eigen::Matrix3Xd v = system.solve(std::move(b), targets, threads);
  const auto solved = Clock::now();
  v = arap_refined(system, A, targets, std::move(v), arap_iterations, threads);
  if (timings) {
    const auto seconds = [](auto from, auto to) { return std::chrono::duration<double>(to - from).count(); };
    *timings = {seconds(start, mapped), seconds(mapped, assembled), seconds(assembled, solved),
                seconds(solved, Clock::now())};
  }
  return v;
}

}  // namespace affinterp::global3
