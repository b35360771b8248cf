// The 3D deformation pipeline of the thesis's application (theory/deformation/deformation.hpp) on a small
// generated mesh: it reproduces the source at t = 0 and the target at t = 1.
#include "theory/deformation/deformation.hpp"
#include "experiments/inputs/sym3/pose.hpp"
#include "theory/linalg/symmetric.hpp"

#include <gtest/gtest.h>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace affinterp::sym3 {
namespace {

/// The regular octahedron, subdivided twice (128 triangles): a small closed surface.
Mesh3 small_sphere() {
  Mesh3 octahedron;
  octahedron.vertices.resize(3, 6);
  octahedron.vertices << 1, -1, 0, 0, 0, 0,  //
      0, 0, 1, -1, 0, 0,                     //
      0, 0, 0, 0, 1, -1;
  octahedron.triangles.resize(3, 8);
  octahedron.triangles << 0, 2, 1, 3, 2, 0, 3, 1,  //
      2, 1, 3, 0, 0, 3, 1, 2,                      //
      4, 4, 4, 4, 5, 5, 5, 5;
  return midpoint_subdivision(midpoint_subdivision(octahedron));
}

/// exp S by diagonalisation, independent of the algorithms under test.
Eigen::Matrix3d exp_by_diagonalisation(const Eigen::Matrix3d& S) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(S);
  return linalg::congruence(eigen.eigenvectors(), eigen.eigenvalues().array().exp().matrix());
}

/// The largest distance between corresponding vertices (a plain loop: GCC 12 warns falsely on Eigen's
/// AVX-512 reductions over dynamic-size matrices).
double max_distance(const Eigen::Matrix3Xd& a, const Eigen::Matrix3Xd& b) {
  double worst = 0;
  for (Eigen::Index k = 0; k < a.cols(); ++k) worst = std::max(worst, (a.col(k) - b.col(k)).norm());
  return worst;
}

TEST(Deformation3, SubdivisionMultipliesTrianglesByFour) {
  const Mesh3 mesh = small_sphere();
  EXPECT_EQ(mesh.triangle_count(), 128);
  EXPECT_EQ(mesh.vertex_count(), 66);  // Euler: V − E + F = 2 with E = 3F/2
}

TEST(Deformation3, ReproducesSourceAtZeroAndTargetAtOne) {
  const Mesh3 source = small_sphere();
  const Mesh3 target = twisted_pose(source);
  Deformation3 deformation(source, target);
  const SymExpBatch exp = elementwise(exp_by_diagonalisation);
  EXPECT_LT(max_distance(deformation.interpolate(0, exp), source.vertices), 1e-9);
  EXPECT_LT(max_distance(deformation.interpolate(1, exp), target.vertices), 1e-9);
  // Halfway the shape differs from both ends.
  const Eigen::Matrix3Xd half = deformation.interpolate(0.5, exp);
  EXPECT_GT(max_distance(half, source.vertices), 1e-1);
  EXPECT_GT(max_distance(half, target.vertices), 1e-1);
}

TEST(Deformation3, RejectsMismatchedAndDegenerateTargets) {
  const Mesh3 source = small_sphere();
  Mesh3 flat = source;
  flat.vertices.col(flat.triangles(1, 0)) = flat.vertices.col(flat.triangles(0, 0));
  EXPECT_THROW(Deformation3(source, flat), std::invalid_argument);
  Mesh3 other = source;
  other.triangles.col(0).reverseInPlace();
  EXPECT_THROW(Deformation3(source, other), std::invalid_argument);
}

}  // namespace
}  // namespace affinterp::sym3
