#pragma once
// A polynomial with rational coefficients in named variables, expanded by the exact grid's own arithmetic
// (exact::Rational, no GiNaC arithmetic), with a canonical text: how the grid names the variable cos(g), sin(g) or
// exp(g) after a substitution into g, so that cos(φ + tβ) at t = 0 and cos(φ) are one variable.
#include "theory/exact/rational.hpp"

#include <ginac/ginac.h>

#include <map>
#include <string>

namespace affinterp::proofs {

struct ExpandedPolynomial {
  /// Monomial (variable name → exponent, none zero) → coefficient (none zero).
  std::map<std::map<std::string, unsigned>, exact::Rational> terms;
};

/// `e` expanded, each symbol named in `values` replaced by its polynomial. Throws std::invalid_argument on
/// anything but sums, products, powers with natural exponents, rational numbers and symbols.
ExpandedPolynomial expanded(const GiNaC::ex& e, const std::map<std::string, ExpandedPolynomial>& values);

/// The terms in the order of their monomials, e.g. "beta*t+phi", "0" for the zero polynomial.
std::string to_text(const ExpandedPolynomial& p);

}  // namespace affinterp::proofs
