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
// The carrier, in two steps:
//  1. Fill. The walk's seeds s_i (rotation_branches3.hpp) are as good as the exponential makes them. Across its axis
//     exp moves by the gain σ(θ) = |sin(θ/2)|/(θ/2) (θ = |ω|), which falls from 2/π at a half turn to 0 on the
//     singular sphere θ = 2π: there a seed's direction is the shear's tilt, not the element's turn, and beyond
//     it the tilt comes amplified by 1/σ across the axis (3 to 4 rad at θ ≈ 3.6π on a bar twisted by 5π). Each
//     seed is held with the fidelity ρ_i = w/(1 − w), w = (σ(θ_i)/σ(π))⁴ (infinite up to a half turn, 0 on the
//     sphere), so that its pull ρ_i |f_i − s_i| on the carrier vanishes as σ³. (With the square, the inverse of
//     the error's variance, the pulls left the 5π bar's carrier 0.06 rad off its axis where it neared 4π, and its
//     sections there 0.1 rad wrong at t = 1/4 and 3/4: 1.2 widths off in 120 boxes. The power was chosen on the
//     twisted bars, 2, 4 and 8 tried; the cat poses measured after it moved by one triangle at most.) The carrier's
//     starting field f minimises
//         Σ_i ρ_i |f_i − s_i|² + Σ_{i ~ j} |f_j − f_i − d_ij|²,     d_ij = log(R_j R_iᵀ),
//     over the neighbours i ~ j (elements sharing a facet) whose relative turn d_ij is small (|d_ij| ≤ 1 rad; it is
//     well determined at any θ, and where the rotations share an axis it is exactly ω_j − ω_i): one sparse solve
//     over the elements beyond a half turn, the others held at their seeds. The seeds near a full turn are
//     replaced by their reliable neighbours' seeds carried along the relative turns, however many rings the band
//     is wide. No element beyond a half turn, nothing to solve: f = s. Its cost is one sparse factorisation over
//     those elements (on a mesh twisted by 3π, most of them).
//  2. Smooth. `carrier_steps` steps of ω̄_i ← ½ ω̄_i + ½ (the mean of ω̄ over the elements sharing a facet with i),
//     from f: a diffusion over a few rings of neighbours, each element's value from the previous step only, so the
//     same bits on any number of threads.
// The fill, with the walk's prediction, is what holds finely cut bars and turns beyond 2π: with the smoothing alone,
// the 3π bar in 120 or 240 boxes has more elements at its full turn than 16 steps reach, and its frames there were
// off by 0.77 and 1.47 widths on an AVX-512 build and 0.28 and 0.91 on the x86-64 baseline (the branch near-ties at
// the full turn fell differently in the last bits); with both, the two builds hold it within a quarter of the width
// (checks/global3/interpolation3_test.cpp). Bars twisted by 1.5π to 5π, in 30 or 120 boxes, stay within 0.32
// widths at t = 1/4, 1/2 and 3/4.
#include "theory/global3/rotation_branches3.hpp"

#include <Eigen/Core>

namespace affinterp::global3 {

/// Smoothing steps of the carrier, chosen on the 3π bar before any other mesh was measured (and before the fill).
/// Measured there with ω itself as the seeds: 3 steps left the full turn 0.95 width off; 10, 16 and 30 steps gave
/// 0.21, 0.19 and 0.18.
inline constexpr int carrier_steps = 16;

/// The fill's bounds on ρ_i: below max_seed_fidelity the seed is an unknown (above it the fill would move it by
/// less than a thousandth of its neighbours' pull, and it is held), and ρ_i is at least min_seed_fidelity, on the
/// singular sphere too (so that the fill's system is strictly diagonally dominant, even on a piece all of whose
/// elements turn by more than a half turn).
inline constexpr double max_seed_fidelity = 1e3, min_seed_fidelity = 1e-6;

/// The fidelity ρ of a seed turning by `angle` = |s_i| (step 1 above).
double seed_fidelity(double angle);

/// The fill of step 1: the seeds of `logs` with their elements beyond a half turn replaced by the minimiser above
/// (the relative turns from the rotations exp [ω_i]×).
Eigen::Matrix3Xd filled_seeds(const DualGraph3& graph, const ConsistentLogs& logs);

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
