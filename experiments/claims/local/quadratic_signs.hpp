#pragma once
// Where a determinant c0 + c1 t + c2 t² with c0 = 1 (det((1−t)I + tB) of theory/local/goodness.hpp) goes
// over all real t, decided exactly from its coefficients.
#include "theory/exact/rational.hpp"
#include "theory/local/goodness.hpp"

namespace affinterp::claims::local {

using affinterp::local::Quadratic;
using exact::Rational;

/// Whether p takes a negative value at some real t.
inline bool takes_negative_value(const Quadratic<Rational>& p) {
  const Rational discriminant = p.c1 * p.c1 - 4 * p.c0 * p.c2;
  return p.c2 < 0 || (p.c2 == 0 && p.c1 != 0) || (p.c2 > 0 && discriminant > 0);
}

/// Whether p vanishes at some real t.
inline bool has_real_root(const Quadratic<Rational>& p) {
  const Rational discriminant = p.c1 * p.c1 - 4 * p.c0 * p.c2;
  return (p.c2 == 0 && p.c1 != 0) || (p.c2 != 0 && discriminant >= 0);
}

}  // namespace affinterp::claims::local
