#pragma once
// Per-frame quality of a 3D interpolation or blend, the counterpart of theory/global/metrics.hpp: each element's
// map B_i from the source (rest) element to the frame's (tetrahedra: [x1−x0 x2−x0 x3−x0][p1−p0 p2−p0 p3−p0]⁻¹;
// triangles: the in-plane map X_i E_i⁺ of poisson_system3.hpp) and the frame's element measures.
//
// Inversion. A tetrahedron is inverted when det B_i ≤ 0. A triangle in space has no sign of its own: it is
// inverted when its normal n_x = (x1−x0) × (x2−x0) points away from the normal its local map expects,
// n_x · (A_i n_p) ≤ 0 with n_p the source normal and A_i the element's local map A_i(t) (or A_i(w)); without
// local maps, A_i = I (n_x · n_p ≤ 0: meaningful only for frames that turn no element by more than 90°). The
// signed measure ratio is det B_i for a tetrahedron and |n_x|/|n_p| with that sign for a triangle.
#include "theory/global3/mesh3.hpp"

#include <Eigen/Core>

#include <span>
#include <vector>

namespace affinterp::global3 {

struct FrameMetrics3 {
  Eigen::Index inverted_elements = 0;  ///< elements with a signed measure ratio ≤ 0
  std::vector<Eigen::Index> inverted;  ///< which: the inverted_elements elements, increasing
  /// Of those, the ones the `near` mask marks (target_folds3.hpp: at or beside a triangle the target folds).
  Eigen::Index inverted_near_folds = 0;
  double min_ratio = 0;  ///< min_i of the signed area or volume ratio
  double max_ratio = 0;  ///< max_i of it
  double max_distortion = 0;  ///< max_i σ1/σ3 of B_i (σ1/σ2 of a triangle's in-plane map); +∞ when some B_i is singular
  double mean_distortion = 0;  ///< the plain mean over elements of the same
  double measure_ratio = 0;    ///< the frame's total area (surfaces: unsigned) or signed volume / the source's
};

/// The metrics of the frame (3 × n) against the source; `local_maps` and `near` each empty or one per element.
FrameMetrics3 frame_metrics3(const Mesh3& source, const Eigen::Matrix3Xd& frame,
                             std::span<const Eigen::Matrix3d> local_maps = {},
                             std::span<const unsigned char> near = {});

}  // namespace affinterp::global3
