#include "theory/global3/arap_refinement3.hpp"

#include "theory/global/parallel_ranges.hpp"
#include "theory/global/refused_problem.hpp"
#include "theory/local3/nearest_rotation3.hpp"

#include <string>

namespace affinterp::global3 {

void require_arap_iterations(int iterations) {
  if (iterations < 0 || iterations > max_arap_iterations)
    throw global::RefusedProblem("arap_iterations must be in 0.." + std::to_string(max_arap_iterations) + ", not " +
                                 std::to_string(iterations));
}

std::vector<Eigen::Matrix3d> rotated_maps(const PoissonSystem3& system, std::span<const Eigen::Matrix3d> A,
                                          const Eigen::Matrix3Xd& v, std::size_t threads) {
  std::vector<Eigen::Matrix3d> RA = system.gradients(v, threads);
  const bool in_plane = system.corners() == 3;  // B_s A_sᵀ of rank 2: no SVD needed
  global::for_each_range(RA.size(), threads, [&](std::size_t first, std::size_t last) {
    for (std::size_t s = first; s < last; ++s) {
      const Eigen::Matrix3d M = RA[s] * A[s].transpose();
      RA[s] = (in_plane ? local3::nearest_rotation_of_rank_two<double>(M) : local3::nearest_rotation<double>(M)) * A[s];
    }
  });
  return RA;
}

Eigen::Matrix3Xd arap_refined(const PoissonSystem3& system, std::span<const Eigen::Matrix3d> A,
                              const ConstraintTargets3& targets, Eigen::Matrix3Xd v, int iterations,
                              std::size_t threads) {
  for (int k = 0; k < iterations; ++k)
    v = system.solve(system.right_hand_side(rotated_maps(system, A, v, threads), threads), targets, threads);
  return v;
}

double arap_energy(const PoissonSystem3& system, std::span<const Eigen::Matrix3d> A, const Eigen::Matrix3Xd& v,
                   const ConstraintTargets3& targets) {
  return system.energy(rotated_maps(system, A, v, 1), v, targets);
}

}  // namespace affinterp::global3
