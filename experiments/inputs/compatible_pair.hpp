#pragma once
// Compatible triangulations of two simple polygons with corresponding vertices (Aronov, Seidel and Souvaine,
// "On compatible triangulations of simple polygons", 1993): one triangle list, and in both shapes no
// flipped and no degenerate triangle, by construction.
//
// Construction. Let P and Q have n vertices, the i-th corresponding, oriented alike. Place vertex i at
// D_i = (cos 2πi/n, ±sin 2πi/n) on a convex domain D (the sign following the outlines' orientation): a
// polygon triangulation without interior vertices is a set of non-crossing diagonals, so any triangulation
// T_P of P (constrained Delaunay, CGAL) drawn with the same triangles on the D_i is a triangulation of D, the
// same for T_Q; this is the Tutte embedding of a graph without interior vertices, valid by Floater's theorem.
// The piecewise affine map φ_P: D → P that is affine on each triangle of T_P is an orientation-preserving
// homeomorphism (each triangle keeps its orientation), likewise φ_Q. The overlay of T_P and T_Q on D is
// computed with exact predicates and constructions (a CGAL arrangement over Epeck); each of its faces is
// convex (an intersection of two triangles) and lies in one triangle of T_P and one of T_Q. Each face is
// triangulated without degenerate triangles (a fan from a corner when one gives none, else from an interior
// point), and the common refinement is mapped to P by φ_P and to Q by φ_Q, exactly: every triangle lies in
// one triangle of T_P, where φ_P is affine with positive determinant, so its image is positively oriented,
// and likewise in Q. When T_P (or T_Q) is already positive in both shapes it is used alone, without Steiner
// points. Coordinates are then rounded to doubles and every triangle's orientation is checked again with
// exact predicates (a triangle flattened by rounding is reported, not written).
//
// Quality, without creating a flip: edges are flipped where the quadrilateral is strictly convex in both
// shapes and the smaller of the two shapes' smallest angles grows; interior (Steiner) vertices move towards
// the centroid of their neighbours, in each shape on its own, when every incident triangle stays positive
// and their smallest angle grows. Every test of orientation is exact.
#include "theory/global/mesh.hpp"

#include <stdexcept>
#include <string>

namespace affinterp::io {

/// Two outlines that cannot be paired: not simple, different vertex counts, opposite orientations; what()
/// is one line naming the outline and the element.
struct OutlineError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

struct CompatiblePair {
  global::Mesh source, target;  ///< one triangle list, counter-clockwise in both; vertices 0 … n−1 the outlines'
  int steiner_vertices = 0;     ///< vertices added inside (overlay crossings and face centres)
  double source_min_angle = 0, target_min_angle = 0;  ///< the smallest angle of any triangle, in degrees
};

/// Compatible triangulations of the simple polygons `source` and `target` (2 × n each, the i-th vertices
/// corresponding, either orientation but the same for both); `source_name` and `target_name` start the
/// messages. `quality_passes` rounds of the improvement above (0: none). Throws OutlineError.
CompatiblePair compatible_pair(const Eigen::Matrix2Xd& source, const Eigen::Matrix2Xd& target,
                               const std::string& source_name, const std::string& target_name, int quality_passes = 8);

/// `outline` resampled to `n` vertices at equal arc length along its closed boundary, from vertex 0.
Eigen::Matrix2Xd resample_outline(const Eigen::Matrix2Xd& outline, int n);

}  // namespace affinterp::io
