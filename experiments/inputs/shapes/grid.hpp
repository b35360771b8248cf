#pragma once
// The triangle list of a grid: cols × rows cells, each split into two counter-clockwise triangles along
// its rising diagonal. Vertex (i, j), 0 ≤ i ≤ cols, 0 ≤ j ≤ rows, has index j (cols + 1) + i.
#include <Eigen/Core>

namespace affinterp::shapes {

inline Eigen::Matrix3Xi grid_triangles(int cols, int rows) {
  Eigen::Matrix3Xi triangles(3, 2 * cols * rows);
  for (int j = 0, t = 0; j < rows; ++j)
    for (int i = 0; i < cols; ++i) {
      const int a = j * (cols + 1) + i, b = a + 1, c = a + cols + 1, d = c + 1;
      triangles.col(t++) = Eigen::Vector3i(a, b, d);
      triangles.col(t++) = Eigen::Vector3i(a, d, c);
    }
  return triangles;
}

}  // namespace affinterp::shapes
