#pragma once
// The global interpolation of the two triangles (thesis §2.1 step 3, Fig. 2.7) when each triangle's local
// interpolation is taken about its own origin o_i: the frames differ with the origins (thesis §2.3).
#include "theory/origin/two_triangles.hpp"

#include <Eigen/Core>

#include <array>

namespace affinterp::origin {

/// The local interpolation of the 3×3 affine map A about the origin o, in world coordinates: in the
/// frame with origin o, A = [[L, τ], [0, 1]] becomes [[A^E(t), t τ], [0, 1]] with A^E(t) = R_{tθ} S^t
/// (Kaji eq. (3), thesis §2.1), L = R_θ S the polar decomposition, θ ∈ (−π, π]. Requires det L > 0.
Eigen::Matrix3d local_interpolation(const Eigen::Matrix3d& A, const Eigen::Vector2d& o, double t);

/// The intermediate vertices v_1 … v_4 (columns) at time t: the minimiser of
/// E2(A1(t), A2(t), B1, B2, o1, o2), A_i(t) the local interpolation of A_i about o_i.
Eigen::Matrix<double, 2, 4> global_interpolation(const TwoTriangles& config,
                                                 const std::array<Eigen::Vector2d, 2>& origins, double t);

}  // namespace affinterp::origin
