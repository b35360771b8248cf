#include "theory/logic/polynomial.hpp"

#include <stdexcept>

namespace affinterp::logic {

Polynomial::Polynomial(const Rational& constant) {
  if (constant != 0) terms_[Monomial{}] = constant;
}

Polynomial Polynomial::variable(const std::string& name) {
  Polynomial p;
  p.terms_[Monomial{{name, 1u}}] = Rational(1);
  return p;
}

bool Polynomial::is_constant() const { return terms_.empty() || (terms_.size() == 1 && terms_.begin()->first.empty()); }

Rational Polynomial::constant_term() const {
  const auto it = terms_.find(Monomial{});
  return it == terms_.end() ? Rational(0) : it->second;
}

std::set<std::string> Polynomial::variables() const {
  std::set<std::string> names;
  for (const auto& [m, c] : terms_)
    for (const auto& [name, e] : m) names.insert(name);
  return names;
}

unsigned Polynomial::degree_in(const std::string& name) const {
  unsigned d = 0;
  for (const auto& [m, c] : terms_)
    if (const auto it = m.find(name); it != m.end() && it->second > d) d = it->second;
  return d;
}

void Polynomial::add_term(const Monomial& m, const Rational& c) {
  if (c == 0) return;
  const auto [it, inserted] = terms_.emplace(m, c);
  if (!inserted && (it->second += c) == 0) terms_.erase(it);
}

Polynomial Polynomial::operator-() const {
  Polynomial p = *this;
  for (auto& [m, c] : p.terms_) c = -c;
  return p;
}

Polynomial& Polynomial::operator+=(const Polynomial& other) {
  for (const auto& [m, c] : other.terms_) add_term(m, c);
  return *this;
}

Polynomial& Polynomial::operator-=(const Polynomial& other) {
  for (const auto& [m, c] : other.terms_) add_term(m, -c);
  return *this;
}

Polynomial& Polynomial::operator*=(const Polynomial& other) {
  Polynomial product;
  for (const auto& [m1, c1] : terms_)
    for (const auto& [m2, c2] : other.terms_) {
      Monomial m = m1;
      for (const auto& [name, e] : m2) m[name] += e;
      product.add_term(m, c1 * c2);
    }
  return *this = std::move(product);
}

Rational Polynomial::evaluate(const Point& at) const {
  Rational sum = 0;
  for (const auto& [m, c] : terms_) {
    Rational term = c;
    for (const auto& [name, e] : m) {
      const auto it = at.find(name);
      if (it == at.end()) throw std::invalid_argument("no value for the variable " + name);
      for (unsigned i = 0; i < e; ++i) term *= it->second;
    }
    sum += term;
  }
  return sum;
}

Polynomial Polynomial::substitute(const std::string& name, const Polynomial& by) const {
  Polynomial result;
  for (const auto& [m, c] : terms_) {
    Monomial rest = m;
    const auto it = rest.find(name);
    const unsigned e = it == rest.end() ? 0 : it->second;
    if (it != rest.end()) rest.erase(it);
    Polynomial term;
    term.terms_[rest] = c;
    result += term * pow(by, e);
  }
  return result;
}

Polynomial Polynomial::derivative(const std::string& name) const {
  Polynomial result;
  for (const auto& [m, c] : terms_) {
    const auto it = m.find(name);
    if (it == m.end()) continue;
    Monomial lowered = m;
    if (--lowered[name] == 0) lowered.erase(name);
    result.add_term(lowered, c * it->second);
  }
  return result;
}

Polynomial Polynomial::rename(const std::map<std::string, std::string>& names) const {
  Polynomial result;
  for (const auto& [m, c] : terms_) {
    Monomial renamed;
    for (const auto& [name, e] : m) {
      const auto it = names.find(name);
      renamed[it == names.end() ? name : it->second] += e;
    }
    result.add_term(renamed, c);
  }
  return result;
}

Polynomial pow(const Polynomial& base, unsigned exponent) {
  Polynomial result(1), square = base;
  for (; exponent > 0; exponent >>= 1) {
    if (exponent & 1u) result *= square;
    if (exponent > 1) square *= square;
  }
  return result;
}

std::string to_string(const Polynomial& p) {
  if (p.is_zero()) return "0";
  std::string text;
  for (const auto& [m, c] : p.terms()) {
    const bool negative = c < 0;
    const Rational magnitude = negative ? Rational(-c) : c;
    text += text.empty() ? (negative ? "-" : "") : (negative ? " - " : " + ");
    std::string factors;
    for (const auto& [name, e] : m) {
      if (!factors.empty()) factors += "*";
      factors += name;
      if (e > 1) {  // appended piece by piece: GCC 12 misreports "^" + s (-Wrestrict)
        factors += '^';
        factors += std::to_string(e);
      }
    }
    if (factors.empty())
      text += exact::to_string(magnitude);
    else {
      if (magnitude != 1) text += exact::to_string(magnitude) + "*";
      text += factors;
    }
  }
  return text;
}

}  // namespace affinterp::logic
