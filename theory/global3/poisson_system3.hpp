#pragma once
// E^F in 3D, in the Poisson form of Xu et al. (the thesis's deformer, its reference [14]; Kaji §4 with E^F):
// for target linear maps A_i the vertices v minimising
//     E(v) = Σ_i w_i ‖(X_i − A_i E_i) E_i⁺‖²_F + C(v),
// where E_i holds element i's rest edges from corner 0 (3 × 2 for a triangle, 3 × 3 for a tetrahedron),
// X_i = [v_{i1}−v_{i0} …] the same edges in the frame, and E_i⁺ = (E_iᵀE_i)⁻¹E_iᵀ. X_i E_i⁺ is the linear part
// B_i of the element's map (the in-plane part for a triangle: it maps the rest plane and is 0 on the normal),
// so the term is ‖B_i − A_i‖²_F restricted to the element's span: on a tetrahedron exactly Kaji's
// E^F = ‖A − B‖²_F, on a triangle its value in the plane, the same number the 2D engine's E^F gives for a flat
// mesh. (The gradient form; Deformation3's edge form Σ_edges ‖(x_b − x_a) − A_i(p_b − p_a)‖² weighs the three
// edges alike instead and is not ‖B_i − A_i‖_F on non-equilateral triangles.) w_i is the rest element's area or
// volume, or 1.
//
// Normal equations: L V = Σ_i W_i A_iᵀ scattered to the corners, with V the n × 3 vertices, L = Σ_i w_i C M_i Cᵀ,
// M_i = (E_iᵀE_i)⁻¹, W_i = w_i C E_i⁺ and C the (d+1) × d map from edges to corners (row 0 all −1, then I). L
// depends on the rest mesh only: factored once, the three coordinates solved together in one block.
// Symmetrised (E′(t) = E(t) + E^{−1}(1 − t), interpolation3.hpp): the same sum over a second rest pose of the
// same elements, the target, whose edges E_i and weights w_i are the target's; L is the sum of both, still
// constant in t, and term r·m + i (r = 0 source, 1 target) takes its own map.
// Constraints: pins and vertex loci add c on L's diagonal; the barycentre term is a rank-one dense matrix (c_o/n²) 11ᵀ,
// handled by Sherman–Morrison on top of the pinned factor, or, without pins or loci, as the gauge: L's kernel is the
// translations (a connected mesh) and Σ_i W_i A_iᵀ ⟂ 1, so the minimiser is any solution of L V = b (computed with
// vertex 0 grounded: L + s e_0e_0ᵀ) shifted to the target barycentre.
#include "theory/global/sparse_factor.hpp"
#include "theory/global3/constraints3.hpp"
#include "theory/global3/mesh3.hpp"

#include <Eigen/Core>

#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace affinterp::global3 {

class PoissonSystem3 {
 public:
  using Block = global::SparseFactor<double>::Block;  ///< n × 3, row k = vertex k

  /// The set-up: L with the constraints' diagonal, its factorisation. `rest` must be valid
  /// (mesh3_validation.hpp). Throws global::RefusedProblem for a pinned vertex or a locus's out of range, a locus
  /// of fewer than two points or a non-finite one, a weight not
  /// positive and finite, no constraint fixing the translation, or a system the factorisation finds singular.
  PoissonSystem3(const Mesh3& rest, bool area_weighted, const Constraints3& constraints,
                 std::optional<global::SparseBackEnd> back_end);
  /// The sum over several rest poses of the same elements (the symmetrised energy: source and target): term
  /// r·m + i fits element i of rests[r], and right_hand_side and energy take one map per term.
  PoissonSystem3(std::span<const Mesh3* const> rests, bool area_weighted, const Constraints3& constraints,
                 std::optional<global::SparseBackEnd> back_end);
  ~PoissonSystem3();
  PoissonSystem3(PoissonSystem3&&) noexcept;
  PoissonSystem3& operator=(PoissonSystem3&&) noexcept;

  /// b = Σ_i W_i A_iᵀ (n × 3), one A_i per term (element of each rest pose); summed per vertex over its star in a fixed
  /// order, so the same bits on any number of threads.
  Block right_hand_side(std::span<const Eigen::Matrix3d> A, std::size_t threads) const;
  /// The minimiser v (3 × n) for the right-hand side b and the constraints' targets. Const and safe to call
  /// from several threads at once.
  Eigen::Matrix3Xd solve(Block b, const ConstraintTargets3& targets, std::size_t threads) const;
  /// B_s = X_s E_s⁺ of every term at the vertices v (3 × n): the linear part of the map from the term's rest
  /// element to v's (a triangle's in-plane part), the matrix its E^F term compares with A_s. The same bits on any
  /// number of threads.
  std::vector<Eigen::Matrix3d> gradients(const Eigen::Matrix3Xd& v, std::size_t threads) const;
  /// E(v) for the maps A and the targets: E^F's sum plus C.
  double energy(std::span<const Eigen::Matrix3d> A, const Eigen::Matrix3Xd& v, const ConstraintTargets3& targets) const;

  Eigen::Index vertex_count() const;
  int corners() const;  ///< 3 (triangles) or 4 (tetrahedra)
  /// w_i: the rest element's area or volume (area_weighted), else 1; one per term.
  const Eigen::VectorXd& weights() const;
  const Constraints3& constraints() const;
  global::SparseBackEnd back_end() const;

  struct Data;  ///< the set-up's arrays, opaque (poisson_system3.cpp)

 private:
  std::unique_ptr<Data> data_;
};

}  // namespace affinterp::global3
