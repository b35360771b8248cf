#pragma once
// Small test shapes: a rectangular strip of triangles and its bend around an arc, built in the tests
// themselves so that they need no files.
#include "experiments/inputs/shapes/grid.hpp"
#include "theory/global/mesh.hpp"

#include <cmath>

namespace affinterp::global::testing {

/// Two counter-clockwise triangles on the unit square: (0,1,2) and (0,2,3).
inline Mesh unit_square() {
  Mesh mesh;
  mesh.vertices.resize(2, 4);
  mesh.vertices << 0, 1, 1, 0, 0, 0, 1, 1;
  mesh.triangles.resize(3, 2);
  mesh.triangles << 0, 0, 1, 2, 2, 3;
  return mesh;
}

/// A cols × rows grid of unit squares, each split into two counter-clockwise triangles.
inline Mesh strip(int cols, int rows) {
  Mesh mesh;
  mesh.vertices.resize(2, (cols + 1) * (rows + 1));
  for (int j = 0; j <= rows; ++j)
    for (int i = 0; i <= cols; ++i) mesh.vertices.col(j * (cols + 1) + i) = Eigen::Vector2d(i, j);
  mesh.triangles = shapes::grid_triangles(cols, rows);
  return mesh;
}

/// The strip bent so that its x axis follows an arc turning by `angle` in total (radians; beyond 2π the
/// strip coils), keeping lengths along the axis: a target whose local rotations grow from 0 to `angle`.
inline Mesh bent(const Mesh& straight, double angle) {
  Mesh mesh = straight;
  const double length = straight.vertices.row(0).maxCoeff();
  const double radius = length / angle;
  for (Eigen::Index k = 0; k < mesh.vertex_count(); ++k) {
    const double x = straight.vertices(0, k), y = straight.vertices(1, k);
    const double phi = x / radius, r = radius - y;
    mesh.vertices.col(k) = Eigen::Vector2d(r * std::sin(phi), radius - r * std::cos(phi));
  }
  return mesh;
}

}  // namespace affinterp::global::testing
