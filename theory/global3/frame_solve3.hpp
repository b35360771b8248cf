#pragma once
// One frame of E^F from its local maps, as Interpolation3 and Blend3 make it: the right-hand side Σ_i W_i A_iᵀ
// (poisson_system3.hpp), the solve against the constraints' targets with the factor made once, then the
// as-rigid-as-possible steps when asked for (arap_refinement3.hpp); each part timed for the benchmarks.
#include "theory/global3/frame_timings.hpp"
#include "theory/global3/poisson_system3.hpp"

#include <Eigen/Core>

#include <functional>
#include <vector>

namespace affinterp::global3 {

/// The frame whose terms' local maps `local_maps` gives, solved on `threads` threads; with `timings`, the time of
/// each part.
Eigen::Matrix3Xd solve_frame(const PoissonSystem3& system,
                             const std::function<std::vector<Eigen::Matrix3d>()>& local_maps,
                             const ConstraintTargets3& targets, int arap_iterations, std::size_t threads,
                             FrameTimings* timings);

}  // namespace affinterp::global3
