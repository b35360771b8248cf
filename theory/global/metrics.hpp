#pragma once
// Per-frame quality of a global interpolation (Kaji §4): the frame's vertices v_k(t) define, on each
// triangle τ_i, the linear part B_i(t) of the affine map from the source triangle (Kaji eq. (1)). The
// metrics summarise det B_i (flips, area change) and its singular values (distortion).
#include "theory/global/mesh.hpp"

namespace affinterp::global {

/// B_i: the linear part of the affine map taking source triangle i onto the same triangle with the
/// corners `frame` (Kaji eq. (1)); columns of `frame` are vertices in the source's order.
Eigen::Matrix2d triangle_linear_map(const Mesh& source, const Eigen::Matrix2Xd& frame, Eigen::Index i);

struct FrameMetrics {
  Eigen::Index flipped_triangles = 0;  ///< triangles with det B_i ≤ 0
  double min_det = 0;                  ///< min_i det B_i (the smallest per-triangle area ratio)
  double max_det = 0;                  ///< max_i det B_i (the largest per-triangle area ratio)
  double max_distortion = 0;           ///< max_i σ1(B_i)/σ2(B_i); +∞ when some B_i is singular
  double mean_distortion = 0;          ///< the plain mean over triangles of σ1/σ2
  double area_ratio = 0;               ///< total signed area of the frame / total area of the source
};

/// The metrics of one frame against the source (oriented counter-clockwise).
FrameMetrics frame_metrics(const Mesh& source, const Eigen::Matrix2Xd& frame);

}  // namespace affinterp::global
