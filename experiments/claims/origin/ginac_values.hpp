#pragma once
// GiNaC values in claims.json: exact numbers as "p/q" strings, matrices as arrays of rows, formulas as
// text in GiNaC's notation (x^2 for x², * for products) with a fixed term order.
#include <ginac/ginac.h>
#include <nlohmann/json.hpp>

#include <string>

namespace affinterp::claims {

/// An exact rational number as "p/q"; throws std::invalid_argument when `e` is not one.
std::string exact_number(const GiNaC::ex& e);

/// An exact numeric GiNaC matrix as an array of rows of "p/q" strings.
nlohmann::json exact_matrix(const GiNaC::matrix& m);

/// A formula as text. A rational function of the origin's x, y as its reduced fraction with a monic
/// denominator, both polynomials in polynomial_formula's order — "(x^2 - 4*x*y + y^2 + x + y)/(x^2 + 3)" —
/// so that one function always reads the same; anything else (e.g. a lone unknown v1x) as GiNaC prints it.
std::string formula(const GiNaC::ex& e);

/// A polynomial in x, y (the origin) with rational coefficients, terms by falling total degree, then
/// falling degree in x: "x^2 - 4*x*y + y^2 + x + y - 1/4".
std::string polynomial_formula(const GiNaC::ex& P);

}  // namespace affinterp::claims
