// The default gauge (theory/global/gauge.hpp): when it adds an edge, which edge (the same for (Q, P) as for
// (P, Q)), and that the edge is what makes E^R with only a barycentre locus well posed.
#include "theory/global/gauge.hpp"
#include "checks/global/strip.hpp"
#include "theory/global/interpolation.hpp"

#include <gtest/gtest.h>

namespace affinterp::global::gauge_test {
namespace {

/// Three counter-clockwise triangles (0,1,2), (1,3,2), (1,4,3) on p = (0,0), (1,0), (0,1), (1,1), (3,0).
/// The vertex barycentre is (1, 0.4); the centroids (1/3, 1/3), (2/3, 2/3), (5/3, 1/3) lie at squared
/// distances 0.449, 0.182, 0.449 from it, so triangle 1 is nearest and its corners 0, 1 are vertices 1, 3.
Mesh fan() {
  Mesh mesh;
  mesh.vertices.resize(2, 5);
  mesh.triangles.resize(3, 3);
  // clang-format off
  mesh.vertices << 0, 1, 0, 1, 3,
                   0, 0, 1, 1, 0;
  mesh.triangles << 0, 1, 1,
                    1, 3, 4,
                    2, 2, 3;
  // clang-format on
  return mesh;
}

InterpolationOptions with(Energy energy, Constraints constraints = {}) {
  InterpolationOptions options;
  options.energy = energy;
  options.constraints = std::move(constraints);
  return options;
}

TEST(DefaultEdgeDirection, TheEdgeOfTheTriangleNearestTheBarycentre) {
  for (const Energy energy : {Energy::R, Energy::S, Energy::blend}) {
    const auto edge = default_edge_direction(fan(), fan(), with(energy));
    ASSERT_TRUE(edge) << to_string(energy);
    EXPECT_EQ(edge->i, 1);
    EXPECT_EQ(edge->j, 3);
    EXPECT_EQ(edge->path, EdgeDirection::Path::local_homotopy);
    EXPECT_EQ(edge->weight, 1.0);
  }
  // A tie goes to the first triangle: on the square [0, 3]² cut along its diagonal the centroids (2, 1)
  // and (1, 2) are both at squared distance ½ from (3/2, 3/2), exactly.
  Mesh square = testing::unit_square();
  square.vertices *= 3;
  const auto first = default_edge_direction(square, square, with(Energy::R));
  ASSERT_TRUE(first);
  EXPECT_EQ(first->i, 0);
  EXPECT_EQ(first->j, 1);
}

/// The fan with vertex 4 moved to (2, −2) (triangle 2 stays counter-clockwise): barycentre (0.8, 0), spread
/// r² = 44/25, and the centroids' squared distances over r² are 0.187, 0.263, 0.225, so this mesh alone
/// would choose triangle 0; the fan's own are 0.312, 0.127, 0.312 (r² = 1.44). Summed: 0.499, 0.389, 0.536.
Mesh fan_pulled_down() {
  Mesh mesh = fan();
  mesh.vertices.col(4) = Eigen::Vector2d(2, -2);
  return mesh;
}

TEST(DefaultEdgeDirection, ScoresEachTriangleInBothMeshesSoSwappingKeepsTheEdge) {
  const Mesh P = fan(), Q = fan_pulled_down();
  const auto q_alone = default_edge_direction(Q, Q, with(Energy::R));
  ASSERT_TRUE(q_alone);
  EXPECT_EQ(std::pair(q_alone->i, q_alone->j), std::pair(Eigen::Index{0}, Eigen::Index{1}));  // triangle 0's
  for (const auto& [source, target] : {std::pair{P, Q}, std::pair{Q, P}}) {
    const auto edge = default_edge_direction(source, target, with(Energy::R));
    ASSERT_TRUE(edge);
    EXPECT_EQ(std::pair(edge->i, edge->j), std::pair(Eigen::Index{1}, Eigen::Index{3}));  // triangle 1's
  }
}

TEST(DefaultEdgeDirection, NoneWhenTheEnergyOrTheConstraintsFixRotationAndScale) {
  EXPECT_FALSE(default_edge_direction(fan(), fan(), with(Energy::F)));
  EXPECT_FALSE(default_edge_direction(fan(), fan(), with(Energy::R, {{{0, 1.0}}, {}, {}, {}})));
  EXPECT_FALSE(
      default_edge_direction(fan(), fan(), with(Energy::R, {{}, {{2, Eigen::Matrix2Xd::Zero(2, 2), 1.0}}, {}, {}})));
  EXPECT_FALSE(
      default_edge_direction(fan(), fan(), with(Energy::R, {{}, {}, {{0, 2, EdgeDirection::Path::linear, 1.0}}, {}})));
  // A barycentre locus fixes translation only: the edge is still added.
  EXPECT_TRUE(default_edge_direction(fan(), fan(), with(Energy::R, {{}, {}, {}, BarycentreLocus{}})));
}

TEST(DefaultEdgeDirection, MakesASimilarityInvariantEnergyWellPosed) {
  const Mesh P = testing::strip(4, 2), Q = testing::bent(P, 1.0);
  InterpolationOptions options = with(Energy::R, {{}, {}, {}, BarycentreLocus{}});
  EXPECT_THROW(Interpolation(P, Q, options), RefusedProblem);  // the collapse onto the barycentre's path
  options.constraints.edges.push_back(*default_edge_direction(P, Q, options));
  EXPECT_NO_THROW(Interpolation(P, Q, options));
}

}  // namespace
}  // namespace affinterp::global::gauge_test
