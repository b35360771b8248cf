#pragma once
// Work over the triangles or vertices of a large mesh split into contiguous ranges, one thread each: the
// engine's per-frame loops whose items write disjoint outputs, so that the result is the same whatever the
// number of threads.
#include <cstddef>
#include <functional>

namespace affinterp::global {

/// Calls body(first, last) on the `ranges` contiguous ranges of [0, count), each on a thread of its own
/// (the first on the caller's), and returns when all are done; rethrows the first exception.
void for_each_range(std::size_t count, std::size_t ranges, const std::function<void(std::size_t, std::size_t)>& body);

/// The ranges worth a thread each for `count` items of similar cost: one per hardware thread, each of at least
/// `grain` items (so that small meshes stay on the caller's thread).
std::size_t ranges_for(std::size_t count, std::size_t grain);

/// Triangles per thread below which the set-up's and a frame's loops over triangles stay on one thread.
inline constexpr std::size_t triangles_per_thread = 1 << 15;

/// The threads worth one frame for `unknowns` vertices, up to the hardware's. A frame that factorises H(t) takes one
/// per 4096 unknowns: from there the factor's two groups of subtrees (simplicial_factor.hpp) cost far more than
/// starting a thread. A frame with H factored once (E^F: a right-hand side and a solve) takes one per 16384: a
/// solve is so much cheaper that at 8192 unknowns a second thread gains nothing.
inline std::size_t frame_threads(std::size_t unknowns, bool factorised_per_frame) {
  return ranges_for(unknowns, factorised_per_frame ? 1 << 12 : 1 << 14);
}

/// Runs `there` on a thread of its own while `here` runs on the caller's, and returns when both are done;
/// rethrows the first exception (here's first).
void side_by_side(const std::function<void()>& here, const std::function<void()>& there);

}  // namespace affinterp::global
