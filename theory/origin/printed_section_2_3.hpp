#pragma once
// The formulas printed in thesis §2.3, transcribed as they stand, in the symbols x, y (the origin o) and
// v_1 … v_4 of symbols(). Nothing here is computed: these are the statements under test.
#include <ginac/ginac.h>

namespace affinterp::origin::printed {

/// How to read a formula with an evident typo.
enum class Reading {
  as_printed,  ///< the characters as they stand
  intended,    ///< with the evident typo repaired (stated where it applies)
};

/// A1 and A2 (3×3, in x, y), the affine maps of the first and second triangle to the target.
GiNaC::matrix A1();
GiNaC::matrix A2();

/// B1 (3×3, in x, y and v), the affine map of the first triangle to the intermediate configuration,
/// with b11, b12 as printed.
GiNaC::matrix B1();

/// B2 with b21, b22. As printed they read "−x + v2x + v3x − v4x x(−v3x + v4x) + y(−v2x + v4x)", a
/// product v4x·x·(…); the intended reading has the "+" that the juxtaposition lost:
/// "−x + v2x + v3x − v4x + x(−v3x + v4x) + y(−v2x + v4x)" (likewise for b22 with y-coordinates).
GiNaC::matrix B2(Reading reading);

/// The printed minimiser, relations v_kx == …, v_ky == … in the order of symbols().unknowns.
/// (The thesis prints "v3x = 2" twice; both lines agree.)
GiNaC::lst minimiser();

/// min_{B1, B2} E2(A1, A2, B1, B2, o, o) = (2 + (x − 1)x + (y − 1)y) / (x² + 2xy + y² − 2x − 2y + 3).
GiNaC::ex min_E2();

/// The left side of the printed conic x² − 4xy + y² + x + y − 1/4 = 0.
GiNaC::ex conic();

}  // namespace affinterp::origin::printed
