#pragma once
// A triangulated surface in 3D for the deformation application of thesis §3.3–3.4 (Fig. 3.3): source
// and target poses share one triangle list and differ only in their vertices.
#include <Eigen/Core>

namespace affinterp::sym3 {

struct Mesh3 {
  Eigen::Matrix3Xd vertices;   ///< column k is vertex p_k
  Eigen::Matrix3Xi triangles;  ///< column i holds triangle i's vertex indices (0-based)

  Eigen::Index vertex_count() const { return vertices.cols(); }
  Eigen::Index triangle_count() const { return triangles.cols(); }
  Eigen::Vector3d corner(Eigen::Index i, int c) const { return vertices.col(triangles(c, i)); }
};

/// 1→4 midpoint subdivision: every triangle is split at its edge midpoints (shared edges share their
/// midpoint), so the surface is unchanged and the triangle count is multiplied by 4.
Mesh3 midpoint_subdivision(const Mesh3& mesh);

}  // namespace affinterp::sym3
