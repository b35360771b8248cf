#pragma once
// 3D meshes drawn in-process with Cairo: an orthographic projection after a fixed view rotation, the boundary
// triangles painted back to front (the painter's algorithm: no depth buffer, exact for the convex pieces of a
// surface, close enough for figures), each flat-shaded by Lambert's cosine law and outlined thinly.
#include "theory/global3/mesh3.hpp"

#include <Eigen/Core>

#include <span>

using cairo_t = struct _cairo;

namespace affinterp::plots {

/// The triangles drawn for a mesh, as column triples of vertex indices: a surface's own triangles; for tetrahedra
/// the faces that belong to one tetrahedron only, oriented outward.
Eigen::Matrix3Xi boundary_triangles(const global3::Mesh3& mesh);

/// The fixed view: turned 35° about the vertical axis, then tilted 25° towards the viewer.
Eigen::Matrix3d view_rotation();

/// Where a set of frames lands on the page: the projected box (after view_rotation) that holds all of them.
struct ProjectedBox {
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(1e300), hi = Eigen::Vector2d::Constant(-1e300);
  void include(const Eigen::Matrix3Xd& vertices);
};

/// What a drawn triangle is marked as, in the colours of the 3D viewer (plots/viewer/viewer3.html).
enum class FaceMark : unsigned char {
  none,
  fold,                ///< a triangle the target folds within the surface (target_folds3.hpp): purple
  inverted_near_fold,  ///< inverted in its frame, at or beside such a fold: orange
  inverted,            ///< inverted in its frame, away from the folds: red
};

/// The fill of a triangle so marked before shading (unmarked: pale to deep blue as `tint` goes from 0 to 1).
Eigen::Vector3d face_colour(FaceMark mark, double tint);

/// Draws `triangles` at `vertices` into the cell (x, y, size, size) of the page, scaled so that `box` fits the cell;
/// `tint` (0 … 1) darkens the fill from pale to deep blue (a frame's time or a blend's position); `marks` (empty, or
/// one a triangle) paint marked triangles in their colours instead, outlined widely in the same colour, after all
/// unmarked ones, so that none of those hides a marked one.
void draw_mesh3(cairo_t* cr, const Eigen::Matrix3Xi& triangles, const Eigen::Matrix3Xd& vertices,
                const ProjectedBox& box, double x, double y, double size, double tint = 0.5,
                std::span<const FaceMark> marks = {});

}  // namespace affinterp::plots
