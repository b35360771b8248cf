#pragma once
// The default gauge of the global interpolation (Kaji §4). E^R and E^S satisfy E(A, s R_δ B) = s² E(A, B)
// (eq. (4) and the Appendix: their minimum over s, δ absorbs the similarity), so the global error of a
// shape turned by R_δ and scaled by s about any point is s² times its own: with constraints that fix
// only translation, its minimum is the collapse onto a point (well_posedness.hpp). Kaji §4: "one can
// modify the constraint function C such that [the minimiser] becomes a single point". When the caller
// constrains no vertex and no edge, one edge direction is such a modification: e(t) fixes v_i − v_j, that
// is the rotation and the scale; translation is left to the barycentre locus.
//
// The edge is chosen from quantities symmetric in the pair (P, Q), so that the reverse problem (Q, P)
// gets the same edge: with the exp-log homotopy, A^{-1}(1 − t) A = R_{tθ} S^t = A(t) (eq. (3)), so the
// edge's path e(t) = A_τ(t)(p_i − p_j) is the reverse problem's e′(1 − t) = A_τ^{-1}(1 − t)(q_i − q_j), and
// the symmetrised energy E(t) + E^{-1}(1 − t) ("Improvements") of (P, Q) at t is that of (Q, P) at 1 − t.
#include "theory/global/mesh.hpp"
#include "theory/global/options.hpp"

#include <optional>

namespace affinterp::global {

/// The edge direction that fixes rotation and scale when the caller's constraints do not.
///
/// @param[in] source   the source mesh P (counter-clockwise)
/// @param[in] target   the target mesh Q, with P's triangles
/// @param[in] options  only `energy` and `constraints` are read
/// @return the edge between corners 0 and 1 of the triangle τ minimising
///   ‖c_τ(P) − p̄‖² / r²(P) + ‖c_τ(Q) − q̄‖² / r²(Q), c_τ the centroid, p̄ = Σ p_k / n the vertex barycentre,
///   r²(P) = Σ ‖p_k − p̄‖² / n (so each mesh counts alike whatever its size), the lowest index on a tie,
///   following its local homotopy, e(t) = A_τ(t)(p_i − p_j), with weight 1; std::nullopt when the energy is
///   E^F (not invariant under scaling) or the constraints already hold a pinned vertex, a vertex locus or
///   an edge direction. The score is a sum of a term of P and the same term of Q, so swapping the meshes
///   gives the same τ, bit for bit. A blend gets the edge whatever its weights w_i.
std::optional<EdgeDirection> default_edge_direction(const Mesh& source, const Mesh& target,
                                                    const InterpolationOptions& options);

}  // namespace affinterp::global
