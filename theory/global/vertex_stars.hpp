#pragma once
// The star of each vertex, the triangles that contain it, as one array (compressed rows): the incidence
// that the engine's per-vertex sums (the right-hand side of a frame, hermitian_form.hpp), the sparsity
// pattern of H and the dual graph of the rotation branches (rotation_branch.hpp) read.
#include <Eigen/Core>

#include <vector>

namespace affinterp::global {

struct VertexStars {
  /// Triangles triangle[start[k]] … triangle[start[k + 1] − 1] contain vertex k, in increasing order, as their
  /// corners corner[start[k]] … (0, 1 or 2).
  std::vector<int> start, triangle;
  std::vector<unsigned char> corner;
};

/// The stars of vertices 0 … vertex_count − 1 of `triangles` (whose indices lie in that range).
VertexStars vertex_stars(const Eigen::Matrix3Xi& triangles, Eigen::Index vertex_count);

}  // namespace affinterp::global
