#pragma once
// The symbolic part of an up-looking LDLᴴ factorisation (Davis, "Direct Methods for Sparse Linear Systems",
// SIAM 2006, §4.1-4.4, and his LDL package): for A = P K Pᵀ, ordered by postordered_amd.hpp, the elimination
// tree, L's structure by columns, and for each row k the columns i < k with L(k, i) ≠ 0 in an order that puts
// every column before its ancestors, each with the slot of L(k, i) in column i. All of it depends on K's
// pattern only, so the numeric factorisation (simplicial_factor.cpp) runs over fixed index lists frame after
// frame instead of finding each row's pattern again.
#include "theory/global/ldl_subtrees.hpp"

#include <Eigen/Core>

#include <optional>
#include <vector>

namespace affinterp::global {

struct LdlSymbolic {
  Eigen::Index n = 0;
  /// The unknown of each pivot: A(k, l) = K(pivot_unknown[k], pivot_unknown[l]).
  std::vector<int> pivot_unknown;
  /// A's lower triangle row by row: row k's entries e in [a_start[k], a_start[k + 1]) lie in column
  /// a_column[e] ≤ k and take K's value number a_source[e] (in K's compressed storage), conjugated where
  /// a_conjugated[e] (an entry of K's lower triangle that lands in A's upper one).
  std::vector<int> a_start, a_column, a_source;
  std::vector<unsigned char> a_conjugated;
  /// L's strictly lower structure by columns, rows ascending.
  std::vector<int> l_start, l_row;
  /// Row k's pattern, entries q in [r_start[k], r_start[k + 1]): the column r_column[q], descendants before
  /// ancestors, and the slot r_slot[q] of L(k, r_column[q]) in l_row.
  std::vector<int> r_start, r_column, r_slot;
  /// L's columns in two groups of subtrees (ldl_subtrees.hpp), whose rows factorise side by side; empty when
  /// the tree has no split worth two threads.
  std::optional<LdlSubtrees> subtrees;
  /// With a split, each top row's entries in A and its pattern ordered by their columns' group: group 0's,
  /// group 1's, then the top's (an order that still puts columns before their ancestors: a group's columns have
  /// no ancestor in the other group and no descendant in the top). A group's part of a top row reaches only
  /// that group's columns and the top's rows, so both groups work through the top rows side by side, leaving
  /// sums for the top's columns and D's share (`partial`: their offset, per group, in a buffer of
  /// `partial_size`), and the top's part of each row follows.
  struct TopRow {
    int a_end[2];  ///< where group g's entries of A's row end (group 0's begin at a_start[k])
    int r_end[2];  ///< where group g's columns of the pattern end (group 0's begin at r_start[k])
    int partial;   ///< offset of the row's sums: one per top column of its pattern, then D's share
  };
  std::vector<TopRow> top_rows;  ///< per top row, in the order of LdlSubtrees::top
  std::size_t partial_size = 0;
};

/// The symbolic factorisation of K's pattern, its lower triangle read from compressed columns (n columns,
/// column j's rows row[s] for s in [start[j], start[j + 1]); entries above the diagonal are skipped).
LdlSymbolic ldl_symbolic(Eigen::Index n, const int* start, const int* row);

}  // namespace affinterp::global
