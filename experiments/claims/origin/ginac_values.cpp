#include "experiments/claims/origin/ginac_values.hpp"

#include "experiments/proofs/ginac_polynomial.hpp"
#include "theory/exact/rational.hpp"
#include "theory/origin/equal_energy_locus.hpp"
#include "theory/origin/symbols.hpp"

#include <sstream>
#include <stdexcept>

namespace affinterp::claims {
namespace {

/// Whether `e` is a polynomial in the origin's x, y with rational coefficients.
bool rational_polynomial_in_origin(const GiNaC::ex& e) {
  const origin::Symbols& s = origin::symbols();
  if (!e.is_polynomial(GiNaC::lst{s.x, s.y})) return false;
  const GiNaC::ex expanded = e.expand();
  for (int i = expanded.ldegree(s.x); i <= expanded.degree(s.x); ++i) {
    const GiNaC::ex in_y = expanded.coeff(s.x, i);
    for (int j = in_y.ldegree(s.y); j <= in_y.degree(s.y); ++j)
      if (!GiNaC::is_a<GiNaC::numeric>(in_y.coeff(s.y, j))) return false;
  }
  return true;
}

/// The coefficient of P's first term in polynomial_formula's order.
GiNaC::numeric leading_coefficient(const GiNaC::ex& P) {
  const origin::Symbols& s = origin::symbols();
  const GiNaC::ex e = P.expand();
  const int degree = origin::total_degree(e);
  for (int i = degree; i >= 0; --i)
    if (const GiNaC::ex c = e.coeff(s.x, i).coeff(s.y, degree - i); !c.is_zero())
      return GiNaC::ex_to<GiNaC::numeric>(c);
  return 0;
}

}  // namespace

std::string exact_number(const GiNaC::ex& e) {
  if (!GiNaC::is_a<GiNaC::numeric>(e) || !GiNaC::ex_to<GiNaC::numeric>(e).is_rational())
    throw std::invalid_argument("exact_number: not a rational number: " + proofs::text_of(e));
  // GiNaC prints rationals as p/q; parsing through the suite's own type fixes the exchange format.
  return exact::to_string(exact::parse_rational(proofs::text_of(e)));
}

nlohmann::json exact_matrix(const GiNaC::matrix& m) {
  nlohmann::json rows = nlohmann::json::array();
  for (unsigned r = 0; r < m.rows(); ++r) {
    nlohmann::json row = nlohmann::json::array();
    for (unsigned c = 0; c < m.cols(); ++c) row.push_back(exact_number(m(r, c)));
    rows.push_back(row);
  }
  return rows;
}

std::string formula(const GiNaC::ex& e) {
  const GiNaC::ex fraction = e.normal().numer_denom();
  const GiNaC::ex numerator = fraction.op(0), denominator = fraction.op(1);
  if (!rational_polynomial_in_origin(numerator) || !rational_polynomial_in_origin(denominator))
    return proofs::text_of(e);
  // The reduced fraction with a denominator whose leading coefficient is 1: the same text for the same
  // function, whatever order GiNaC holds the terms in.
  const GiNaC::numeric lead = leading_coefficient(denominator);
  const std::string top = polynomial_formula(numerator / lead), bottom = polynomial_formula(denominator / lead);
  return bottom == "1" ? top : "(" + top + ")/(" + bottom + ")";
}

std::string polynomial_formula(const GiNaC::ex& P) {
  const origin::Symbols& s = origin::symbols();
  const GiNaC::ex e = P.expand();
  const int degree = origin::total_degree(e);
  std::ostringstream text;
  bool first = true;
  for (int total = degree; total >= 0; --total)
    for (int i = total; i >= 0; --i) {
      const int j = total - i;
      const GiNaC::ex c = e.coeff(s.x, i).coeff(s.y, j);
      if (c.is_zero()) continue;
      const GiNaC::numeric coefficient = GiNaC::ex_to<GiNaC::numeric>(c);
      const GiNaC::numeric magnitude = abs(coefficient);
      text << (first ? (coefficient.is_negative() ? "-" : "") : (coefficient.is_negative() ? " - " : " + "));
      first = false;
      if (total == 0 || magnitude != 1) text << exact_number(magnitude) << (total > 0 ? "*" : "");
      if (i > 0) text << "x";
      if (i > 1) text << "^" << i;
      if (i > 0 && j > 0) text << "*";
      if (j > 0) text << "y";
      if (j > 1) text << "^" << j;
    }
  return first ? "0" : text.str();
}

}  // namespace affinterp::claims
