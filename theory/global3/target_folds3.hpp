#pragma once
// Triangles a surface's target pose folds within the surface. A triangle in space has no orientation of its own, so
// element_maps3.hpp's map A_i (the scaled normal as third column, Sumner and Popović 2004) always has det A_i > 0:
// a triangle that the target turns over across its neighbours, which in the plane would be a flipped target
// triangle (det < 0, refused there), becomes a half-turn about an axis in the surface, and the exp-log path
// R_i^t S_i^t stands it up out of the surface half-way while the vertices it shares cannot follow. Such folds are
// in the input, not made by the interpolation: frames near them may invert whatever the homotopy or rotation
// branches.
//
// Triangle i is folded in the target when its target normal opposes the source normal carried by the motion of
// its neighbourhood: n_q · (R n_p) ≤ 0, with R the rotation that best maps the source's vertices of the triangle's
// vertex one-ring (every vertex of a triangle sharing a corner with it) onto the target's, in the least-squares
// sense (Kabsch: R = V diag(1, 1, ±1) Uᵀ from the SVD U Σ Vᵀ of the centred cross-covariance).
#include "theory/global3/mesh3.hpp"

#include <Eigen/Core>

#include <vector>

namespace affinterp::global3 {

/// The triangles of `source` (a surface) that `target` (its pose: same elements) folds, as above, increasing;
/// none for tetrahedra, whose inversion is det ≤ 0 and refused by mesh3_validation.hpp.
std::vector<Eigen::Index> target_folds(const Mesh3& source, const Mesh3& target);

/// For a blend: per pose k, the triangles it folds against the first, target_folds(poses[0], poses[k]) (none for
/// k = 0).
std::vector<std::vector<Eigen::Index>> pose_folds(const std::vector<Mesh3>& poses);

/// near_folds of every pose's folds together, on the first pose; empty when no pose folds any triangle.
std::vector<unsigned char> near_pose_folds(const std::vector<Mesh3>& poses,
                                           const std::vector<std::vector<Eigen::Index>>& folds);

/// Per element, whether it is one of `folds` or shares a vertex with one: the elements whose vertices a fold's own
/// term pulls directly (frame_metrics3.hpp counts inversions there apart).
std::vector<unsigned char> near_folds(const Mesh3& mesh, const std::vector<Eigen::Index>& folds);

}  // namespace affinterp::global3
