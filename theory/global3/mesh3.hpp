#pragma once
// A compatibly meshed 3D shape: vertices p_1 … p_n and elements, all triangles (a surface) or all tetrahedra
// (a solid). One type for both, its element kind read from the element matrix's rows (3 or 4): the engine has one
// code path for either (the element's edge matrix E_i is 3×2 or 3×3; element_maps3.hpp), and a front end passes
// an (m, 3) or (m, 4) index array straight through. Source, target and blend poses share one element list and
// differ only in their vertices.
#include <Eigen/Core>

namespace affinterp::global3 {

enum class ElementKind { triangle, tetrahedron };

struct Mesh3 {
  Eigen::Matrix3Xd vertices;  ///< column k is p_k
  /// Column i holds element i's vertex indices (0-based): 3 rows for triangles, 4 for tetrahedra (p1 − p0,
  /// p2 − p0, p3 − p0 positively oriented: det > 0).
  Eigen::MatrixXi elements;

  Eigen::Index vertex_count() const { return vertices.cols(); }
  Eigen::Index element_count() const { return elements.cols(); }
  /// d + 1 for elements of dimension d.
  int corners() const { return static_cast<int>(elements.rows()); }
  ElementKind kind() const { return elements.rows() == 4 ? ElementKind::tetrahedron : ElementKind::triangle; }
  /// The corner c of element i.
  Eigen::Vector3d corner(Eigen::Index i, int c) const { return vertices.col(elements(c, i)); }
};

}  // namespace affinterp::global3
