#pragma once
// Meshing a planar outline into well-shaped triangles: CGAL's constrained Delaunay triangulation refined
// by Ruppert/Shewchuk's algorithm (CGAL::refine_Delaunay_mesh_2) with a minimum-angle bound of ~20.7°
// and an edge-length bound. Deterministic: the same input gives the same mesh.
#include "theory/global/mesh.hpp"

#include <vector>

namespace affinterp::shapes {

using Outline = std::vector<Eigen::Vector2d>;  ///< a simple closed polygon (last point ≠ first)

/// Meshes the inside of `outline` with edges no longer than `max_edge`. `extra_points` (inside the
/// outline) are inserted first: a dense set makes a finely meshed region. Triangles run
/// counter-clockwise.
global::Mesh triangulate(const Outline& outline, double max_edge,
                         const std::vector<Eigen::Vector2d>& extra_points = {});

/// The Delaunay triangulation of a point set (the triangles of its convex hull), counter-clockwise.
global::Mesh delaunay(const std::vector<Eigen::Vector2d>& points);

}  // namespace affinterp::shapes
