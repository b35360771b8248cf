#pragma once
// The two-triangle configuration of thesis §2.3, as the printed matrices imply it. B1's columns are
// v2 − v1, v3 − v1 and B2's are v4 − v3, v4 − v2, with translations fixing p1 = 0 and p4 = p2 + p3: so
// the source is the unit square p1 = (0,0), p2 = (1,0), p3 = (0,1), p4 = (1,1) cut along the shared edge
// p2 p3, with T1 = (p1, p2, p3) and T2 = (p2, p4, p3). The target maps are the printed A1, A2 at o = 0.
#include <ginac/ginac.h>

#include <array>

namespace affinterp::origin {

struct TwoTriangles {
  GiNaC::matrix source{2, 4};  ///< column k − 1 is p_k
  /// 0-based vertex indices of T1 and T2, counter-clockwise in the source.
  std::array<std::array<unsigned, 3>, 2> triangles{{{0, 1, 2}, {1, 3, 2}}};
  std::array<GiNaC::matrix, 2> A;  ///< A1, A2 in world coordinates (every origin at zero)
};

/// The configuration above.
TwoTriangles thesis_two_triangles();

/// The corners of triangle i (0 or 1) among the columns of `vertices` (2×4), as a 2×3 matrix.
GiNaC::matrix triangle_corners(const TwoTriangles& config, unsigned i, const GiNaC::matrix& vertices);

/// B_i: the affine map of triangle i from the source onto the intermediate vertices (columns of the
/// 2×4 `v`), in world coordinates.
GiNaC::matrix intermediate_map(const TwoTriangles& config, unsigned i, const GiNaC::matrix& v);

/// The barycentre of source triangle i, as a column.
GiNaC::matrix barycentre(const TwoTriangles& config, unsigned i);

/// The image A p of the point p (a column) under the 3×3 affine matrix A, as a column.
GiNaC::matrix apply(const GiNaC::matrix& A, const GiNaC::matrix& p);

}  // namespace affinterp::origin
