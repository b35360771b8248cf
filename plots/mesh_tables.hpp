#pragma once
// A triangle mesh as gnuplot data: its edges as polylines and its triangles as closed polygons, with
// triangles that are flipped (signed area ≤ 0; the triangle list runs counter-clockwise in the source)
// kept apart so they can be drawn in red.
#include "plots/figure.hpp"

#include <Eigen/Core>

namespace affinterp::plots {

struct MeshTables {
  Table edges;      ///< one two-point polyline per edge, separated by blank lines
  Table triangles;  ///< closed polygons of the unflipped triangles, separated by two blank lines
  Table flipped;    ///< closed polygons of the flipped triangles
};

/// Above this many triangles only boundary edges are drawn and triangles are not filled one by one.
inline constexpr Eigen::Index detailed_triangle_limit = 20000;

/// The tables of the mesh (`triangles` columns index `vertices` columns), shifted by `offset`.
MeshTables mesh_tables(const Eigen::Matrix3Xi& triangles, const Eigen::Matrix2Xd& vertices,
                       const Eigen::Vector2d& offset = Eigen::Vector2d::Zero());

/// Appends `more`'s rows to `table`.
void append(Table& table, const Table& more);

}  // namespace affinterp::plots
