#pragma once
// What makes a pair of triangle meshes a valid input of Kaji §2: vertices P and Q of one triangle list
// τ_1 … τ_m, every source triangle non-degenerate and all of them oriented alike, so that each local map
// A_i (Kaji eq. (1)) exists. Element indices in the messages are 0-based.
#include "theory/global/mesh.hpp"

#include <stdexcept>
#include <vector>

namespace affinterp::global {

/// A mesh or a pair of meshes that cannot be interpolated; what() is one line naming the element.
struct InvalidMesh : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

/// Throws InvalidMesh unless the mesh has a vertex and a triangle, finite coordinates, and triangles of
/// three distinct in-range vertices.
void check_well_formed(const Mesh& mesh);

/// Throws InvalidMesh unless source and target have the same vertex count and the same triangle list
/// (the first difference is named).
void check_compatible(const Mesh& source, const Mesh& target);

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
