#pragma once
// The quadratic form vᵀ G(t) v + vᵀ u(t) + c(t) of the global error function at time t (Kaji Appendix,
// "Efficiency"): the local errors of all triangles — and, for the symmetrised energy, those of the
// reverse problem Q → P at time 1 − t — plus the constraint terms.
//
// When every triangle's error is E^F, G = L ⊗ I₂ (x and y decouple, and G does not involve A_i(t)), so
// the n × n matrix L is assembled once; otherwise G(t) is the full 2n × 2n matrix over the unknowns
// (v_1x, v_1y, …), with a fixed sparsity pattern whose value slots are precomputed.
#include "theory/global/constraint_terms.hpp"
#include "theory/global/local_error.hpp"
#include "theory/global/local_paths.hpp"

#include <Eigen/SparseCore>

#include <array>
#include <vector>

namespace affinterp::global {

/// One local error E_i(A_i(s), B_i(x)), its reference corners and weights.
struct TriangleTerm {
  std::array<Eigen::Index, 3> vertex;
  Eigen::Matrix<double, 3, 2> D;  ///< B_i = V D (eq. (1))
  Corners<double> corners;        ///< the reference triangle (source, or target for the reverse problem)
  double weight = 1.0;            ///< its area when area weighted, else 1
  double frobenius_share = 1.0;   ///< w_i: E^F's share of the blend
};

class FrameAssembly {
 public:
  using SparseMatrix = Eigen::SparseMatrix<double>;

  /// `reverse` (the reverse problem's local paths) only for the symmetrised energy.
  FrameAssembly(const Mesh& source, const Mesh& target, const InterpolationOptions& options, const LocalPaths& forward,
                const LocalPaths* reverse, std::vector<ConstraintTerm> constraints);

  /// G = L ⊗ I₂ for every t; then matrix_at is the n × n L and right_hand_side_at has two columns.
  bool isotropic() const { return isotropic_; }
  /// G(t), or L when isotropic, plus `grounding` on the diagonal of vertex 0 (see low_rank_columns).
  const SparseMatrix& matrix_at(double t);
  /// −u(t)/2, so that G v = −u/2 at the minimiser: 2n × 1, or n × 2 (x and y columns) when isotropic.
  Eigen::MatrixXd right_hand_side_at(double t) const;
  /// The dense constraint terms (the barycentre) as U diag(c) Uᵀ, minus the grounding added to matrix_at.
  const Eigen::MatrixXd& low_rank_columns() const { return U_; }
  const Eigen::VectorXd& low_rank_weights() const { return c_; }

  /// The whole form at t, dense (for inspection on small meshes).
  FrameQuadratic dense_quadratic_at(double t) const;

 private:
  TriangleQuadratic<double> triangle_quadratic(Eigen::Index i, double t) const;
  void build_pattern();
  void add_constraint_quadratic(std::vector<double>& values) const;

  Energy energy_;
  Eigen::Index n_;
  bool isotropic_;
  const LocalPaths& forward_;
  const LocalPaths* reverse_;
  std::vector<TriangleTerm> forward_terms_, reverse_terms_;
  std::vector<ConstraintTerm> constraints_;
  SparseMatrix matrix_;
  std::vector<int> triangle_slots_;      ///< per triangle, 36 slots into matrix_'s values (−1: upper half)
  std::vector<double> constant_values_;  ///< the constraint terms and the grounding
  Eigen::MatrixXd U_;
  Eigen::VectorXd c_;
  bool assembled_once_ = false;
};

}  // namespace affinterp::global
