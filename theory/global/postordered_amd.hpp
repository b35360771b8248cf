#pragma once
// The ordering of the simplicial factor (ldl_symbolic.hpp): Eigen's approximate minimum degree (AMD) followed
// by a postorder of the permuted matrix's elimination tree (Liu, "The role of elimination trees in sparse
// factorization", SIMAX 1990, §3-4). A postorder is an equivalent ordering — the same fill and the same
// operations — in which every subtree is a range of columns, so that the factor's rows and its solve split
// into two groups of subtrees for two threads (ldl_subtrees.hpp), as CHOLMOD's postordered factor does.
#include <Eigen/OrderingMethods>
#include <Eigen/SparseCore>

#include <vector>

namespace affinterp::global {

struct PostorderedAmd {
  using PermutationType = Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int>;

  /// As Eigen's orderings: `A` the full symmetric pattern, `perm` such that perm.indices()[k] is the row of A
  /// numbered k.
  template <class MatrixType>
  void operator()(const MatrixType& A, PermutationType& perm) const {
    Eigen::AMDOrdering<int>()(A, perm);
    const int n = static_cast<int>(A.cols());
    if (perm.size() != n) return;
    std::vector<int> position(static_cast<std::size_t>(n));  // old row → its number in AMD's order
    for (int k = 0; k < n; ++k) position[static_cast<std::size_t>(perm.indices()[k])] = k;
    // the elimination tree of the permuted matrix, by ancestors with path compression (Liu, Algorithm 4.2)
    std::vector<int> parent(static_cast<std::size_t>(n), -1), ancestor(static_cast<std::size_t>(n), -1);
    for (int k = 0; k < n; ++k)
      for (typename MatrixType::InnerIterator it(A, perm.indices()[k]); it; ++it)
        for (int i = position[static_cast<std::size_t>(it.index())]; i < k;) {
          const int next = ancestor[static_cast<std::size_t>(i)];
          ancestor[static_cast<std::size_t>(i)] = k;
          if (next < 0) {
            parent[static_cast<std::size_t>(i)] = k;
            break;
          }
          i = next;
        }
    // a depth-first postorder, roots and children in ascending order
    std::vector<int> child_start(static_cast<std::size_t>(n) + 1, 0), child(static_cast<std::size_t>(n));
    for (const int p : parent)
      if (p >= 0) ++child_start[static_cast<std::size_t>(p) + 1];
    for (std::size_t j = 0; j < static_cast<std::size_t>(n); ++j) child_start[j + 1] += child_start[j];
    std::vector<int> filled(child_start.begin(), child_start.end() - 1);
    for (int j = 0; j < n; ++j)
      if (const int p = parent[static_cast<std::size_t>(j)]; p >= 0)
        child[static_cast<std::size_t>(filled[static_cast<std::size_t>(p)]++)] = j;
    std::vector<int> order, stack, next_child(child_start.begin(), child_start.end() - 1);
    order.reserve(static_cast<std::size_t>(n));
    for (int root = 0; root < n; ++root) {
      if (parent[static_cast<std::size_t>(root)] >= 0) continue;
      stack.assign(1, root);
      while (!stack.empty()) {
        const auto v = static_cast<std::size_t>(stack.back());
        if (next_child[v] < child_start[v + 1]) {
          stack.push_back(child[static_cast<std::size_t>(next_child[v]++)]);
        } else {
          order.push_back(stack.back());
          stack.pop_back();
        }
      }
    }
    PermutationType amd = perm;
    for (int k = 0; k < n; ++k) perm.indices()[k] = amd.indices()[order[static_cast<std::size_t>(k)]];
  }
};

}  // namespace affinterp::global
