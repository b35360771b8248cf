#pragma once
// The threads one 3D frame uses: the caller's choice, else by the mesh's size as the 2D engine chooses
// (global::frame_threads for the solve, global::triangles_per_thread for the per-element loops).
#include "theory/global/parallel_ranges.hpp"
#include "theory/global3/mesh3.hpp"

#include <algorithm>

namespace affinterp::global3 {

inline std::size_t frame_threads3(std::size_t requested, const Mesh3& mesh) {
  if (requested > 0) return requested;
  return std::max(global::frame_threads(static_cast<std::size_t>(mesh.vertex_count()), false),
                  global::ranges_for(static_cast<std::size_t>(mesh.element_count()), global::triangles_per_thread));
}

}  // namespace affinterp::global3
