#pragma once
// The threads the 3D engine's loops use: a frame's, the caller's choice or by the mesh's size as the 2D engine
// chooses (global::frame_threads for the solve, global::triangles_per_thread for the per-element loops); the
// set-up's per-element decompositions by their own grain.
#include "theory/global/parallel_ranges.hpp"
#include "theory/global3/mesh3.hpp"

#include <algorithm>

namespace affinterp::global3 {

/// Elements per thread below which the set-up's decompositions (a Jacobi SVD and three logarithms each) stay on one
/// thread.
inline constexpr std::size_t decompositions_per_thread = 1 << 13;

inline std::size_t frame_threads3(std::size_t requested, const Mesh3& mesh) {
  if (requested > 0) return requested;
  return std::max(global::frame_threads(static_cast<std::size_t>(mesh.vertex_count()), false),
                  global::ranges_for(static_cast<std::size_t>(mesh.element_count()), global::triangles_per_thread));
}

}  // namespace affinterp::global3
