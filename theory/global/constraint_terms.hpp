#pragma once
// The constraint function C of Kaji §4 as a sum of terms c ‖ℓ(v) − r(t)‖² with ℓ(v) = Σ_k α_k v_k a linear
// combination of vertices: a vertex locus or pinned vertex (ℓ = v_k), an edge direction (ℓ = v_i − v_j)
// or the barycentre (ℓ = Σ v_k / n). Every term is isotropic: it treats x and y alike.
#include "theory/global/local_paths.hpp"
#include "theory/global/mesh.hpp"
#include "theory/global/options.hpp"

#include <Eigen/Core>

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace affinterp::global {

struct ConstraintTerm {
  std::vector<std::pair<Eigen::Index, double>> coefficients;  ///< (k, α_k); all n vertices for the barycentre
  double weight = 1.0;                                        ///< c
  std::function<Eigen::Vector2d(double)> target;              ///< r(t)
  std::string name;                                           ///< for messages, e.g. "locus of vertex 3"
  bool dense() const { return coefficients.size() > 3; }
};

/// The terms of `constraints` for the meshes (P, Q); edge directions following the local homotopy read
/// A_τ(t) from `paths`, which must outlive the terms. Throws RefusedProblem for bad indices or weights.
std::vector<ConstraintTerm> constraint_terms(const Constraints& constraints, const Mesh& source, const Mesh& target,
                                             const LocalPaths& paths);

}  // namespace affinterp::global
