#pragma once
// Grids of exact values for sweeps, the simplicity order used to shrink counterexamples (a rational p/q is
// simpler the smaller max(|p|, q)), and the exact 2×2 matrices the local claims are built from.
#include "theory/exact/rational.hpp"
#include "theory/local/matrix2.hpp"

#include <vector>

namespace affinterp::claims::local {

using exact::Rational;

/// lo, lo + step, ..., up to hi inclusive.
inline std::vector<Rational> grid(const Rational& lo, const Rational& hi, const Rational& step) {
  std::vector<Rational> values;
  for (Rational v = lo; v <= hi; v += step) values.push_back(v);
  return values;
}

/// max(|p|, q) of p/q.
inline double height(const Rational& q) {
  const exact::Integer p = abs(boost::multiprecision::numerator(q)), d = boost::multiprecision::denominator(q);
  return static_cast<double>(p > d ? p : d);
}

/// A rotation R_β with rational entries: cos β = (1−u²)/(1+u²), sin β = 2u/(1+u²) (β = 2 arctan u).
template <class Mat>
Mat rational_rotation(const Rational& u) {
  const Rational c = (1 - u * u) / (1 + u * u), s = 2 * u / (1 + u * u);
  Mat R;
  R << c, -s, s, c;
  return R;
}

/// D = diag(x, y).
inline affinterp::local::Mat2<Rational> diagonal(const Rational& x, const Rational& y) {
  affinterp::local::Mat2<Rational> D;
  D << x, 0, 0, y;
  return D;
}

/// S = [[x, h], [h, y]].
inline affinterp::local::Mat2<Rational> symmetric(const Rational& x, const Rational& y, const Rational& h) {
  affinterp::local::Mat2<Rational> S;
  S << x, h, h, y;
  return S;
}

}  // namespace affinterp::claims::local
