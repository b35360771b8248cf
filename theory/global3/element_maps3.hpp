#pragma once
// The linear map A_i of each element from one pose to another: the 3D counterpart of Kaji eq. (1).
//  - tetrahedra: the linear part of the affine map taking p0 … p3 to q0 … q3,
//      A_i = [q1−q0 q2−q0 q3−q0][p1−p0 p2−p0 p3−p0]⁻¹;
//  - triangles: Sumner and Popović's deformation gradient (Sumner, Popović, "Deformation transfer for triangle
//    meshes", SIGGRAPH 2004, eq. (3)–(4)), made full rank by a scaled normal as the third column,
//      A_i = [e1' e2' n'/√|n'|][e1 e2 n/√|n|]⁻¹,  e_k = p_k − p0, n = e1 × e2,
//    whose normal column scales like an edge, so that A_i is a similarity when the triangle moves by one.
#include "theory/global3/mesh3.hpp"

#include <Eigen/Core>

#include <vector>

namespace affinterp::global3 {

/// E_i: the element's edges from corner 0 as columns (3 × 2 for a triangle, 3 × 3 for a tetrahedron).
Eigen::Matrix<double, 3, Eigen::Dynamic, 0, 3, 3> element_edges(const Mesh3& mesh, Eigen::Index i);

/// The frame A_i is defined through: [e1 e2 e3] for a tetrahedron, [e1 e2 n/√|n|] for a triangle.
Eigen::Matrix3d element_frame(const Mesh3& mesh, Eigen::Index i);

/// A_i = frame_i(pose) frame_i(rest)⁻¹ for every element (rest and pose compatible and valid:
/// mesh3_validation.hpp).
std::vector<Eigen::Matrix3d> element_maps(const Mesh3& rest, const Mesh3& pose);

/// Each element's area (triangles) or volume (tetrahedra).
Eigen::VectorXd element_measures(const Mesh3& mesh);

}  // namespace affinterp::global3
