#pragma once
// When the global problem has a unique, non-degenerate minimiser (Kaji §4: "one can modify the
// constraint function C such that [the minimiser] becomes a single point").
//
// Every local error depends on B_i only, so the global error is invariant under translating all v_k:
// the constraints must fix translation. E^R and E^S are moreover invariant under B_i ↦ s R_δ B_i up to the
// factor s², with minimum 0 at B = 0: when no triangle carries an E^F part, constraints that fix only
// translation leave the collapse of the whole shape onto one point as the minimiser. Then the constraints
// must also fix rotation and scale. Both conditions are read off the constraint quadratic restricted to
// the motions v_k = (xI + yJ) p_k + d of the source: it must be definite in d, and for a similarity
// invariant energy definite in (x, y, d).
#include "theory/global/constraint_terms.hpp"

#include <vector>

namespace affinterp::global {

/// Throws RefusedProblem naming what is missing; `similarity_invariant` when no triangle has an E^F part.
void require_well_posed(const Mesh& source, const std::vector<ConstraintTerm>& terms, bool similarity_invariant,
                        const std::string& energy_name);

}  // namespace affinterp::global
