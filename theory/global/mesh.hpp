#pragma once
// A compatibly triangulated 2D shape (Kaji §2): vertices p_1 … p_n and triangles τ_1 … τ_m. Source and
// target shapes share one triangle list and differ only in their vertices.
#include <Eigen/Core>

namespace affinterp::global {

struct Mesh {
  Eigen::Matrix2Xd vertices;   ///< column k is p_k
  Eigen::Matrix3Xi triangles;  ///< column i holds τ_i's vertex indices (0-based), counter-clockwise

  Eigen::Index vertex_count() const { return vertices.cols(); }
  Eigen::Index triangle_count() const { return triangles.cols(); }
  /// The corner c ∈ {0, 1, 2} of triangle i.
  Eigen::Vector2d corner(Eigen::Index i, int c) const { return vertices.col(triangles(c, i)); }
  /// Twice the signed area of triangle i: positive when its corners run counter-clockwise.
  double doubled_signed_area(Eigen::Index i) const {
    const Eigen::Vector2d e1 = corner(i, 1) - corner(i, 0), e2 = corner(i, 2) - corner(i, 0);
    return e1.x() * e2.y() - e1.y() * e2.x();
  }
};

}  // namespace affinterp::global
