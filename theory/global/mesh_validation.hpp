#pragma once
// What makes a pair of triangle meshes a valid input of Kaji §2: vertices P and Q of one triangle list
// τ_1 … τ_m, every source triangle non-degenerate and all of them oriented alike, so that each local map
// A_i (Kaji eq. (1)) exists. The one place for these rules: the engine (interpolation.cpp) and the mesh
// readers (experiments/inputs/mesh_pair) combine them. The readers' test of a flat triangle is
// numerical (is_degenerate) and they orient the source counter-clockwise; the engine asks only for the
// exact signs that make det A_i > 0 (check_orientation_preserved). Element indices in the messages are
// 0-based.
#include "theory/global/mesh.hpp"
#include "theory/global/refused_problem.hpp"

#include <vector>

namespace affinterp::global {

/// A mesh or a pair of meshes that cannot be interpolated; what() is one line naming the element. A
/// RefusedProblem, which the engine throws for its input.
struct InvalidMesh : RefusedProblem {
  using RefusedProblem::RefusedProblem;
};

/// Throws InvalidMesh unless the mesh has a vertex and a triangle, finite coordinates, and triangles of
/// three distinct in-range vertices.
void check_well_formed(const Mesh& mesh);

/// Throws InvalidMesh unless source and target have the same vertex count and the same triangle list
/// (the first difference is named).
void check_compatible(const Mesh& source, const Mesh& target);

/// Throws InvalidMesh unless every vertex belongs to a triangle and the triangles are in one piece
/// (joined through shared vertices): every local error depends on B_i only, so otherwise a vertex, or a
/// whole piece, moves freely and the minimiser of Kaji §4 is not unique. For a well-formed mesh.
void check_connected(const Mesh& mesh);

/// Throws InvalidMesh unless every source triangle has a non-zero signed area and its target triangle one
/// of the same sign: det A_i > 0, so A_i ∈ GL⁺(2) and its local homotopy (Kaji §3) exists. Exact signs,
/// whatever the orientation shared by the pair. For compatible meshes.
void check_orientation_preserved(const Mesh& source, const Mesh& target);

/// True when triangle i of `mesh` has (numerically) zero area: |2·area| at the rounding level of its
/// longest edge squared.
bool is_degenerate(const Mesh& mesh, Eigen::Index i);

/// Orients the source counter-clockwise. When every triangle runs clockwise, reverses every triangle
/// (the source shape is the same, seen from the other side) and returns true; when all already run
/// counter-clockwise returns false. Throws InvalidMesh on a zero-area triangle or on triangles of both
/// orientations (the source folds over itself: no consistent orientation exists).
bool orient_counter_clockwise(Mesh& source);

/// Reverses every triangle's corner order (τ = {a, b, c} → {a, c, b}).
void reverse_orientation(Mesh& mesh);

/// Triangles whose target image is flipped or collapsed: det A_i ≤ 0, i.e. the target triangle's signed
/// area is not positive while the source's is (source oriented counter-clockwise, same triangle list).
std::vector<Eigen::Index> flipped_triangles(const Mesh& target);

}  // namespace affinterp::global
