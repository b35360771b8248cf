#pragma once
// The default gauge of the global interpolation (Kaji §4). E^R and E^S satisfy E(A, s R_δ B) = s² E(A, B)
// (eq. (4) and the Appendix: their minimum over s, δ absorbs the similarity), so the global error of a
// shape turned by R_δ and scaled by s about any point is s² times its own: with constraints that fix
// only translation, its minimum is the collapse onto a point (well_posedness.hpp). Kaji §4: "one can
// modify the constraint function C such that [the minimiser] becomes a single point". When the caller
// constrains no vertex and no edge, one edge direction is such a modification: e(t) fixes v_i − v_j, that
// is the rotation and the scale; translation is left to the barycentre locus.
#include "theory/global/mesh.hpp"
#include "theory/global/options.hpp"

#include <optional>

namespace affinterp::global {

/// The edge direction that fixes rotation and scale when the caller's constraints do not.
///
/// @param[in] source   the source mesh P as the engine receives it (counter-clockwise)
/// @param[in] options  only `energy` and `constraints` are read
/// @return the edge between corners 0 and 1 of the source triangle whose centroid is nearest the
///   vertex barycentre Σ p_k / n (the first such triangle on a tie), following its local homotopy,
///   e(t) = A_τ(t)(p_i − p_j), with weight 1; std::nullopt when the energy is E^F (not invariant
///   under scaling) or the constraints already hold a pinned vertex, a vertex locus or an edge direction.
/// \note The edge is chosen from the source alone, so interpolating (Q, P) may constrain another edge
///   than (P, Q). A blend gets the edge whatever its weights w_i.
std::optional<EdgeDirection> default_edge_direction(const Mesh& source, const InterpolationOptions& options);

}  // namespace affinterp::global
