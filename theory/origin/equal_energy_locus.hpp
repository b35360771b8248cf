#pragma once
// The origin study of thesis §2.3 (Problem 2.3.1, Fig. 2.6): min E1 and min E2(o, o) for the
// two-triangle configuration as exact rational functions of the origin o = (x, y), and the locus of the
// origins where they coincide.
#include "theory/origin/energy.hpp"
#include "theory/origin/two_triangles.hpp"

#include <ginac/ginac.h>

#include <utility>
#include <vector>

namespace affinterp::origin {

struct OriginStudy {
  TwoTriangles config;
  GiNaC::ex E1;           ///< E1(A1, A2, B1(v), B2(v)): every origin at zero
  GiNaC::ex E2_common;    ///< E2(A1, A2, B1(v), B2(v), o, o) with o = (x, y)
  Minimum min_E1;         ///< a number
  Minimum min_E2_common;  ///< rational functions of x, y
};

/// Builds both energies from their definitions (Defs. 2.3.1, 2.3.2) and minimises them exactly.
OriginStudy study_origin(const TwoTriangles& config);

/// study_origin of the thesis's configuration (thesis_two_triangles), computed once.
const OriginStudy& thesis_study();

/// The polynomial P(x, y) whose zero set is {difference = 0} for a rational function whose denominator
/// never vanishes: the numerator, with integer coefficients of gcd 1 and a positive leading coefficient
/// (first in x, then in y).
GiNaC::ex locus_polynomial(const GiNaC::ex& difference);

/// The total degree of the polynomial P in x, y (−1 for zero).
int total_degree(const GiNaC::ex& P);

/// Whether P = c Q for a nonzero rational constant c.
bool proportional(const GiNaC::ex& P, const GiNaC::ex& Q);

/// Rational points (x, y) on the curve P(x, y) = 0, P of degree ≤ 2 in y: for x running through the
/// small rationals p/q (|p| ≤ 2q, q ≤ 4, in order of q then |p|), the rational roots y; at most `count`.
/// Throws std::invalid_argument when P has degree above 2 in y.
std::vector<std::pair<GiNaC::numeric, GiNaC::numeric>> small_rational_points(const GiNaC::ex& P, std::size_t count);

/// Whether the polynomial q(x, y), of degree ≤ 2, is positive everywhere in the real plane (exact, by
/// completing the square in x).
bool positive_quadratic(const GiNaC::ex& q);

}  // namespace affinterp::origin
