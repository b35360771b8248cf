#pragma once
// Exact numbers a + b√d (a, b rational, d a square-free positive integer): the field Q(√d), ordered as a
// subfield of ℝ. Thesis §2.2.4's example lives in Q(√3) (cos and sin of multiples of π/3).
#include "theory/exact/rational.hpp"

#include <compare>
#include <string>

namespace affinterp::local {

template <int d>
struct QuadraticSurd {
  exact::Rational a = 0;  ///< rational part
  exact::Rational b = 0;  ///< coefficient of √d

  QuadraticSurd() = default;
  QuadraticSurd(exact::Rational a, exact::Rational b = 0) : a(std::move(a)), b(std::move(b)) {}
  QuadraticSurd(int a) : a(a) {}  // NOLINT: integer literals in templates (Scalar(1))

  static QuadraticSurd root() { return {0, 1}; }  ///< √d

  friend QuadraticSurd operator+(const QuadraticSurd& u, const QuadraticSurd& v) { return {u.a + v.a, u.b + v.b}; }
  friend QuadraticSurd operator-(const QuadraticSurd& u, const QuadraticSurd& v) { return {u.a - v.a, u.b - v.b}; }
  friend QuadraticSurd operator-(const QuadraticSurd& u) { return {-u.a, -u.b}; }
  friend QuadraticSurd operator*(const QuadraticSurd& u, const QuadraticSurd& v) {
    return {u.a * v.a + d * u.b * v.b, u.a * v.b + u.b * v.a};
  }
  /// u / v = u·(v.a − v.b√d) / (v.a² − d·v.b²); throws std::domain_error for v = 0.
  friend QuadraticSurd operator/(const QuadraticSurd& u, const QuadraticSurd& v) {
    const exact::Rational norm = v.a * v.a - d * v.b * v.b;
    if (norm == 0) throw std::domain_error("division by zero in Q(sqrt d)");
    return u * QuadraticSurd{v.a / norm, -v.b / norm};
  }
  QuadraticSurd& operator+=(const QuadraticSurd& v) { return *this = *this + v; }
  QuadraticSurd& operator-=(const QuadraticSurd& v) { return *this = *this - v; }
  QuadraticSurd& operator*=(const QuadraticSurd& v) { return *this = *this * v; }
  QuadraticSurd& operator/=(const QuadraticSurd& v) { return *this = *this / v; }

  /// The sign of a + b√d, decided exactly: compare a² with d·b² when the parts differ in sign.
  int sign() const {
    const int sa = a.sign(), sb = b.sign();
    if (sa == sb || sb == 0) return sa;
    if (sa == 0) return sb;
    const exact::Rational gap = a * a - d * b * b;  // > 0 iff |a| > |b|√d
    return gap.sign() * sa;
  }
  friend bool operator==(const QuadraticSurd& u, const QuadraticSurd& v) { return u.a == v.a && u.b == v.b; }
  friend std::strong_ordering operator<=>(const QuadraticSurd& u, const QuadraticSurd& v) {
    return (u - v).sign() <=> 0;
  }

  double to_double() const {
    return static_cast<double>(a) + static_cast<double>(b) * std::sqrt(static_cast<double>(d));
  }
};

/// "a + b*sqrt(d)" with a, b as "p/q"; a zero part is left out.
template <int d>
std::string to_string(const QuadraticSurd<d>& u) {
  const std::string surd = exact::to_string(u.b) + "*sqrt(" + std::to_string(d) + ")";
  if (u.b == 0) return exact::to_string(u.a);
  return u.a == 0 ? surd : exact::to_string(u.a) + " + " + surd;
}

using QSqrt3 = QuadraticSurd<3>;

}  // namespace affinterp::local
