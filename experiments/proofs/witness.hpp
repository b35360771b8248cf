#pragma once
// Counterexamples people can check by hand: a decider's sample point moved to small rationals while the
// exact quantifier-free predicate still holds at it: shrunk to small rationals where the set has one, and
// re-verified.
#include "theory/logic/polynomial.hpp"

#include <functional>
#include <optional>
#include <vector>

namespace affinterp::proofs {

using Predicate = std::function<bool(const logic::Point&)>;

/// Rationals p/q ordered from simple to complex: by q, then |p|, then closeness to `near`; |p/q| ≤ `span`,
/// q ≤ `max_denominator`, plus the best approximations of `near` with q ≤ 64.
std::vector<exact::Rational> simple_rationals(const exact::Rational& near, int max_denominator = 8, int span = 8);

/// A simpler point where `holds` is still true: first the first of `simple_points` (coordinates not given keep
/// `start`'s) where it holds, then, coordinate by coordinate and until nothing changes, the simplest candidate of
/// simple_rationals() that keeps it true. `start` may be approximate (an algebraic sample point rationalised):
/// when `holds` is false at it, nearby continued-fraction approximations are tried; nullopt when none holds.
std::optional<logic::Point> shrink_witness(const logic::Point& start, const Predicate& holds,
                                           const std::vector<logic::Point>& simple_points = {});

}  // namespace affinterp::proofs
