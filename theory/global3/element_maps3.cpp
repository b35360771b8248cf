#include "theory/global3/element_maps3.hpp"

#include <Eigen/Dense>

#include <cmath>

namespace affinterp::global3 {

using Eigen::Index;

Eigen::Matrix<double, 3, Eigen::Dynamic, 0, 3, 3> element_edges(const Mesh3& mesh, Index i) {
  Eigen::Matrix<double, 3, Eigen::Dynamic, 0, 3, 3> E(3, mesh.corners() - 1);
  for (int c = 1; c < mesh.corners(); ++c) E.col(c - 1) = mesh.corner(i, c) - mesh.corner(i, 0);
  return E;
}

Eigen::Matrix3d element_frame(const Mesh3& mesh, Index i) {
  Eigen::Matrix3d frame;
  if (mesh.kind() == ElementKind::tetrahedron) return element_edges(mesh, i);
  const Eigen::Vector3d e1 = mesh.corner(i, 1) - mesh.corner(i, 0), e2 = mesh.corner(i, 2) - mesh.corner(i, 0);
  const Eigen::Vector3d n = e1.cross(e2);
  frame << e1, e2, n / std::sqrt(n.norm());
  return frame;
}

std::vector<Eigen::Matrix3d> element_maps(const Mesh3& rest, const Mesh3& pose) {
  std::vector<Eigen::Matrix3d> maps(static_cast<std::size_t>(rest.element_count()));
  for (Index i = 0; i < rest.element_count(); ++i)
    maps[static_cast<std::size_t>(i)] = element_frame(pose, i) * element_frame(rest, i).inverse();
  return maps;
}

Eigen::VectorXd element_measures(const Mesh3& mesh) {
  Eigen::VectorXd measure(mesh.element_count());
  for (Index i = 0; i < mesh.element_count(); ++i) {
    const Eigen::Matrix3d frame = element_frame(mesh, i);
    measure[i] =
        mesh.kind() == ElementKind::tetrahedron ? frame.determinant() / 6 : frame.col(0).cross(frame.col(1)).norm() / 2;
  }
  return measure;
}

}  // namespace affinterp::global3
