#include "theory/logic/smtlib_input.hpp"

#include <stdexcept>

namespace affinterp::logic {

namespace {

std::string rational_term(const Rational& r) {
  const bool negative = r < 0;
  const Rational m = negative ? Rational(-r) : r;
  const exact::Integer p = boost::multiprecision::numerator(m), q = boost::multiprecision::denominator(m);
  const std::string body = q == 1 ? p.str() : "(/ " + p.str() + " " + q.str() + ")";
  return negative ? "(- " + body + ")" : body;
}

std::string formula_text(const Formula& f) {
  using K = Formula::Kind;
  switch (f.kind) {
    case K::constant:
      return f.value ? "true" : "false";
    case K::atom: {
      const std::string lhs = smtlib_term(f.polynomial);
      if (f.relation == Relation::not_equal) return "(not (= " + lhs + " 0))";
      return "(" + std::string(symbol(f.relation)) + " " + lhs + " 0)";
    }
    case K::conjunction:
    case K::disjunction: {
      std::string text = f.kind == K::conjunction ? "(and" : "(or";
      for (const Formula& g : f.parts) text += " " + formula_text(g);
      return text + ")";
    }
    case K::negation:
      return "(not " + formula_text(f.parts.front()) + ")";
    case K::exists:
    case K::forall: {
      std::string text = f.kind == K::exists ? "(exists (" : "(forall (";
      for (std::size_t i = 0; i < f.bound.size(); ++i) text += (i ? " (" : "(") + f.bound[i] + " Real)";
      return text + ") " + formula_text(f.parts.front()) + ")";
    }
  }
  throw std::logic_error("unknown formula kind");
}

}  // namespace

std::string smtlib_term(const Polynomial& p) {
  if (p.is_zero()) return "0";
  std::vector<std::string> terms;
  for (const auto& [m, c] : p.terms()) {
    std::vector<std::string> factors;
    if (c != 1 || m.empty()) factors.push_back(rational_term(c));
    for (const auto& [name, e] : m)
      for (unsigned i = 0; i < e; ++i) factors.push_back(name);
    if (factors.size() == 1) {
      terms.push_back(factors.front());
    } else {
      std::string product = "(*";
      for (const std::string& x : factors) product += " " + x;
      terms.push_back(product + ")");
    }
  }
  if (terms.size() == 1) return terms.front();
  std::string sum = "(+";
  for (const std::string& t : terms) sum += " " + t;
  return sum + ")";
}

std::string to_smtlib(const Formula& f, const std::string& title) {
  if (!free_variables(f).empty()) throw std::invalid_argument("to_smtlib(): not a sentence");
  Prenex p = prenex(f);
  std::vector<std::string> declared;
  std::size_t first = 0;
  if (!p.prefix.empty() && !p.prefix.front().universal) declared = p.prefix[first++].variables;
  Formula body = p.matrix;
  for (std::size_t i = p.prefix.size(); i-- > first;)
    body = p.prefix[i].universal ? forall(p.prefix[i].variables, std::move(body))
                                 : exists(p.prefix[i].variables, std::move(body));
  std::string text = "; " + title + "\n(set-logic " + (first == p.prefix.size() ? "QF_NRA" : "NRA") + ")\n";
  for (const std::string& v : declared) text += "(declare-const " + v + " Real)\n";
  return text + "(assert " + formula_text(body) + ")\n(check-sat)\n";
}

}  // namespace affinterp::logic
