// The elements' dual graph (rotation_branches3.hpp) against its definition, element pairs sharing a facet found by
// comparing every pair: on a tube of triangles, a bar of tetrahedra, and a fan of three triangles on one edge (a
// non-manifold edge, each of the three a neighbour of the other two).
#include "checks/global3/meshes3.hpp"
#include "theory/global3/rotation_branches3.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <vector>

namespace dual_graph3_test {

using namespace affinterp::global3;

/// Element j is a neighbour of i when they share all but one vertex (a facet): by comparing every pair.
std::vector<std::vector<int>> by_definition(const Eigen::MatrixXi& elements) {
  std::vector<std::vector<int>> neighbours(static_cast<std::size_t>(elements.cols()));
  for (Eigen::Index i = 0; i < elements.cols(); ++i)
    for (Eigen::Index j = 0; j < elements.cols(); ++j) {
      if (i == j) continue;
      const std::set<int> a(elements.col(i).data(), elements.col(i).data() + elements.rows());
      int shared = 0;
      for (Eigen::Index c = 0; c < elements.rows(); ++c) shared += static_cast<int>(a.count(elements(c, j)));
      if (shared == elements.rows() - 1) neighbours[static_cast<std::size_t>(i)].push_back(static_cast<int>(j));
    }
  return neighbours;
}

void expect_definition(const Eigen::MatrixXi& elements) {
  const DualGraph3 graph = dual_graph3(elements);
  const std::vector<std::vector<int>> expected = by_definition(elements);
  ASSERT_EQ(graph.start.size(), expected.size() + 1);
  for (std::size_t i = 0; i < expected.size(); ++i)
    EXPECT_EQ(std::vector<int>(graph.neighbour.begin() + graph.start[i], graph.neighbour.begin() + graph.start[i + 1]),
              expected[i])
        << "element " << i;
}

TEST(DualGraph3, IsTheElementsSharingAFacet) {
  expect_definition(meshes3::triangle_tube(4, 6, 4).elements);
  expect_definition(meshes3::tetrahedral_bar(4, 4).elements);
  Eigen::MatrixXi fan(3, 4);  // triangles 0, 1, 2 on the edge (0, 1); triangle 3 shares only vertex 0
  fan << 0, 1, 0, 0, 1, 0, 1, 5, 2, 3, 4, 6;
  expect_definition(fan);
}

}  // namespace dual_graph3_test
