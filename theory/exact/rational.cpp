#include "theory/exact/rational.hpp"

#include <cmath>
#include <regex>
#include <stdexcept>

namespace affinterp::exact {

std::string to_string(const Rational& q) {
  const Integer num = boost::multiprecision::numerator(q);
  const Integer den = boost::multiprecision::denominator(q);
  if (den == 1) return num.str();
  return num.str() + "/" + den.str();
}

Rational parse_rational(const std::string& text) {
  static const std::regex form(R"(^\s*([+-]?\d+)(?:\s*/\s*(\d+))?\s*$)");
  std::smatch m;
  if (!std::regex_match(text, m, form)) throw std::invalid_argument("not a rational p/q: '" + text + "'");
  const Integer num(m[1].str());
  const Integer den = m[2].matched ? Integer(m[2].str()) : Integer(1);
  if (den == 0) throw std::invalid_argument("zero denominator: '" + text + "'");
  return Rational(num, den);
}

Rational from_double(double x) {
  if (!std::isfinite(x)) throw std::invalid_argument("non-finite value has no rational form");
  int exponent = 0;
  const double mantissa = std::frexp(x, &exponent);                      // x = mantissa * 2^exponent
  const auto scaled = static_cast<long long>(std::ldexp(mantissa, 53));  // exact: 53-bit integer
  Rational q(scaled);
  const int shift = exponent - 53;
  if (shift >= 0) return q * Rational(Integer(1) << shift);
  return q / Rational(Integer(1) << -shift);
}

}  // namespace affinterp::exact
