#pragma once
// Sparse multivariate polynomials over the rationals, in named variables: the atoms of the first-order
// sentences that decide the algebraic claims for all reals. Exact throughout.
#include "theory/exact/rational.hpp"

#include <map>
#include <set>
#include <string>

namespace affinterp::logic {

using exact::Rational;

/// A point of R^n with rational coordinates, by variable name.
using Point = std::map<std::string, Rational>;

/// x1^e1 · x2^e2 ⋯ as variable → exponent (≥ 1); the empty monomial is 1.
using Monomial = std::map<std::string, unsigned>;

class Polynomial {
 public:
  Polynomial() = default;  ///< zero
  Polynomial(const Rational& constant);
  Polynomial(int constant) : Polynomial(Rational(constant)) {}
  static Polynomial variable(const std::string& name);

  /// Monomial → non-zero coefficient.
  const std::map<Monomial, Rational>& terms() const { return terms_; }
  bool is_zero() const { return terms_.empty(); }
  bool is_constant() const;
  /// The constant term (the value, when is_constant()).
  Rational constant_term() const;
  std::set<std::string> variables() const;
  /// Highest exponent of `name` in any term.
  unsigned degree_in(const std::string& name) const;

  Polynomial operator-() const;
  Polynomial& operator+=(const Polynomial& other);
  Polynomial& operator-=(const Polynomial& other);
  Polynomial& operator*=(const Polynomial& other);
  friend Polynomial operator+(Polynomial a, const Polynomial& b) { return a += b; }
  friend Polynomial operator-(Polynomial a, const Polynomial& b) { return a -= b; }
  friend Polynomial operator*(Polynomial a, const Polynomial& b) { return a *= b; }
  friend bool operator==(const Polynomial& a, const Polynomial& b) { return a.terms_ == b.terms_; }

  /// The exact value at `at`; throws std::invalid_argument when a variable has no coordinate.
  Rational evaluate(const Point& at) const;
  /// The polynomial with `name` replaced by `by` everywhere.
  Polynomial substitute(const std::string& name, const Polynomial& by) const;
  /// ∂/∂name.
  Polynomial derivative(const std::string& name) const;
  /// The polynomial with every variable renamed by `names` (variables not in it are kept).
  Polynomial rename(const std::map<std::string, std::string>& names) const;

 private:
  void add_term(const Monomial& m, const Rational& c);
  std::map<Monomial, Rational> terms_;
};

/// base^exponent.
Polynomial pow(const Polynomial& base, unsigned exponent);

/// Readable text, e.g. "x^2*y - 1/2*h + 3" (terms in the monomial order); for messages and tests.
std::string to_string(const Polynomial& p);

}  // namespace affinterp::logic
