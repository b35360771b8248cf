#include "theory/logic/qepcad_input.hpp"

#include <algorithm>
#include <numeric>

namespace affinterp::logic {

namespace {

using exact::Integer;

/// p times the positive lcm of its coefficients' denominators: the same sign everywhere, integer coefficients.
Polynomial integer_multiple(const Polynomial& p) {
  Integer lcm = 1;
  for (const auto& [m, c] : p.terms()) {
    const Integer q = boost::multiprecision::denominator(c);
    lcm = lcm / boost::multiprecision::gcd(lcm, q) * q;
  }
  return p * Polynomial(Rational(lcm));
}

/// QEPCAD B writes ≠ as "/="; every other relation as the decide grammar does.
std::string_view qepcad_relation(Relation r) { return r == Relation::not_equal ? "/=" : symbol(r); }

std::string matrix_text(const Formula& f) {
  using K = Formula::Kind;
  switch (f.kind) {
    case K::atom:
      return "[ " + qepcad_polynomial(f.polynomial) + " " + std::string(qepcad_relation(f.relation)) + " 0 ]";
    case K::conjunction:
    case K::disjunction: {
      std::string text = "[ ";
      for (std::size_t i = 0; i < f.parts.size(); ++i)
        text += (i ? (f.kind == K::conjunction ? " /\\ " : " \\/ ") : "") + matrix_text(f.parts[i]);
      return text + " ]";
    }
    case K::negation:
      return "~" + matrix_text(f.parts.front());
    default:
      return "";  // constants are simplified away and quantifiers pulled out before writing
  }
}

}  // namespace

std::string qepcad_polynomial(const Polynomial& p) {
  if (p.is_zero()) return "0";
  std::string text;
  const auto degree = [](const Monomial& m) {
    return std::accumulate(m.begin(), m.end(), 0u, [](unsigned s, const auto& e) { return s + e.second; });
  };
  const Polynomial integral = integer_multiple(p);
  // Highest total degree first, as one writes polynomials by hand.
  std::vector<std::pair<Monomial, Rational>> integral_terms(integral.terms().begin(), integral.terms().end());
  std::stable_sort(integral_terms.begin(), integral_terms.end(),
                   [&](const auto& a, const auto& b) { return degree(a.first) > degree(b.first); });
  for (const auto& [m, c] : integral_terms) {
    const bool negative = c < 0;
    const Rational magnitude = negative ? Rational(-c) : c;
    text += text.empty() ? (negative ? "- " : "") : (negative ? " - " : " + ");
    std::string body = (magnitude != 1 || m.empty()) ? exact::to_string(magnitude) : "";
    for (const auto& [name, e] : m) {
      if (!body.empty()) body += " ";
      body += name;
      if (e > 1) body.append("^").append(std::to_string(e));
    }
    text += body;
  }
  return text;
}

std::string to_qepcad(const Formula& f, const QepcadInput& input) {
  Prenex p = prenex(f);
  for (QuantifierBlock& block : p.prefix) {
    std::stable_sort(block.variables.begin(), block.variables.end(), [&](const auto& a, const auto& b) {
      const auto rank = [&](const std::string& v) {
        return std::find(input.order.begin(), input.order.end(), v) - input.order.begin();
      };
      return rank(a) < rank(b);
    });
  }
  std::vector<std::string> variables = input.free;
  const std::vector<std::string> bound = p.bound_variables();
  variables.insert(variables.end(), bound.begin(), bound.end());
  std::string matrix;
  if (p.matrix.kind == Formula::Kind::constant) {
    // QEPCAD has no constants: "zz - zz = 0" is true, "/= 0" false.
    if (variables.empty()) {
      variables.push_back("zz");
      p.prefix.push_back({false, {"zz"}});
    }
    matrix = "[ " + variables.front() + " - " + variables.front() + (p.matrix.value ? " = 0 ]" : " /= 0 ]");
  } else {
    matrix = matrix_text(p.matrix);
  }
  std::string text = "[ " + input.title + " ]\n(";
  for (std::size_t i = 0; i < variables.size(); ++i) text += (i ? "," : "") + variables[i];
  text += ")\n" + std::to_string(input.free.size()) + "\n";
  for (const QuantifierBlock& block : p.prefix)
    for (const std::string& v : block.variables) text += (block.universal ? "(A " : "(E ") + v + ")";
  text += matrix + ".\n";
  for (const std::string& c : input.setup) text += c + "\n";
  std::vector<std::string> commands = input.commands;
  if (commands.empty())
    commands = p.existential() && input.free.empty()
                   ? std::vector<std::string>{"go", "go", "go", "d-witness-list", "finish"}
                   : std::vector<std::string>{"finish"};
  for (const std::string& c : commands) text += c + "\n";
  return text;
}

}  // namespace affinterp::logic
