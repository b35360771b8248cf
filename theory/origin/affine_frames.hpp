#pragma once
// Affine maps of triangles as 3×3 matrices, and the change of origin T of thesis Def. 2.3.2. Entries are
// GiNaC expressions: symbolic in the origin or the vertices, exact rationals when numeric.
#include <ginac/ginac.h>

namespace affinterp::origin {

/// The 3×3 matrix, last row (0, 0, 1), of the affine map sending the corners a, b, c of a triangle
/// (columns of the 2×3 `corners`) onto the columns of the 2×3 `images` (Kaji eq. (1)).
GiNaC::matrix affine_map(const GiNaC::matrix& corners, const GiNaC::matrix& images);

/// T(A, o) = [[I, o], [0, 1]] A [[I, −o], [0, 1]] (thesis Def. 2.3.2), the map p ↦ A(p − o) + o.
/// So T(A, −o) is A written in coordinates whose origin is the point o.
GiNaC::matrix translate_origin(const GiNaC::matrix& A, const GiNaC::matrix& o);

/// The linear part (upper-left 2×2) and the translation (upper-right 2×1) of a 3×3 affine matrix.
GiNaC::matrix linear_part(const GiNaC::matrix& A);
GiNaC::matrix translation(const GiNaC::matrix& A);

/// The 3×3 affine matrix [[L, t], [0, 1]].
GiNaC::matrix affine_matrix(const GiNaC::matrix& L, const GiNaC::matrix& t);

/// Whether every entry of `M` is zero as a rational function of its symbols.
bool is_zero_matrix(const GiNaC::matrix& M);

}  // namespace affinterp::origin
