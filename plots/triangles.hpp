#pragma once
// Triangles as gnuplot polygons: each triangle becomes its three vertices, the first again to close it,
// and a blank row, with a value column (time, or the sign of the determinant) for colouring.
#include "plots/figure.hpp"

#include <Eigen/Core>

namespace affinterp::plots {

/// Appends the closed triangle with vertices the columns of `vertices` (2×3), shifted by `offset`, each
/// row (x, y, value).
inline void append_triangle(Table& table, const Eigen::Matrix<double, 2, 3>& vertices, const Eigen::Vector2d& offset,
                            double value) {
  for (int k = 0; k <= 3; ++k) {
    const Eigen::Vector2d p = vertices.col(k % 3) + offset;
    table.push_back({p.x(), p.y(), value});
  }
  table.push_back({});
}

}  // namespace affinterp::plots
