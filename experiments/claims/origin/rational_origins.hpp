#pragma once
// Origins o = (x, y) with rational coordinates, where the origin claims of thesis §2.3 compare a printed rational
// function of o with the computed one.
#include "experiments/support/random.hpp"

#include <ginac/ginac.h>

#include <optional>

namespace affinterp::claims {

/// A random origin o = (x, y) with small-denominator rational coordinates (numerators in [−12, 12],
/// denominators in [1, 9]), as the substitution {x == …, y == …}.
GiNaC::lst random_rational_origin(Rng& rng);

/// The first origin o = (x, y), x and y running through 0, 1, −1, 1/2, −1/2, 2, −2, where the rational functions
/// `a` and `b` of x, y are both defined and differ; none when they agree on all of them.
std::optional<GiNaC::lst> small_origin_where_differ(const GiNaC::ex& a, const GiNaC::ex& b);

}  // namespace affinterp::claims
