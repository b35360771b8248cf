#pragma once
// Solves G X = R for G = K + U diag(c) Uᵀ: K sparse Hermitian positive definite (real symmetric, or complex
// Hermitian for the complex form of hermitian_form.hpp), factored by a sparse LDLᴴ whose symbolic analysis
// (fill-reducing ordering, elimination tree) is done once for the pattern and reused by every numeric
// factorisation; U a few dense real columns (the barycentre term of Kaji §4, whose Σ v_k / n couples all
// vertices) handled by the Sherman–Morrison–Woodbury identity
//     G⁻¹ = K⁻¹ − K⁻¹U (diag(c)⁻¹ + UᴴK⁻¹U)⁻¹ UᴴK⁻¹.
// Eigen's SimplicialLDLT rather than CHOLMOD, by measurement on the octopus mesh's complex E^R matrix
// (34,458 unknowns, 0.64 M non-zeros in L; one thread, AMD EPYC, g++ 12 -O3 -march=native): numeric
// factorisation 23 ms (built with -fcx-fortran-rules, see CMakeLists.txt; 61–99 ms without) against
// 63–72 ms for CholmodSupernodalLLT with OpenBLAS and 77–115 ms for SimplicialLDLT with a METIS ordering.
// CHOLMOD's supernodes stay small on a planar mesh, so its BLAS-3 kernels do not pay for their overhead;
// and Eigen's solver needs no further library.
#include <Eigen/Core>
#include <Eigen/LU>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <complex>

namespace affinterp::global {

template <class Scalar>
class SparseMinimiser {
 public:
  using SparseMatrix = Eigen::SparseMatrix<Scalar>;
  using Dense = Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>;

  /// The symbolic analysis for K's pattern (its lower triangle is read).
  void analyse(const SparseMatrix& K);
  /// The numeric factorisation of K (same pattern as analysed) and the Woodbury capacitance for U, c.
  /// Throws RefusedProblem when G is singular or not positive definite: the minimiser is not unique.
  void factorise(const SparseMatrix& K, const Eigen::MatrixXd& U, const Eigen::VectorXd& c);
  /// G⁻¹ R.
  Dense solve(const Dense& R) const;

 private:
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower> ldlt_;
  Dense U_, K_inverse_U_;
  /// diag(c)⁻¹ + UᴴK⁻¹U: at most a few rows (indefinite, hence LU rather than LDLᴴ).
  using Capacitance = Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic, 0, 8, 8>;
  Eigen::FullPivLU<Capacitance> capacitance_;
};

extern template class SparseMinimiser<double>;
extern template class SparseMinimiser<std::complex<double>>;

}  // namespace affinterp::global
