#pragma once
// Rotation consistency in 3D (the counterpart of theory/global/rotation_branch.hpp): each element's rotation
// logarithm ω_i (local3/rotation_branch3.hpp) is defined only up to the branches (θ + 2πk) a, and a local
// homotopy R^t = exp(t[ω_i]×) depends on the branch for every t ∉ ℤ. A mesh that turns by more than π from one end
// to the other (a bar twisted by 3π, a tail turned by 180° against a body turned the other way) needs logarithms
// beyond the principal ones. The consistent choice walks the dual graph from element 0 (from the first unvisited
// element of each further piece) and gives each element its representative nearest its parent's reference.
//
// Order: the walk is quality-guided, as in phase unwrapping (Ghiglia and Pritt, "Two-Dimensional Phase
// Unwrapping", Wiley 1998, §4.3): of all unvisited neighbours of visited elements, the next one visited is the one
// whose nearest representative lies nearest its parent's reference (Prim's order on those distances). Smooth regions
// are unwrapped first and the walk crosses creases and badly determined elements last, so that their choices are
// passed on to as few elements as possible. (The 2D engine's breadth-first order is enough in the plane, where
// angles are scalars and a choice is never ambiguous; on the cat poses the breadth-first walk gave up to 474
// triangles folded against their local maps in mid-frames, this order 18.)
//
// Reference: the element's own logarithm when it lies within `reliable_step` (1 rad) of its parent's reference.
// Unlike the plane's, the 3D exponential is singular on the spheres |ω| = 2πk: near them a small tilt of the
// rotation needs a large change of ω, and an element turned by a full turn about a slightly tilted axis (R ≈ I, as
// in a twisted bar's elements at twist 2π, sheared by the twist) has all its representatives on the line of its tilt
// axis, none near its neighbours' ≈ 2π along the bar. Its turn relative to its parent, d = log(R_child R_parentᵀ),
// is still small and well determined. So, when no representative lies within 1 rad of the parent's reference r, the
// element is compared instead with the prediction r + d (when |d| ≤ 1 rad; a larger d is a crease or a fold, and
// the prediction stays r): it gets the representative nearest that, and if that one too is more than 1 rad off, its
// children get the prediction as their reference, so that the walk carries the turn count past it, however wide
// the band of such elements (no choice makes such an element's own path right: rotation_carrier3.hpp turns it with
// its neighbours). Neighbours on a mesh fine enough for its motion differ by far less than 1 rad; an element on the
// singular sphere by about 2π·sin(the angle between the axes).
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

/// d = log(exp [ω_j]× exp [−ω_i]×) = log(R_j R_iᵀ), the turn from element i's rotation to element j's (principal,
/// |d| ≤ π): small and well determined between neighbours at any |ω|, where ω_j − ω_i is not.
Eigen::Vector3d relative_turn(const Eigen::Vector3d& omega_i, const Eigen::Vector3d& omega_j);

/// The dual graph of a well-formed element list (3 or 4 rows).
DualGraph3 dual_graph3(const Eigen::MatrixXi& elements);

/// Each element's logarithm on its consistent branch, and the field the rotation paths' carrier smooths
/// (rotation_carrier3.hpp).
struct ConsistentLogs {
  Eigen::Matrix3Xd omega;  ///< ω_i, column i
  /// ω_i where it lies within π of its parent's reference (or the prediction above), else that reference or
  /// prediction: without the elements none of whose logarithms is near their neighbours' (at a twisted bar's full
  /// turn, every logarithm across the bar).
  Eigen::Matrix3Xd seed;
};

/// The principal logarithms `principal` (column i: ω_i, |ω_i| ≤ π) moved to consistent branches as above. The
/// root of each piece takes its representative nearest root_reference's column (none: the principal one), which
/// is how the blend aligns one pose's field with the previous pose's (blend3.hpp).
ConsistentLogs consistent_logs(const DualGraph3& graph, const Eigen::Matrix3Xd& principal,
                               const Eigen::Matrix3Xd* root_reference = nullptr);

}  // namespace affinterp::global3
