#pragma once
// The solve of L D Lᴴ y = x by substitution, for a unit lower triangular L stored by columns (compressed
// sparse columns, as Eigen's SimplicialLDLT and CHOLMOD's simplicial LDLᴴ store it) and all right-hand sides
// at once, one row of Y per unknown, so that each entry of L is read once for every column: forward over L's
// columns, the diagonal, backward (sparse_factor.hpp's back-ends; internal to theory/global).
#include <Eigen/Core>

namespace affinterp::global {

/// The factor's arrays: column j's strictly lower entries are row[s], value[s] for s in
/// [start[j] + skip, start[j + 1]), skip = 1 where a column stores its diagonal first (CHOLMOD), 0 where it
/// does not (Eigen); D[j] the pivots.
template <class Scalar>
struct LdlColumns {
  Eigen::Index n;
  const int* start;
  const int* row;
  const Scalar* value;
  int skip;
  const Scalar* D;
};

/// Y ← (L D Lᴴ)⁻¹ Y in place, Y n × columns and row-major. `columns` is a template argument for the frames'
/// one and two right-hand sides, so that the inner loops over a row are unrolled and row j's entries stay in
/// registers while its column of L is applied (L is strictly lower there: no entry is row j); 0 is any count,
/// read from Y.
template <int columns, class Scalar, class Block>
void ldl_substitute(const LdlColumns<Scalar>& L, Block& Y) {
  constexpr int fixed = columns > 0 ? columns : Eigen::Dynamic;
  const Eigen::Index m = columns > 0 ? columns : Y.cols();
  Scalar* __restrict y = Y.data();  // no alias of L's arrays: its loads need not be repeated after each store
  const int* __restrict start = L.start;
  const int* __restrict row = L.row;
  const Scalar* __restrict value = L.value;
  Eigen::Matrix<Scalar, 1, fixed> y_j(m);
  for (Eigen::Index j = 0; j < L.n; ++j) {  // L y = P x
    for (Eigen::Index c = 0; c < m; ++c) y_j[c] = y[j * m + c];
    for (int s = start[j] + L.skip; s < start[j + 1]; ++s)
      for (Eigen::Index c = 0; c < m; ++c) y[row[s] * m + c] -= value[s] * y_j[c];
  }
  for (Eigen::Index j = 0; j < L.n; ++j)
    for (Eigen::Index c = 0; c < m; ++c) y[j * m + c] /= L.D[j];
  for (Eigen::Index j = L.n - 1; j >= 0; --j) {  // Lᴴ w = D⁻¹ y
    for (Eigen::Index c = 0; c < m; ++c) y_j[c] = y[j * m + c];
    for (int s = start[j] + L.skip; s < start[j + 1]; ++s)
      for (Eigen::Index c = 0; c < m; ++c) y_j[c] -= Eigen::numext::conj(value[s]) * y[row[s] * m + c];
    for (Eigen::Index c = 0; c < m; ++c) y[j * m + c] = y_j[c];
  }
}

/// Y ← (L D Lᴴ)⁻¹ Y for any number of columns, the one- and two-column cases unrolled.
template <class Scalar, class Block>
void ldl_solve_in_place(const LdlColumns<Scalar>& L, Block& Y) {
  if (Y.cols() == 1)
    ldl_substitute<1>(L, Y);
  else if (Y.cols() == 2)
    ldl_substitute<2>(L, Y);
  else
    ldl_substitute<0>(L, Y);
}

}  // namespace affinterp::global
