#pragma once
// A regular strip of quads and its roll into a spiral: the engine's scale case (2000 × 250 quads,
// 1,000,000 triangles), at any resolution and in any units. The shape pair "strip-spiral" and the global
// checks build theirs here; header-only, as grid.hpp, so that the library's own tests need no more than it.
#include "experiments/inputs/shapes/grid.hpp"
#include "theory/global/mesh.hpp"

#include <cmath>
#include <numbers>

namespace affinterp::shapes {

/// A cols × rows grid of unit squares, each split into two counter-clockwise triangles (grid_triangles).
inline global::Mesh strip(int cols, int rows) {
  global::Mesh mesh;
  mesh.vertices.resize(2, (cols + 1) * (rows + 1));
  for (int j = 0; j <= rows; ++j)
    for (int i = 0; i <= cols; ++i) mesh.vertices.col(j * (cols + 1) + i) = Eigen::Vector2d(i, j);
  mesh.triangles = grid_triangles(cols, rows);
  return mesh;
}

/// The strip bent so that its x axis follows an arc turning by `angle` in total (radians; beyond 2π the
/// strip coils), keeping lengths along the axis: a target whose local rotations grow from 0 to `angle`.
inline global::Mesh bent(const global::Mesh& straight, double angle) {
  global::Mesh mesh = straight;
  const double length = straight.vertices.row(0).maxCoeff();
  const double radius = length / angle;
  for (Eigen::Index k = 0; k < mesh.vertex_count(); ++k) {
    const double x = straight.vertices(0, k), y = straight.vertices(1, k);
    const double phi = x / radius, r = radius - y;
    mesh.vertices.col(k) = Eigen::Vector2d(r * std::sin(phi), radius - r * std::cos(phi));
  }
  return mesh;
}

/// The resolution of the shape pair "strip-spiral": 200 × 25 quads (10,000 triangles) unless asked for more.
struct StripQuads {
  int cols = 200, rows = 25;
};

struct Spiral {
  global::Mesh source, target;
};

/// A strip of cols × rows quads, `length` × 2·length/18.8, rolled 1.5 turns: its axis bent along an arc of
/// radius length / 3π with its width outwards, so that no triangle flips.
inline Spiral spiral(int cols, int rows, double length = 18.8) {
  const double width = 2 * length / 18.8;
  global::Mesh straight = strip(cols, rows);
  straight.vertices.row(0) *= length / cols;
  straight.vertices.row(1) *= width / rows;
  global::Mesh inner = straight;
  inner.vertices.row(1).array() -= width;  // y ∈ [−width, 0]: bent() puts y = 0 on the arc
  return {straight, bent(inner, 3 * std::numbers::pi)};
}

}  // namespace affinterp::shapes
