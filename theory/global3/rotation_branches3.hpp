#pragma once
// Rotation consistency in 3D (the counterpart of theory/global/rotation_branch.hpp): each element's rotation
// logarithm ω_i (local3/rotation_branch3.hpp) is defined only up to the branches (θ + 2πk) a, and a local
// homotopy R^t = exp(t[ω_i]×) depends on the branch for every t ∉ ℤ. A mesh that turns by more than π from one end
// to the other (a bar twisted by 3π, a tail turned by 180° against a body turned the other way) needs logarithms
// beyond the principal ones. The consistent choice walks the dual graph breadth-first from element 0 (from the
// first unvisited element of each further piece) and replaces each ω_j by its representative nearest its parent's
// reference: the parent's own logarithm when that was reliable, else the parent's reference.
//
// Why a reference. Unlike the plane's, the 3D exponential is singular on the spheres |ω| = 2πk: near them a small
// tilt of the rotation needs a large change of ω, and an element turned by a full turn about a slightly tilted
// axis (R ≈ I, as in a twisted bar's elements at twist 2π, sheared by the twist) has all its representatives on
// the line of its tilt axis, none near its neighbours' ≈ 2π along the bar. Such an element is given its nearest
// representative (no choice makes its own path right), but its children are compared with its parent's reference,
// so that the walk carries the turn count past it. An element is reliable when its logarithm lies within
// `reliable_step` (1 rad) of its parent's reference: neighbours on a mesh fine enough for its motion differ by far
// less, an element on the singular sphere by about its distance 2π·sin(angle between the axes) from it.
#include <Eigen/Core>

#include <vector>

namespace affinterp::global3 {

/// The elements sharing a facet with each element (an edge between triangles, a face between tetrahedra):
/// those of element i are neighbour[start[i]] … neighbour[start[i + 1] − 1], in increasing order.
struct DualGraph3 {
  std::vector<int> start, neighbour;
};

/// The largest distance (rad) between an element's logarithm and its parent's reference for the element to be
/// the reference of its children.
inline constexpr double reliable_step = 1.0;

/// The dual graph of a well-formed element list (3 or 4 rows).
DualGraph3 dual_graph3(const Eigen::MatrixXi& elements);

/// The principal logarithms `principal` (column i: ω_i, |ω_i| ≤ π) moved to consistent branches as above. The
/// root of each piece takes its representative nearest root_reference's column (none: the principal one), which
/// is how the blend aligns one pose's field with the previous pose's (blend3.hpp).
Eigen::Matrix3Xd consistent_logs(const DualGraph3& graph, const Eigen::Matrix3Xd& principal,
                                 const Eigen::Matrix3Xd* root_reference = nullptr);

}  // namespace affinterp::global3
