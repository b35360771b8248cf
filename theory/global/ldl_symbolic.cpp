#include "theory/global/ldl_symbolic.hpp"

#include "theory/global/postordered_amd.hpp"

#include <Eigen/SparseCore>

#include <algorithm>
#include <numeric>

namespace affinterp::global {
namespace {

/// P by postordered AMD on the full symmetric pattern of K (its lower triangle given).
std::vector<int> amd_pivots(Eigen::Index n, const int* start, const int* row) {
  std::vector<Eigen::Triplet<double>> entries;
  for (int j = 0; j < n; ++j)
    for (int s = start[j]; s < start[j + 1]; ++s)
      if (const int i = row[s]; i >= j) {
        entries.emplace_back(i, j, 1.0);
        if (i != j) entries.emplace_back(j, i, 1.0);
      }
  Eigen::SparseMatrix<double> full(n, n);
  full.setFromTriplets(entries.begin(), entries.end());
  PostorderedAmd::PermutationType P;
  PostorderedAmd()(full, P);
  std::vector<int> pivots(static_cast<std::size_t>(n));
  if (P.size() == n)
    std::copy(P.indices().data(), P.indices().data() + n, pivots.begin());
  else
    std::iota(pivots.begin(), pivots.end(), 0);
  return pivots;
}

}  // namespace

LdlSymbolic ldl_symbolic(Eigen::Index n, const int* start, const int* row) {
  const auto size = static_cast<std::size_t>(n);
  LdlSymbolic s;
  s.n = n;
  s.pivot_unknown = amd_pivots(n, start, row);
  std::vector<int> position(size);
  for (std::size_t k = 0; k < size; ++k) position[static_cast<std::size_t>(s.pivot_unknown[k])] = static_cast<int>(k);

  // A's lower triangle by rows: K(i, j), i ≥ j, is A(a, b) with a, b the positions of i, j; where a < b it is
  // stored as A(b, a) = conj K(i, j)
  auto for_each_entry = [&](auto&& visit) {
    for (int j = 0; j < n; ++j)
      for (int e = start[j]; e < start[j + 1]; ++e)
        if (row[e] >= j) visit(e, position[static_cast<std::size_t>(row[e])], position[static_cast<std::size_t>(j)]);
  };
  s.a_start.assign(size + 1, 0);
  for_each_entry([&](int, int a, int b) { ++s.a_start[static_cast<std::size_t>(std::max(a, b)) + 1]; });
  std::partial_sum(s.a_start.begin(), s.a_start.end(), s.a_start.begin());
  const auto entries = static_cast<std::size_t>(s.a_start[size]);
  s.a_column.resize(entries), s.a_source.resize(entries), s.a_conjugated.resize(entries);
  std::vector<int> filled(s.a_start.begin(), s.a_start.end() - 1);
  for_each_entry([&](int e, int a, int b) {
    const auto slot = static_cast<std::size_t>(filled[static_cast<std::size_t>(std::max(a, b))]++);
    s.a_column[slot] = std::min(a, b), s.a_source[slot] = e, s.a_conjugated[slot] = a < b;
  });

  // Row k's pattern is the set of columns reached from A's row k up the elimination tree, whose parents are
  // set on the way (Davis §4.1, ereach; LDL's ldl_symbolic): each path pushed as found, later paths before
  // earlier ones, so that every column comes before its ancestors
  std::vector<int> parent(size, -1), flag(size, -1), count(size, 0), path(size), pattern(size);
  s.r_start.assign(1, 0);
  for (int k = 0; k < n; ++k) {
    flag[static_cast<std::size_t>(k)] = k;
    std::size_t top = size;
    for (int e = s.a_start[static_cast<std::size_t>(k)]; e < s.a_start[static_cast<std::size_t>(k) + 1]; ++e) {
      std::size_t length = 0;
      for (int i = s.a_column[static_cast<std::size_t>(e)]; flag[static_cast<std::size_t>(i)] != k;
           i = parent[static_cast<std::size_t>(i)]) {
        if (parent[static_cast<std::size_t>(i)] < 0) parent[static_cast<std::size_t>(i)] = k;
        path[length++] = i, flag[static_cast<std::size_t>(i)] = k;
      }
      while (length > 0) pattern[--top] = path[--length];
    }
    for (std::size_t q = top; q < size; ++q) ++count[static_cast<std::size_t>(pattern[q])];
    s.r_column.insert(s.r_column.end(), pattern.begin() + static_cast<std::ptrdiff_t>(top), pattern.end());
    s.r_start.push_back(static_cast<int>(s.r_column.size()));
  }

  // L's columns fill in row order, so that rows ascend in each
  s.l_start.assign(size + 1, 0);
  std::partial_sum(count.begin(), count.end(), s.l_start.begin() + 1);
  s.l_row.resize(s.r_column.size()), s.r_slot.resize(s.r_column.size());
  filled.assign(s.l_start.begin(), s.l_start.end() - 1);
  for (int k = 0; k < n; ++k)
    for (int q = s.r_start[static_cast<std::size_t>(k)]; q < s.r_start[static_cast<std::size_t>(k) + 1]; ++q) {
      const int slot = filled[static_cast<std::size_t>(s.r_column[static_cast<std::size_t>(q)])]++;
      s.l_row[static_cast<std::size_t>(slot)] = k, s.r_slot[static_cast<std::size_t>(q)] = slot;
    }
  s.subtrees = split_subtrees(n, s.l_start.data(), s.l_row.data(), 0);
  return s;
}

}  // namespace affinterp::global
