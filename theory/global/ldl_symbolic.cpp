#include "theory/global/ldl_symbolic.hpp"

#include "theory/global/postordered_amd.hpp"

#include <Eigen/SparseCore>

#include <algorithm>
#include <array>
#include <numeric>
#include <type_traits>

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

/// Each top row's entries of A and pattern ordered by group, group 0's, group 1's, the top's, each kept in its
/// order (LdlSymbolic::TopRow).
void order_top_rows(LdlSymbolic& s) {
  const LdlSubtrees& split = *s.subtrees;
  std::vector<int> group(static_cast<std::size_t>(s.n), 2);  // 2: the top
  for (int g = 0; g < 2; ++g)
    for (const auto& [first, root] : split.ranges[static_cast<std::size_t>(g)])
      std::fill(group.begin() + first, group.begin() + root + 1, g);
  // stably by the group of each entry's column, returning where groups 0 and 1 end
  auto order = [&](int begin, int end, const std::vector<int>& column, auto&&... parallel) {
    std::vector<int> entries(static_cast<std::size_t>(end - begin));
    std::iota(entries.begin(), entries.end(), begin);
    std::stable_sort(entries.begin(), entries.end(), [&](int a, int b) {
      return group[static_cast<std::size_t>(column[static_cast<std::size_t>(a)])] <
             group[static_cast<std::size_t>(column[static_cast<std::size_t>(b)])];
    });
    auto permute = [&](auto& values) {  // the row's entries only: a copy of the whole array per row is quadratic
      const std::vector<typename std::decay_t<decltype(values)>::value_type> row(values.begin() + begin,
                                                                                 values.begin() + end);
      for (std::size_t e = 0; e < entries.size(); ++e)
        values[static_cast<std::size_t>(begin) + e] = row[static_cast<std::size_t>(entries[e] - begin)];
    };
    (permute(parallel), ...);
    std::array<int, 2> ends{begin, begin};
    for (int e = begin; e < end; ++e)
      for (int g = 0; g < 2; ++g)
        if (group[static_cast<std::size_t>(column[static_cast<std::size_t>(e)])] <= g)
          ends[static_cast<std::size_t>(g)] = e + 1;
    return ends;
  };
  for (const int k : split.top) {
    const auto row = static_cast<std::size_t>(k);
    const std::array<int, 2> a_end =
        order(s.a_start[row], s.a_start[row + 1], s.a_column, s.a_source, s.a_conjugated, s.a_column);
    const std::array<int, 2> r_end = order(s.r_start[row], s.r_start[row + 1], s.r_column, s.r_slot, s.r_column);
    s.top_rows.push_back({{a_end[0], a_end[1]}, {r_end[0], r_end[1]}, static_cast<int>(s.partial_size)});
    s.partial_size += static_cast<std::size_t>(s.r_start[row + 1] - r_end[1]) + 1;
  }
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
  if (s.subtrees) order_top_rows(s);
  return s;
}

}  // namespace affinterp::global
