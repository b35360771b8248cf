#include "theory/origin/printed_section_2_3.hpp"

#include "theory/origin/symbols.hpp"

namespace affinterp::origin::printed {
namespace {

using GiNaC::ex;
using GiNaC::numeric;

ex vx(unsigned k) { return symbols().v(0, k - 1); }
ex vy(unsigned k) { return symbols().v(1, k - 1); }

/// x² + 2xy + y² − 2x − 2y + 3, the denominator shared by the printed minimiser and minimum.
ex denominator() {
  const ex &x = symbols().x, &y = symbols().y;
  return x * x + 2 * x * y + y * y - 2 * x - 2 * y + 3;
}

}  // namespace

GiNaC::matrix A1() {
  const ex &x = symbols().x, &y = symbols().y;
  return GiNaC::matrix{{0, 2, -x + 2 * y}, {-2, 0, 4 - 2 * x - y}, {0, 0, 1}};
}

GiNaC::matrix A2() {
  const ex &x = symbols().x, &y = symbols().y;
  return GiNaC::matrix{{1, 2, 2 * y}, {-1, 0, 3 - x - y}, {0, 0, 1}};
}

GiNaC::matrix B1() {
  const ex &x = symbols().x, &y = symbols().y;
  const ex b11 = -x + vx(1) + x * (-vx(1) + vx(2)) + y * (-vx(1) + vx(3));
  const ex b12 = -y + vy(1) + x * (-vy(1) + vy(2)) + y * (-vy(1) + vy(3));
  return GiNaC::matrix{{-vx(1) + vx(2), -vx(1) + vx(3), b11}, {-vy(1) + vy(2), -vy(1) + vy(3), b12}, {0, 0, 1}};
}

GiNaC::matrix B2(Reading reading) {
  const ex &x = symbols().x, &y = symbols().y;
  ex b21, b22;
  if (reading == Reading::as_printed) {
    b21 = -x + vx(2) + vx(3) - vx(4) * x * (-vx(3) + vx(4)) + y * (-vx(2) + vx(4));
    b22 = -y + vy(2) + vy(3) - vy(4) * x * (-vy(3) + vy(4)) + y * (-vy(2) + vy(4));
  } else {
    b21 = -x + vx(2) + vx(3) - vx(4) + x * (-vx(3) + vx(4)) + y * (-vx(2) + vx(4));
    b22 = -y + vy(2) + vy(3) - vy(4) + x * (-vy(3) + vy(4)) + y * (-vy(2) + vy(4));
  }
  return GiNaC::matrix{{-vx(3) + vx(4), -vx(2) + vx(4), b21}, {-vy(3) + vy(4), -vy(2) + vy(4), b22}, {0, 0, 1}};
}

GiNaC::lst minimiser() {
  const ex &x = symbols().x, &y = symbols().y;
  const ex half = numeric(1, 2);
  const ex D = denominator();
  return GiNaC::lst{
      vx(1) == (1 + x * (-1 + x + y)) / (2 * D),
      vy(1) == half * (7 + (1 + (x - 1) * (-1 + x + y)) / D),
      vx(2) == half,
      vy(2) == 2,
      vx(3) == 2,
      vy(3) == numeric(7, 2),
      vx(4) == half * (5 + (1 + x * (-1 + x + y)) / D),
      vy(4) == half * (4 + (1 + (x - 1) * (-1 + x + y)) / D),
  };
}

GiNaC::ex min_E2() {
  const ex &x = symbols().x, &y = symbols().y;
  return (2 + (x - 1) * x + (y - 1) * y) / denominator();
}

GiNaC::ex conic() {
  const ex &x = symbols().x, &y = symbols().y;
  return x * x - 4 * x * y + y * y + x + y - numeric(1, 4);
}

}  // namespace affinterp::origin::printed
