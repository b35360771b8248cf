#pragma once
// The solve of L D Lᴴ y = x by substitution, for a unit lower triangular L stored by columns (compressed
// sparse columns, as Eigen's SimplicialLDLT and CHOLMOD's simplicial LDLᴴ store it) and all right-hand sides
// at once, one row of Y per unknown, so that each entry of L is read once for every column: forward over L's
// columns, the diagonal, backward (sparse_factor.hpp's back-ends; internal to theory/global). Where L's
// columns are split into two groups of subtrees (ldl_subtrees.hpp), the groups' substitutions run side by
// side.
#include "theory/global/ldl_subtrees.hpp"

#include <Eigen/Core>

#include <array>
#include <ranges>
#include <type_traits>
#include <vector>

namespace affinterp::global {

/// The factor's arrays: column j's strictly lower entries are row[s], value[s] for s in
/// [start[j] + skip, start[j + 1]), skip = 1 where a column stores its diagonal first (CHOLMOD), 0 where it
/// does not (Eigen); D[j] the pivots; and, if not null, the split of its columns into two groups of subtrees.
template <class Scalar>
struct LdlColumns {
  Eigen::Index n;
  const int* start;
  const int* row;
  const Scalar* value;
  int skip;
  const Scalar* D;
  const LdlSubtrees* subtrees = nullptr;
};

/// The substitution's steps on y (n × m, row-major), over the columns `js` of L (any range of column indices,
/// in the order given). `columns` is a template argument for the frames' one, two and three right-hand sides, so that
/// the loops over a row are unrolled and row j's entries stay in registers while its column of L is applied
/// (L is strictly lower there: no entry is row j); 0 is any count m. y aliases none of L's arrays, so that its
/// stores do not force L's loads to be repeated.
namespace ldl_steps {

template <int columns, class Scalar>
using Row = Eigen::Matrix<Scalar, 1, (columns > 0 ? columns : Eigen::Dynamic)>;

/// Forward, L y = P x: each column's rows updated by the column's entry.
template <int columns, class Scalar, class Columns>
void forward(const LdlColumns<Scalar>& L, Scalar* __restrict y, Eigen::Index m, const Columns& js) {
  if constexpr (columns > 0) m = columns;
  const int* __restrict row = L.row;
  const Scalar* __restrict value = L.value;
  Row<columns, Scalar> y_j(m);
  for (const Eigen::Index j : js) {
    for (Eigen::Index c = 0; c < m; ++c) y_j[c] = y[j * m + c];
    for (int s = L.start[j] + L.skip; s < L.start[j + 1]; ++s)
      for (Eigen::Index c = 0; c < m; ++c) y[row[s] * m + c] -= value[s] * y_j[c];
  }
}

/// Forward over the columns of the subtree whose root is `root`: their rows up to the root updated in y, those
/// above it (the top's) summed into top_sum, one row of it per top row (LdlSubtrees::top_index), for the
/// caller to subtract.
template <int columns, class Scalar, class Columns>
void forward_in_subtree(const LdlColumns<Scalar>& L, Scalar* __restrict y, Eigen::Index m, const Columns& js,
                        Eigen::Index root, Scalar* __restrict top_sum, const int* __restrict top_index) {
  if constexpr (columns > 0) m = columns;
  const int* __restrict row = L.row;
  const Scalar* __restrict value = L.value;
  Row<columns, Scalar> y_j(m);
  for (const Eigen::Index j : js) {
    for (Eigen::Index c = 0; c < m; ++c) y_j[c] = y[j * m + c];
    for (int s = L.start[j] + L.skip; s < L.start[j + 1]; ++s)
      if (row[s] <= root)
        for (Eigen::Index c = 0; c < m; ++c) y[row[s] * m + c] -= value[s] * y_j[c];
      else
        for (Eigen::Index c = 0; c < m; ++c) top_sum[top_index[row[s]] * m + c] += value[s] * y_j[c];
  }
}

/// Backward, Lᴴ w = D⁻¹ y: each column's entry from rows that are final.
template <int columns, class Scalar, class Columns>
void backward(const LdlColumns<Scalar>& L, Scalar* __restrict y, Eigen::Index m, const Columns& js) {
  if constexpr (columns > 0) m = columns;
  const int* __restrict row = L.row;
  const Scalar* __restrict value = L.value;
  Row<columns, Scalar> y_j(m);
  for (const Eigen::Index j : js) {
    for (Eigen::Index c = 0; c < m; ++c) y_j[c] = y[j * m + c];
    for (int s = L.start[j] + L.skip; s < L.start[j + 1]; ++s)
      for (Eigen::Index c = 0; c < m; ++c) y_j[c] -= Eigen::numext::conj(value[s]) * y[row[s] * m + c];
    for (Eigen::Index c = 0; c < m; ++c) y[j * m + c] = y_j[c];
  }
}

template <class Scalar>
void diagonal(const LdlColumns<Scalar>& L, Scalar* __restrict y, Eigen::Index m) {
  for (Eigen::Index j = 0; j < L.n; ++j)
    for (Eigen::Index c = 0; c < m; ++c) y[j * m + c] /= L.D[j];
}

/// Columns first … last, ascending, and last … first, descending.
inline auto up(Eigen::Index first, Eigen::Index last) { return std::views::iota(first, last + 1); }
inline auto down(Eigen::Index first, Eigen::Index last) {
  return std::views::iota(first, last + 1) | std::views::reverse;
}

}  // namespace ldl_steps

/// Y ← (L D Lᴴ)⁻¹ Y in place, column after column of L: forward, the diagonal, backward.
template <int columns, class Scalar, class Block>
void ldl_substitute(const LdlColumns<Scalar>& L, Block& Y) {
  using namespace ldl_steps;
  forward<columns>(L, Y.data(), Y.cols(), up(0, L.n - 1));
  diagonal(L, Y.data(), Y.cols());
  backward<columns>(L, Y.data(), Y.cols(), down(0, L.n - 1));
}

/// Y ← (L D Lᴴ)⁻¹ Y in place by L's two groups of subtrees (L.subtrees), each on a thread of its own when
/// `threads` > 1: forward, each group's columns with their sums into the top's rows kept apart, then those sums
/// (group 0's, then group 1's) and the top's columns; the diagonal; backward, the top's columns, then each
/// group's. Every row sees the same operations in the same order whatever `threads`, so Y is the same.
template <int columns, class Scalar, class Block>
void ldl_substitute_by_subtrees(const LdlColumns<Scalar>& L, Block& Y, std::size_t threads) {
  using namespace ldl_steps;
  const LdlSubtrees& split = *L.subtrees;
  Scalar* y = Y.data();
  const Eigen::Index m = Y.cols();
  std::array<std::vector<Scalar>, 2> top_sum;
  for_each_group(threads, [&](std::size_t g) {
    top_sum[g].assign(split.top.size() * static_cast<std::size_t>(m), Scalar(0));
    for (const auto& [first, root] : split.ranges[g])
      forward_in_subtree<columns>(L, y, m, up(first, root), root, top_sum[g].data(), split.top_index.data());
  });
  for (std::size_t t = 0; t < split.top.size(); ++t)
    for (Eigen::Index c = 0; c < m; ++c)
      for (const std::vector<Scalar>& sum : top_sum)
        y[split.top[t] * m + c] -= sum[t * static_cast<std::size_t>(m) + c];
  forward<columns>(L, y, m, split.top);
  diagonal(L, y, m);
  backward<columns>(L, y, m, split.top | std::views::reverse);
  for_each_group(threads, [&](std::size_t g) {
    for (const auto& [first, root] : split.ranges[g] | std::views::reverse)
      backward<columns>(L, y, m, down(first, root));
  });
}

/// Y ← (L D Lᴴ)⁻¹ Y for any number of columns, the one-, two- and three-column cases (2D frames, 3D frames)
/// unrolled; by L's subtrees when
/// it has them, on up to `threads` threads.
template <class Scalar, class Block>
void ldl_solve_in_place(const LdlColumns<Scalar>& L, Block& Y, std::size_t threads) {
  auto solve = [&](auto columns) {
    constexpr int m = decltype(columns)::value;
    if (L.subtrees)
      ldl_substitute_by_subtrees<m>(L, Y, threads);
    else
      ldl_substitute<m>(L, Y);
  };
  if (Y.cols() == 1)
    solve(std::integral_constant<int, 1>{});
  else if (Y.cols() == 2)
    solve(std::integral_constant<int, 2>{});
  else if (Y.cols() == 3)
    solve(std::integral_constant<int, 3>{});
  else
    solve(std::integral_constant<int, 0>{});
}

/// X ← (P L D Lᴴ Pᵀ)⁻¹ X, perm[k] the unknown of pivot k (null: none): X's rows gathered into pivot order,
/// solved as ldl_solve_in_place, scattered back. Row by row, where Eigen's product by a permutation took a visible
/// share of an E^F frame.
template <class Scalar, class Block>
void ldl_solve_permuted(const LdlColumns<Scalar>& L, const int* perm, Block& X, std::size_t threads) {
  if (!perm) return ldl_solve_in_place(L, X, threads);
  Block Y(X.rows(), X.cols());
  for (Eigen::Index k = 0; k < X.rows(); ++k) Y.row(k) = X.row(perm[k]);
  ldl_solve_in_place(L, Y, threads);
  for (Eigen::Index k = 0; k < X.rows(); ++k) X.row(perm[k]) = Y.row(k);
}

}  // namespace affinterp::global
