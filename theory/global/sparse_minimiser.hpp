#pragma once
// Solves G X = R for G = K + U diag(c) Uᵀ: K sparse symmetric positive definite, factored by a sparse
// LDLᵀ whose symbolic analysis (fill-reducing ordering, elimination tree) is done once for the pattern
// and reused by every numeric factorisation; U a few dense columns (the barycentre term of Kaji §4,
// whose Σ v_k / n couples all vertices) handled by the Sherman–Morrison–Woodbury identity
//     G⁻¹ = K⁻¹ − K⁻¹U (diag(c)⁻¹ + UᵀK⁻¹U)⁻¹ UᵀK⁻¹.
// Eigen's SimplicialLDLT rather than CHOLMOD: on a 2×2-block mesh matrix of 68,916 unknowns (5.0 M
// non-zeros in L) its numeric factorisation took 350–425 ms against 447–469 ms for CholmodSupernodalLLT and
// 442 ms for CholmodSimplicialLLT (Debian's reference BLAS, one thread, shared machine), and it needs no
// further library.
#include <Eigen/Core>
#include <Eigen/LU>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

namespace affinterp::global {

class SparseMinimiser {
 public:
  using SparseMatrix = Eigen::SparseMatrix<double>;

  /// The symbolic analysis for K's pattern (its lower triangle is read).
  void analyse(const SparseMatrix& K);
  /// The numeric factorisation of K (same pattern as analysed) and the Woodbury capacitance for U, c.
  /// Throws RefusedProblem when G is singular or not positive definite: the minimiser is not unique.
  void factorise(const SparseMatrix& K, const Eigen::MatrixXd& U, const Eigen::VectorXd& c);
  /// G⁻¹ R.
  Eigen::MatrixXd solve(const Eigen::MatrixXd& R) const;

 private:
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower> ldlt_;
  Eigen::MatrixXd U_, K_inverse_U_;
  /// diag(c)⁻¹ + UᵀK⁻¹U: at most a few rows (indefinite, hence LU rather than LDLᵀ).
  using Capacitance = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 8, 8>;
  Eigen::FullPivLU<Capacitance> capacitance_;
};

}  // namespace affinterp::global
