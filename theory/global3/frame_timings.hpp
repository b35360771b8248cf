#pragma once
// A frame's time split into its parts, for benchmarks: how much of a frame the local maps take (the thesis's
// exponential among them), against the right-hand side and the sparse solve, and the refinement's iterations.
namespace affinterp::global3 {

struct FrameTimings {
  double local_maps = 0;       ///< seconds: every A_i(t) (exp-log and blends: sym3::exp_batched's pass included)
  double right_hand_side = 0;  ///< seconds: Σ_i W_i A_iᵀ per vertex
  double solve = 0;            ///< seconds: the triangular solves and the constraints' corrections
  double refinement = 0;       ///< seconds: the as-rigid-as-possible iterations, if any (arap_refinement3.hpp)
};

}  // namespace affinterp::global3
