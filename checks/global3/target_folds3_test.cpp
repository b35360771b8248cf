// target_folds3.hpp on a bumpy grid of triangles: a vertex dragged across its neighbours turns over exactly the
// triangles whose signed area in the plane changes sign, wherever the target is then rotated (by more than π/2, so
// that the fitted rotation is what tells them apart) or moved; a rigid motion folds none; a blend's poses each
// fold their own; tetrahedra have none.
#include "theory/global3/target_folds3.hpp"
#include "checks/global3/meshes3.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace target_folds3_test {

using namespace affinterp::global3;
using Eigen::Index;

/// An n × n grid of unit squares, each cut into two triangles, on the gently bumpy surface z = 0.1 sin x cos y.
Mesh3 bumpy_grid(int n) {
  Mesh3 mesh;
  mesh.vertices.resize(3, (n + 1) * (n + 1));
  for (int y = 0; y <= n; ++y)
    for (int x = 0; x <= n; ++x) mesh.vertices.col(y * (n + 1) + x) << x, y, 0.1 * std::sin(x) * std::cos(y);
  mesh.elements.resize(3, 2 * n * n);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const int a = y * (n + 1) + x, b = a + 1, c = a + n + 1, d = c + 1, i = 2 * (y * n + x);
      mesh.elements.col(i) << a, b, d;
      mesh.elements.col(i + 1) << a, d, c;
    }
  return mesh;
}

/// The triangles whose signed area in the xy-plane has another sign in `target` than in `source`.
std::vector<Index> flipped_in_plane(const Mesh3& source, const Mesh3& target) {
  const auto signed_area = [](const Mesh3& m, Index i) {
    const Eigen::Vector3d u = m.corner(i, 1) - m.corner(i, 0), v = m.corner(i, 2) - m.corner(i, 0);
    return u.x() * v.y() - u.y() * v.x();
  };
  std::vector<Index> flipped;
  for (Index i = 0; i < source.element_count(); ++i)
    if (signed_area(source, i) * signed_area(target, i) <= 0) flipped.push_back(i);
  return flipped;
}

TEST(TargetFolds3, AreTheTrianglesADraggedVertexTurnsOverWhereverTheTargetIsMoved) {
  const Mesh3 source = bumpy_grid(8);
  Mesh3 dragged = source;
  dragged.vertices.col(4 * 9 + 4).head<2>() += Eigen::Vector2d(1.6, 0.3);  // past its right-hand neighbour
  const std::vector<Index> expected = flipped_in_plane(source, dragged);
  ASSERT_GE(expected.size(), 2u);
  EXPECT_EQ(target_folds(source, dragged), expected);

  const Eigen::Matrix3d turn = Eigen::AngleAxisd(2.5, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  Mesh3 moved = dragged;
  moved.vertices = (turn * dragged.vertices).colwise() + Eigen::Vector3d(5, -2, 7);
  EXPECT_EQ(target_folds(source, moved), expected);

  Mesh3 rigid = source;
  rigid.vertices = turn * source.vertices;
  EXPECT_TRUE(target_folds(source, rigid).empty());
}

TEST(TargetFolds3, NearMarksTheFoldsAndEveryElementSharingAVertexWithOne) {
  const Mesh3 mesh = bumpy_grid(4);
  const std::vector<unsigned char> near = near_folds(mesh, {0});  // triangle (0, 1, 6) of the corner square
  for (Index i = 0; i < mesh.element_count(); ++i) {
    bool shares = false;
    for (int c = 0; c < 3; ++c)
      for (int e = 0; e < 3; ++e) shares |= mesh.elements(c, i) == mesh.elements(e, 0);
    EXPECT_EQ(near[static_cast<std::size_t>(i)] != 0, shares) << i;
  }
}

// A blend's poses: each folds what it folds against the first, and the mask covers every pose's folds at once.
TEST(TargetFolds3, PoseFoldsAreEachPosesAgainstTheFirstAndTheMaskTheirUnion) {
  const Mesh3 source = bumpy_grid(8);
  Mesh3 left = source, right = source;
  left.vertices.col(2 * 9 + 2).head<2>() += Eigen::Vector2d(1.6, 0.3);
  right.vertices.col(6 * 9 + 6).head<2>() += Eigen::Vector2d(-1.6, 0.2);
  const std::vector<Mesh3> poses{source, left, right};
  const std::vector<std::vector<Index>> folds = pose_folds(poses);
  ASSERT_EQ(folds.size(), 3u);
  EXPECT_TRUE(folds[0].empty());
  EXPECT_EQ(folds[1], target_folds(source, left));
  EXPECT_EQ(folds[2], target_folds(source, right));
  std::vector<Index> both = folds[1];
  both.insert(both.end(), folds[2].begin(), folds[2].end());
  EXPECT_EQ(near_pose_folds(poses, folds), near_folds(source, both));
  EXPECT_TRUE(near_pose_folds({source, source}, pose_folds({source, source})).empty());
}

TEST(TargetFolds3, TetrahedraHaveNone) {
  const Mesh3 bar = meshes3::tetrahedral_bar(4, 4);
  EXPECT_TRUE(target_folds(bar, meshes3::twisted(bar, 3.0, 4)).empty());
}

}  // namespace target_folds3_test
