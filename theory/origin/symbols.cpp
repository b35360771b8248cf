#include "theory/origin/symbols.hpp"

namespace affinterp::origin {
namespace {

Symbols make_symbols() {
  static const char* const names[4][2] = {{"v1x", "v1y"}, {"v2x", "v2y"}, {"v3x", "v3y"}, {"v4x", "v4y"}};
  Symbols s;
  for (unsigned k = 0; k < 4; ++k) {
    const GiNaC::symbol vx(names[k][0]), vy(names[k][1]);
    s.v(0, k) = vx;
    s.v(1, k) = vy;
    s.unknowns.append(vx).append(vy);
  }
  return s;
}

}  // namespace

const Symbols& symbols() {
  static const Symbols instance = make_symbols();
  return instance;
}

GiNaC::matrix column(const GiNaC::ex& a, const GiNaC::ex& b) { return GiNaC::matrix{{a}, {b}}; }

}  // namespace affinterp::origin
