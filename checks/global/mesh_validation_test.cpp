// The rules of theory/global/mesh_validation.hpp that the engine applies and the mesh readers do not
// (checks/inputs/mesh_pair_test.cpp covers theirs), and that the engine refuses a bad pair with an
// InvalidMesh, a RefusedProblem.
#include "theory/global/mesh_validation.hpp"
#include "checks/global/strip.hpp"
#include "theory/global/interpolation.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <utility>
#include <vector>

namespace affinterp::global::mesh_validation_test {
namespace {

using testing::unit_square;

InterpolationOptions pinned_corners() {
  InterpolationOptions options;
  options.energy = Energy::F;
  options.constraints.pinned = {{0, 1.0}, {2, 1.0}};
  return options;
}

/// The unit square (triangles (0,1,2), (0,2,3)) with vertex 4 = (2, 2) in no triangle.
Mesh with_lone_vertex() {
  const Mesh square = unit_square();
  Mesh mesh{Eigen::Matrix2Xd(2, 5), square.triangles};
  mesh.vertices << square.vertices, Eigen::Vector2d(2, 2);
  return mesh;
}

TEST(MeshValidation, EveryVertexInOneConnectedPiece) {
  EXPECT_NO_THROW(check_connected(unit_square()));
  EXPECT_THROW(check_connected(with_lone_vertex()), InvalidMesh);
  const Mesh lone = with_lone_vertex();  // plus vertices 5, 6 and a triangle (4, 5, 6) touching nothing
  Mesh two{Eigen::Matrix2Xd(2, 7), Eigen::Matrix3Xi(3, 3)};
  two.vertices << lone.vertices, Eigen::Vector2d(3, 2), Eigen::Vector2d(3, 3);
  two.triangles << lone.triangles, Eigen::Vector3i(4, 5, 6);
  EXPECT_THROW(check_connected(two), InvalidMesh);
}

TEST(MeshValidation, OrientationPreservedIsExactAndRelative) {
  const Mesh P = unit_square();
  Mesh Q = P;
  Q.vertices *= 2;
  EXPECT_NO_THROW(check_orientation_preserved(P, Q));
  Mesh mirrored = Q;  // det A_i < 0
  mirrored.vertices.row(0) *= -1;
  EXPECT_THROW(check_orientation_preserved(P, mirrored), InvalidMesh);
  // Both clockwise: det A_i > 0 still.
  EXPECT_NO_THROW(check_orientation_preserved(mirrored, mirrored));
  // A sliver far below is_degenerate's tolerance passes: only an exact zero is refused.
  Mesh sliver = P;
  sliver.vertices.col(2) << 1, 1e-300;
  sliver.vertices.col(3) << 0, 1e-300;
  EXPECT_TRUE(is_degenerate(sliver, 0));
  EXPECT_NO_THROW(check_orientation_preserved(sliver, sliver));
  Mesh flat = P;
  flat.vertices.col(2) << 1, 0;
  EXPECT_THROW(check_orientation_preserved(flat, Q), InvalidMesh);
}

TEST(MeshValidation, TheEngineRefusesAnInvalidPairWithInvalidMesh) {
  const Mesh P = unit_square();
  Mesh Q = P;
  Q.vertices *= 2;
  EXPECT_NO_THROW(Interpolation(P, Q, pinned_corners()));
  Mesh nan = Q;
  nan.vertices(0, 1) = std::numeric_limits<double>::quiet_NaN();
  Mesh other = Q;
  other.triangles.col(1) << 0, 3, 2;
  const Mesh lone = with_lone_vertex();
  Mesh lone_target = lone;
  lone_target.vertices *= 2;
  Mesh mirrored = Q;
  mirrored.vertices.row(0) *= -1;
  const std::vector<std::pair<Mesh, Mesh>> invalid = {{P, nan}, {P, other}, {lone, lone_target}, {P, mirrored}};
  for (const auto& [source, target] : invalid)
    EXPECT_THROW(Interpolation(source, target, pinned_corners()), InvalidMesh);
}

}  // namespace
}  // namespace affinterp::global::mesh_validation_test
