// The engine's assembly at scale (theory/global/frame_assembly.hpp, rotation_branch.hpp): the sparsity
// pattern built from the vertex stars holds exactly the vertex pairs of the triangles and the sparse
// constraint terms, H(t) and the right-hand side are the same bits on any number of threads, and the dual graph lists
// each triangle's neighbours as its definition says.
#include "theory/global/frame_assembly.hpp"
#include "checks/global/strip.hpp"
#include "experiments/inputs/shapes/random_pair.hpp"
#include "theory/global/constraint_terms.hpp"
#include "theory/global/local_paths.hpp"
#include "theory/global/rotation_branch.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <set>
#include <utility>
#include <vector>

namespace affinterp::global::frame_assembly_test {
namespace {

std::vector<Eigen::Matrix2d> linear_parts(const Mesh& from, const Mesh& to) {
  std::vector<Eigen::Matrix2d> A;
  for (Eigen::Index i = 0; i < from.triangle_count(); ++i) {
    Corners<double> p, q;
    for (int c = 0; c < 3; ++c) p.col(c) = from.corner(i, c), q.col(c) = to.corner(i, c);
    A.push_back(linear_part(p, q));
  }
  return A;
}

Eigen::VectorXd consistent_theta(const Mesh& P, const std::vector<Eigen::Matrix2d>& A) {
  Eigen::VectorXd theta(static_cast<Eigen::Index>(A.size()));
  for (std::size_t i = 0; i < A.size(); ++i) theta[static_cast<Eigen::Index>(i)] = principal_polar_angle(A[i]);
  return consistent_angles(P.triangles, theta);
}

TEST(FrameAssembly, PatternHoldsTheVertexPairsOfTrianglesAndSparseTerms) {
  const Mesh P = testing::strip(7, 3), Q = testing::bent(P, 2.0);
  InterpolationOptions options;
  options.energy = Energy::R;
  options.constraints.pinned = {{5, 1.0}};
  options.constraints.edges = {{0, 30, EdgeDirection::Path::linear, 1.0}};  // vertices of no common triangle
  options.constraints.barycentre = BarycentreLocus{};                       // dense: not in the pattern
  const auto A = linear_parts(P, Q);
  const LocalPaths paths(A, options.homotopy, consistent_theta(P, A));
  const FrameAssembly assembly(P, Q, options, paths, nullptr, constraint_terms(options.constraints, P, Q, paths));
  std::set<std::pair<int, int>> expected = {{30, 0}}, actual;  // (row, column) of the lower triangle
  for (Eigen::Index i = 0; i < P.triangle_count(); ++i)
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        if (P.triangles(a, i) >= P.triangles(b, i)) expected.emplace(P.triangles(a, i), P.triangles(b, i));
  const FrameAssembly::SparseMatrix& pattern = assembly.pattern();
  for (Eigen::Index column = 0; column < pattern.outerSize(); ++column)
    for (FrameAssembly::SparseMatrix::InnerIterator it(pattern, column); it; ++it)
      actual.emplace(static_cast<int>(it.row()), static_cast<int>(it.col()));
  EXPECT_EQ(actual, expected);
}

TEST(FrameAssembly, RightHandSideIsTheSameOnAnyNumberOfThreads) {
  const auto [P, Q] = shapes::random_pair(11, 300);
  for (const Energy energy : {Energy::F, Energy::blend}) {
    InterpolationOptions options;
    options.energy = energy;
    options.symmetric = true;
    options.constraints.pinned = {{0, 1.0}, {3, 1.0}};
    const auto A = linear_parts(P, Q), B = linear_parts(Q, P);
    const Eigen::VectorXd theta = consistent_theta(P, A);
    const LocalPaths forward(A, options.homotopy, theta), reverse(B, options.homotopy, -theta);
    const FrameAssembly assembly(P, Q, options, forward, &reverse,
                                 constraint_terms(options.constraints, P, Q, forward));
    for (const double t : {0.0, 0.3, 1.0}) {
      const Eigen::VectorXcd alone = assembly.right_hand_side_at(t, 1);
      for (const std::size_t threads : {2, 3, 7})
        EXPECT_TRUE(assembly.right_hand_side_at(t, threads) == alone) << to_string(energy) << " t " << t;
    }
  }
}

TEST(FrameAssembly, MatrixIsTheSameOnAnyNumberOfThreads) {
  const auto [P, Q] = shapes::random_pair(13, 300);
  for (const Energy energy : {Energy::R, Energy::S, Energy::blend}) {
    InterpolationOptions options;
    options.energy = energy;
    options.symmetric = true;
    options.constraints.barycentre = BarycentreLocus{};  // grounded: column 0 zeroed after the sums
    const auto A = linear_parts(P, Q), B = linear_parts(Q, P);
    const Eigen::VectorXd theta = consistent_theta(P, A);
    const LocalPaths forward(A, options.homotopy, theta), reverse(B, options.homotopy, -theta);
    const FrameAssembly assembly(P, Q, options, forward, &reverse,
                                 constraint_terms(options.constraints, P, Q, forward));
    FrameAssembly::SparseMatrix alone = assembly.pattern(), H = assembly.pattern();
    for (const double t : {0.0, 0.3, 1.0}) {
      assembly.matrix_at(t, alone, 1);
      for (const std::size_t threads : {2, 3, 7}) {
        assembly.matrix_at(t, H, threads);
        EXPECT_TRUE(Eigen::Map<const Eigen::VectorXcd>(H.valuePtr(), H.nonZeros()) ==
                    Eigen::Map<const Eigen::VectorXcd>(alone.valuePtr(), alone.nonZeros()))
            << to_string(energy) << " t " << t << " threads " << threads;
      }
    }
  }
}

TEST(RotationBranch, DualGraphListsTheTrianglesAcrossEachEdgeInOrder) {
  const auto [P, Q] = shapes::random_pair(5, 60);
  const DualGraph graph = dual_graph(P.triangles);
  ASSERT_EQ(graph.start.size(), static_cast<std::size_t>(P.triangle_count()) + 1);
  for (Eigen::Index i = 0; i < P.triangle_count(); ++i) {
    std::array<std::pair<int, int>, 3> edges;
    for (int c = 0; c < 3; ++c) {
      const int a = P.triangles(c, i), b = P.triangles((c + 1) % 3, i);
      edges[static_cast<std::size_t>(c)] = {std::min(a, b), std::max(a, b)};
    }
    std::sort(edges.begin(), edges.end());
    std::vector<int> expected;  // by the shared edge's (lower, higher) pair, then by index
    for (const auto& [a, b] : edges)
      for (Eigen::Index j = 0; j < P.triangle_count(); ++j)
        if (j != i && (P.triangles.col(j).array() == a).any() && (P.triangles.col(j).array() == b).any())
          expected.push_back(static_cast<int>(j));
    const std::vector<int> actual(graph.neighbour.begin() + graph.start[static_cast<std::size_t>(i)],
                                  graph.neighbour.begin() + graph.start[static_cast<std::size_t>(i) + 1]);
    EXPECT_EQ(actual, expected) << "triangle " << i;
  }
}

}  // namespace
}  // namespace affinterp::global::frame_assembly_test
