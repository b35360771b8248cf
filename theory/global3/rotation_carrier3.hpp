#pragma once
// Rotation paths through full turns: each element's rotation R_i = exp [ω_i]× (ω_i on a consistent branch,
// rotation_branches3.hpp) is reached along
//     R_i(t) = exp(t [ω̄_i]×) exp(t [η_i]×),
// the carrier ω̄_i, the logarithms smoothed over the dual graph, then the element's remainder η_i, the principal
// logarithm of exp(−[ω̄_i]×) R_i (the smallest turn left, |η_i| ≤ π), so that exp [ω̄_i]× exp [η_i]× = R_i: I at
// t = 0, R_i at t = 1, a rotation throughout. When the rotations share one axis (a mesh in a plane turning in it)
// the remainder is ω_i − ω̄_i wherever that is less than π and the path is exp(t [ω_i]×), the plane's consistent
// branch (theory/global/rotation_branch.hpp). The remainder is not taken nearest ω_i − ω̄_i: an element whose own
// logarithm lies across a bar at its full turn (below) would get back the whole turn its carrier gives it.
//
// Why not exp(t [ω_i]×) itself: the exponential is singular on the spheres |ω| = 2πk, where a small difference of
// two rotations is a large difference of their logarithms. In a bar twisted by 3π, neighbours at twist ≈ 2π whose
// rotations differ by 0.03 rad have consistent logarithms 1 rad apart across the bar, and an element whose own twist
// is within the shear's tilt of 2π has every logarithm across the bar (R_i ≈ a small tilt): each path exp(t [ω_i]×)
// then turns about its own axis, and the full-turn section of the frames is about one width off the exact twist.
// The smoothed carrier turns those elements with their neighbours, about the bar, and leaves them only their small
// remainder (sequel.3d.twisted-bar measures both paths).
//
// Smoothing: `carrier_steps` steps of ω̄_i ← ½ ω̄_i + ½ (the mean of ω̄ over the elements sharing a facet with i),
// from the consistent walk's seeds (rotation_branches3.hpp: ω_i, but its parent's reference where ω_i is more than
// π from it, as at the bar's full turn, whose elements would otherwise pull their neighbours' carriers towards their
// own logarithms across the bar): a diffusion over a few rings of neighbours, each element's value from the previous
// step only, so the same bits on any number of threads.
#include "theory/global3/rotation_branches3.hpp"

#include <Eigen/Core>

namespace affinterp::global3 {

/// Smoothing steps of the carrier, chosen on the 3π bar before any other mesh was measured. Measured there with ω
/// itself as the seeds: 3 steps left the full turn 0.95 width off; 10, 16 and 30 steps gave 0.21, 0.19 and 0.18.
/// The steps count rings, not distance: the same bar cut into 120 or 240 boxes holds more elements at its full turn
/// than 16 steps reach, and its frames there are not held (checks/global3/interpolation3_test.cpp).
inline constexpr int carrier_steps = 16;

/// Each element's rotation logarithm ω_i split as above.
struct RotationSplit3 {
  Eigen::Matrix3Xd carrier;    ///< ω̄_i, column i
  Eigen::Matrix3Xd remainder;  ///< η_i, column i
};

/// The split of the consistent logarithms `logs` over the dual graph `graph`.
RotationSplit3 split_rotations(const DualGraph3& graph, const ConsistentLogs& logs);

/// The split of the logarithms `omega` along a given carrier (the symmetrised energy's reverse paths take the
/// forward carrier negated).
RotationSplit3 split_along(Eigen::Matrix3Xd carrier, const Eigen::Matrix3Xd& omega);

/// The split with no carrier: each path exp(t [ω_i]×) as it is (the principal branch).
RotationSplit3 unsplit_rotations(const Eigen::Matrix3Xd& omega);

}  // namespace affinterp::global3
