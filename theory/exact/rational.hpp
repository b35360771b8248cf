#pragma once
// Exact arithmetic used to decide algebraic claims: rationals and high-precision floats from
// Boost.Multiprecision, with Eigen matrices over them.
#include <Eigen/Core>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <boost/multiprecision/cpp_int.hpp>
#include <string>

namespace affinterp::exact {

using Rational = boost::multiprecision::cpp_rational;
using Integer = boost::multiprecision::cpp_int;
/// 50 significant decimal digits, expression templates off (Eigen needs et_off).
using Real50 = boost::multiprecision::cpp_bin_float_50;
/// 100 significant decimal digits, for references that are compared at 50.
using Real100 = boost::multiprecision::cpp_bin_float_100;

using Mat2Q = Eigen::Matrix<Rational, 2, 2>;
using Vec2Q = Eigen::Matrix<Rational, 2, 1>;
using Mat3Q = Eigen::Matrix<Rational, 3, 3>;

/// "p/q" (or "p" when q = 1): the exchange format of exact values in claims.json.
std::string to_string(const Rational& q);
/// Parses "p/q" or "p"; throws std::invalid_argument on anything else.
Rational parse_rational(const std::string& text);
/// The exact rational value of a finite double (every double is a dyadic rational).
Rational from_double(double x);

}  // namespace affinterp::exact
