// The split of a factor's columns into two groups of subtrees (theory/global/ldl_subtrees.hpp) and the
// substitution by them (ldl_substitution.hpp): on a matrix whose natural order is a postordered elimination
// tree of two paths joined by a separator, the split finds the two paths, and the solve by subtrees equals the
// plain solve to rounding and itself exactly on one thread and on two. And the ordering that gives Eigen's
// factor such a tree (postordered_amd.hpp): AMD's fill, split into subtrees.
#include "theory/global/ldl_subtrees.hpp"
#include "theory/global/ldl_substitution.hpp"
#include "theory/global/postordered_amd.hpp"

#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>

#include <vector>

namespace affinterp::global::ldl_subtrees_test {
namespace {

/// Two paths of `length` vertices (0 … length − 1 and length … 2 length − 1), each end joined to the three
/// separator vertices that follow them: a Laplacian plus a shift, lower triangle. In this order the
/// elimination tree is each path up to its last vertex, both under the separator, postordered.
Eigen::SparseMatrix<double> two_paths(int length) {
  const int n = 2 * length + 3;
  std::vector<Eigen::Triplet<double>> entries;
  for (int k = 0; k < n; ++k) entries.emplace_back(k, k, 4.0 + 0.01 * k);
  for (const int first : {0, length}) {
    for (int k = first; k + 1 < first + length; ++k) entries.emplace_back(k + 1, k, -1.0);
    for (int s = 2 * length; s < n; ++s) entries.emplace_back(s, first + length - 1, -0.5);
  }
  for (int s = 2 * length; s + 1 < n; ++s) entries.emplace_back(s + 1, s, -1.0);
  Eigen::SparseMatrix<double> K(n, n);
  K.setFromTriplets(entries.begin(), entries.end());
  K.makeCompressed();
  return K;
}

using Ldlt = Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::NaturalOrdering<int>>;

/// L's columns and D of `ldlt` (D copied into `D`: Eigen returns it by value).
LdlColumns<double> columns_of(const Ldlt& ldlt, Eigen::VectorXd& D, const LdlSubtrees* subtrees) {
  const Eigen::SparseMatrix<double>& L = ldlt.matrixL().nestedExpression();
  D = ldlt.vectorD();
  return {L.outerSize(), L.outerIndexPtr(), L.innerIndexPtr(), L.valuePtr(), 0, D.data(), subtrees};
}

TEST(LdlSubtrees, TwoPathsUnderASeparatorAreTheTwoGroups) {
  const int length = 40;
  const Eigen::SparseMatrix<double> K = two_paths(length);
  const Ldlt ldlt(K);
  ASSERT_EQ(ldlt.info(), Eigen::Success);
  Eigen::VectorXd D;
  const LdlColumns<double> L = columns_of(ldlt, D, nullptr);
  const std::optional<LdlSubtrees> split = split_subtrees(L.n, L.start, L.row, 0);
  ASSERT_TRUE(split);
  using Ranges = std::vector<std::pair<int, int>>;
  EXPECT_EQ(split->ranges[0], (Ranges{{0, length - 1}}));
  EXPECT_EQ(split->ranges[1], (Ranges{{length, 2 * length - 1}}));
  EXPECT_EQ(split->top, (std::vector<int>{2 * length, 2 * length + 1, 2 * length + 2}));
  EXPECT_EQ(split->top_index[2 * length + 1], 1);
  EXPECT_EQ(split->top_index[0], -1);
}

TEST(LdlSubtrees, NoSplitOfAPathOrOfATreeNotPostordered) {
  // a path: each group's work is the rest of the path, never below 0.75 of it with the top
  const std::vector<int> path_start = {0, 1, 2, 3, 3}, path_row = {1, 2, 3};
  EXPECT_FALSE(split_subtrees(4, path_start.data(), path_row.data(), 0));
  // 0 → 2, 1 → 3, 2 → 4, 3 → 4: subtree of 3 is {1, 3}, not a range of columns
  const std::vector<int> start = {0, 1, 2, 3, 4, 4}, row = {2, 3, 4, 4};
  EXPECT_FALSE(split_subtrees(5, start.data(), row.data(), 0));
}

TEST(LdlSubtrees, SolveBySubtreesIsThePlainSolveOnOneThreadOrTwo) {
  const Eigen::SparseMatrix<double> K = two_paths(200);
  const Ldlt ldlt(K);
  ASSERT_EQ(ldlt.info(), Eigen::Success);
  Eigen::VectorXd D;
  const LdlColumns<double> plain = columns_of(ldlt, D, nullptr);
  const std::optional<LdlSubtrees> split = split_subtrees(plain.n, plain.start, plain.row, 0);
  ASSERT_TRUE(split);
  const LdlColumns<double> by_subtrees = columns_of(ldlt, D, &*split);
  using Block = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  for (const Eigen::Index columns : {1, 2, 3}) {
    const Block B = Block::Random(K.rows(), columns);
    Block expected = B, one = B, two = B;
    ldl_solve_in_place(plain, expected, 1);
    ldl_solve_in_place(by_subtrees, one, 1);
    ldl_solve_in_place(by_subtrees, two, 2);
    EXPECT_TRUE(one == two) << columns << " columns";
    EXPECT_LT((one - expected).cwiseAbs().maxCoeff(), 1e-14) << columns << " columns";
    const Eigen::SparseMatrix<double> full = K.selfadjointView<Eigen::Lower>();
    EXPECT_LT((Block(full * one) - B).cwiseAbs().maxCoeff(), 1e-13) << columns << " columns";
  }
}

TEST(PostorderedAmd, KeepsAmdsFillAndGivesATreeToSplit) {
  const int side = 60;  // a grid Laplacian plus a shift
  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j) {
      entries.emplace_back(i * side + j, i * side + j, 4.5);
      if (i + 1 < side) entries.emplace_back((i + 1) * side + j, i * side + j, -1.0);
      if (j + 1 < side) entries.emplace_back(i * side + j + 1, i * side + j, -1.0);
    }
  Eigen::SparseMatrix<double> K(side * side, side * side);
  K.setFromTriplets(entries.begin(), entries.end());
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::AMDOrdering<int>> amd(K);
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, PostorderedAmd> postordered(K);
  ASSERT_EQ(postordered.info(), Eigen::Success);
  const Eigen::SparseMatrix<double>& L = postordered.matrixL().nestedExpression();
  EXPECT_EQ(L.nonZeros(), amd.matrixL().nestedExpression().nonZeros());
  EXPECT_TRUE(split_subtrees(L.outerSize(), L.outerIndexPtr(), L.innerIndexPtr(), 0));
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(K.rows(), -1.0, 2.0);
  EXPECT_LT((postordered.solve(b) - amd.solve(b)).cwiseAbs().maxCoeff(), 1e-12);
}

}  // namespace
}  // namespace affinterp::global::ldl_subtrees_test
