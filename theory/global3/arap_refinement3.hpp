#pragma once
// As-rigid-as-possible refinement of a frame, the nearest sound 3D counterpart of Kaji's E^R (interpolation3.hpp
// says why E^R's closed form stays in the plane). With the frame's local maps A_s fixed, it lowers
//     E^ARAP(v) = Σ_s w_s min_{R_s ∈ SO(3)} ‖(X_s − R_s A_s E_s) E_s⁺‖²_F + C(v),
// E^F of poisson_system3.hpp with each element free to turn its map: Kaji's E^R (eq. (4)) with the scale held at
// 1, since a free scale would let the whole frame shrink towards the constraints. As R_s A_s = (R_s R_s(t)) S_s(t),
// only the local maps' stretches count: each element keeps its shape and its rotation follows the constraints and
// its neighbours.
//
// Local/global iteration (Sorkine and Alexa 2007, with the blended stretches as targets as in Kaji et al.'s
// N-way blender): with P_s = E_s E_s⁺ the term is ‖B_s − R_s A_s P_s‖² for B_s = X_s E_s⁺ (B_s P_s = B_s), whose
// only R_s-dependent part is −2 tr(R_sᵀ B_s A_sᵀ): the local step takes R_s = the rotation nearest to B_s A_sᵀ
// (local3/nearest_rotation3.hpp: in closed form for a triangle, whose B_s A_sᵀ has rank 2; by an SVD for a
// tetrahedron), the global step E^F's solve against R_s A_s with the factor already there. Each step minimises
// E^ARAP over its own variables with the others fixed, so E^ARAP never increases. Started from the E^F frame
// (R_s = I). One iteration costs a frame's right-hand side and solve plus the rotations (bench_3d's 3d/arap-step).
#include "theory/global3/constraints3.hpp"
#include "theory/global3/poisson_system3.hpp"

#include <Eigen/Core>

#include <span>
#include <vector>

namespace affinterp::global3 {

/// At most this many iterations a frame: beyond, a request is more likely a slip than a wish to wait.
inline constexpr int max_arap_iterations = 1000;

/// Throws global::RefusedProblem unless 0 ≤ iterations ≤ max_arap_iterations.
void require_arap_iterations(int iterations);

/// The local step: R_s A_s for every term s, R_s the rotation nearest to B_s(v) A_sᵀ. The same bits on any
/// number of threads.
std::vector<Eigen::Matrix3d> rotated_maps(const PoissonSystem3& system, std::span<const Eigen::Matrix3d> A,
                                          const Eigen::Matrix3Xd& v, std::size_t threads);

/// `iterations` local and global steps from the frame v (iterations = 0: v itself).
Eigen::Matrix3Xd arap_refined(const PoissonSystem3& system, std::span<const Eigen::Matrix3d> A,
                              const ConstraintTargets3& targets, Eigen::Matrix3Xd v, int iterations,
                              std::size_t threads);

/// E^ARAP(v) for the maps A and the constraints' targets.
double arap_energy(const PoissonSystem3& system, std::span<const Eigen::Matrix3d> A, const Eigen::Matrix3Xd& v,
                   const ConstraintTargets3& targets);

}  // namespace affinterp::global3
