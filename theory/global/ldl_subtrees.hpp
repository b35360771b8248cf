#pragma once
// Two groups of a factor L's columns whose substitutions can run side by side (ldl_substitution.hpp): whole
// subtrees of L's elimination tree, the parent of column j being the smallest row below the diagonal in j's
// structure (Liu, "The role of elimination trees in sparse factorization", SIMAX 1990). Column j's entries
// lie in rows that are ancestors of j, so a subtree's columns touch rows of their own subtree or of its
// ancestors only; the ancestors of the chosen subtrees (the "top") are substituted after them going forward
// and before them going back. In a postordered tree (CHOLMOD's, and Eigen's ordered by postordered_amd.hpp)
// each subtree is one range of columns.
#include <Eigen/Core>

#include <array>
#include <functional>
#include <optional>
#include <utility>
#include <vector>

namespace affinterp::global {

struct LdlSubtrees {
  /// Per group, its subtrees as column ranges [first, last] (last is the subtree's root), ascending.
  std::array<std::vector<std::pair<int, int>>, 2> ranges;
  /// The columns in no chosen subtree, ascending.
  std::vector<int> top;
  /// For each column, its index in `top`, or −1.
  std::vector<int> top_index;
};

/// The split of L's columns between two groups that balances their work (L's entries), the top counted with
/// both: chosen from the root down, a subtree at a time, by a greedy packing whose steps are the same on every
/// machine. L is given by its structure (compressed columns, column j's strictly lower entries at row[s] for s
/// in [start[j] + skip, start[j + 1])), as the symbolic factorisation made it: every structural entry, so that
/// the smallest row of each column is its parent. Empty when the tree is not postordered, or when no split
/// leaves the larger group with its top below 0.75 of the work.
std::optional<LdlSubtrees> split_subtrees(Eigen::Index n, const int* start, const int* row, int skip);

/// step(0) and step(1), the two groups' work, side by side when `threads` > 1, else one after the other.
void for_each_group(std::size_t threads, const std::function<void(std::size_t)>& step);

}  // namespace affinterp::global
