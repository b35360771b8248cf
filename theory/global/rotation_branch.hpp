#pragma once
// Rotation consistency: the polar angle θ_i of A_i = R_θ S is defined only up to 2πk, and E^F compares
// B_i with A_i(t) = R_{tθ_i} …, so the branch matters for every t ∉ ℤ. A mesh that turns by more than π
// from one end to the other needs θ_i beyond (−π, π]. The consistent choice walks the dual graph
// (triangles adjacent across an edge) breadth-first from the first triangle of each connected piece and
// gives each triangle the branch θ_j + 2πk_j nearest its parent's angle, so |θ_j − θ_parent| ≤ π.
#include "theory/global/mesh.hpp"

#include <Eigen/Core>

#include <vector>

namespace affinterp::global {

/// The triangles sharing an edge with each triangle (the dual graph): those of triangle i are
/// neighbour[start[i]] … neighbour[start[i + 1] − 1], ordered by the shared edge's (lower, higher) vertex pair,
/// then by index.
struct DualGraph {
  std::vector<int> start, neighbour;
};

/// The dual graph of a well-formed triangle list (mesh_validation.hpp).
DualGraph dual_graph(const Eigen::Matrix3Xi& triangles);

/// The branches θ_i + 2πk_i of the principal angles `principal` chosen breadth-first as above.
Eigen::VectorXd consistent_angles(const Eigen::Matrix3Xi& triangles, const Eigen::VectorXd& principal);

}  // namespace affinterp::global
