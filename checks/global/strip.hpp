#pragma once
// Small test shapes: a rectangular strip of triangles, its bend around an arc and its roll into a spiral,
// built in the tests themselves so that they need no files; the options of `affinterp interpolate`.
#include "experiments/inputs/shapes/grid.hpp"
#include "theory/global/gauge.hpp"
#include "theory/global/mesh.hpp"
#include "theory/global/options.hpp"

#include <cmath>
#include <numbers>

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

/// A strip of cols × rows quads, `length` × 2·length/18.8 (issue 19's 18.8 × 2 strip at any resolution and
/// in any units), rolled 1.5 turns: its axis bent along an arc of radius length / 3π with its width
/// outwards, so that no triangle flips.
struct Spiral {
  Mesh source, target;
};
inline Spiral spiral(int cols, int rows, double length = 18.8) {
  Mesh straight = strip(cols, rows);
  straight.vertices.row(0) *= length / cols;
  straight.vertices.row(1) *= 2 * length / 18.8 / rows;
  Mesh inner = straight;
  inner.vertices.row(1).array() -= 2 * length / 18.8;  // y ∈ [−width, 0]: bent() puts y = 0 on the arc
  Spiral s{straight, bent(inner, 3 * std::numbers::pi)};
  return s;
}

/// The options of `affinterp interpolate`: area weights, the straight barycentre locus, the default gauge.
inline InterpolationOptions cli_options(Energy energy, const Spiral& s) {
  InterpolationOptions options;
  options.energy = energy;
  options.area_weighted = true;
  options.constraints.barycentre = BarycentreLocus{};
  if (const auto edge = default_edge_direction(s.source, s.target, options)) options.constraints.edges.push_back(*edge);
  return options;
}

inline double box_size(const Mesh& a, const Mesh& b) {
  Eigen::Matrix2Xd both(2, a.vertex_count() + b.vertex_count());
  both << a.vertices, b.vertices;
  return (both.rowwise().maxCoeff() - both.rowwise().minCoeff()).maxCoeff();
}

}  // namespace affinterp::global::testing
