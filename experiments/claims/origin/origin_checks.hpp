#pragma once
// The checks of the origin study (thesis §2.3), one per claim, and what they share.
#include "experiments/claims/context.hpp"
#include "experiments/claims/outcome.hpp"
#include "experiments/support/random.hpp"

#include "theory/origin/equal_energy_locus.hpp"

#include <ginac/ginac.h>

#include <optional>

namespace affinterp::claims {

Outcome check_matrices(const RunContext& ctx);     // thesis.sec-2.3.matrices
Outcome check_minimiser(const RunContext& ctx);    // thesis.sec-2.3.minimiser
Outcome check_min_energy(const RunContext& ctx);   // thesis.sec-2.3.min-energy
Outcome check_conic(const RunContext& ctx);        // thesis.sec-2.3.conic

/// A random origin o = (x, y) with small-denominator rational coordinates (numerators in [−12, 12],
/// denominators in [1, 9]), as the substitution {x == …, y == …}.
GiNaC::lst random_rational_origin(Rng& rng);

/// The first origin o = (x, y), x and y running through 0, 1, −1, 1/2, −1/2, 2, −2, where the rational functions
/// `a` and `b` of x, y are both defined and differ; none when they agree on all of them.
std::optional<GiNaC::lst> small_origin_where_differ(const GiNaC::ex& a, const GiNaC::ex& b);

}  // namespace affinterp::claims
