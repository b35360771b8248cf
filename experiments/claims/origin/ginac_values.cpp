#include "experiments/claims/origin/ginac_values.hpp"

#include "theory/exact/rational.hpp"
#include "theory/origin/equal_energy_locus.hpp"
#include "theory/origin/symbols.hpp"

#include <sstream>
#include <stdexcept>

namespace affinterp::claims {

std::string exact_number(const GiNaC::ex& e) {
  if (!GiNaC::is_a<GiNaC::numeric>(e) || !GiNaC::ex_to<GiNaC::numeric>(e).is_rational())
    throw std::invalid_argument("exact_number: not a rational number: " + formula(e));
  // GiNaC prints rationals as p/q; parsing through the suite's own type fixes the exchange format.
  return exact::to_string(exact::parse_rational(formula(e)));
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
  std::ostringstream out;
  out << e;
  return out.str();
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
