#pragma once
// RapidCheck generators of small exact rationals and origins for the origin study's tests.
#include "theory/origin/symbols.hpp"

#include <rapidcheck.h>

#include <ginac/ginac.h>

namespace affinterp::origin::testing {

/// p/q with |p| ≤ 30, 1 ≤ q ≤ 9.
inline rc::Gen<GiNaC::numeric> small_rational() {
  return rc::gen::apply([](int p, int q) { return GiNaC::numeric(p, q); }, rc::gen::inRange(-30, 31),
                        rc::gen::inRange(1, 10));
}

/// An origin o = (x, y) as the substitution {x == …, y == …}.
inline GiNaC::lst origin_substitution(const GiNaC::numeric& x, const GiNaC::numeric& y) {
  return GiNaC::lst{symbols().x == x, symbols().y == y};
}

}  // namespace affinterp::origin::testing

namespace rc {
template <>
struct Arbitrary<GiNaC::numeric> {
  static Gen<GiNaC::numeric> arbitrary() { return affinterp::origin::testing::small_rational(); }
};
}  // namespace rc

namespace GiNaC {
inline void showValue(const numeric& value, std::ostream& os) { os << value; }
}  // namespace GiNaC
