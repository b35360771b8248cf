#pragma once
// Solves G z = b for G = K + c α αᴴ: K the sparse part of the global error's form (the triangles and the
// sparse constraint terms; Hermitian, real or complex, hermitian_form.hpp), factored by a SparseFactor
// (sparse_factor.hpp, the back-end chosen by size), and c |αᵀz − r|² the one dense term, the barycentre of
// Kaji §4, whose Σ z_k / n couples all vertices. The dense term is handled exactly, with no rank test:
//   - grounded (K 1 = 0: no sparse term fixes translation, the barycentre alone does). With s = Σ α_k and
//     S = Σ b_k, summing the rows of G z = b gives c s (αᵀz) = S, so K z = b − α S / s: a consistent
//     singular system, solved as K_0 w = b′ with K grounded at vertex 0 (its row and column 0 replaced by
//     the diagonal entry, b′_0 = 0, so w_0 = 0 exactly), and z = w + δ 1 with δ = (S / (c s) − αᵀw) / s
//     so that αᵀz = S / (c s). One solve per right-hand side, whatever the mesh's size or units.
//   - K definite (a pinned vertex or locus fixes translation): Sherman–Morrison with the positive update,
//     z = x − y (c αᵀx) / (1 + c αᵀy), x = K⁻¹b, y = K⁻¹α (solved once per factorisation); the
//     denominator is at least 1, so this too needs no rank test.
#include "theory/global/sparse_factor.hpp"

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <complex>
#include <memory>
#include <optional>

namespace affinterp::global {

/// The dense term c |αᵀz − r|² of G = K + c α αᵀ (the barycentre).
struct DenseTerm {
  Eigen::VectorXd alpha;
  double weight = 0;  ///< c > 0
  /// K 1 = 0 and Σ α ≠ 0: K is grounded at vertex 0 by the caller (FrameAssembly::matrix_at).
  bool grounded = false;
};

template <class Scalar>
class SparseMinimiser {
 public:
  using SparseMatrix = Eigen::SparseMatrix<Scalar>;
  using Dense = Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>;

  SparseMinimiser() = default;
  SparseMinimiser(const SparseMinimiser& other);
  SparseMinimiser& operator=(const SparseMinimiser&) = delete;
  SparseMinimiser(SparseMinimiser&&) noexcept = default;

  /// The symbolic analysis for K's pattern (its lower triangle is read) on the back-end for its size, and
  /// the dense term, if any.
  void analyse(const SparseMatrix& K, std::optional<DenseTerm> dense);
  /// The same on the named back-end (benchmarks).
  void analyse(const SparseMatrix& K, std::optional<DenseTerm> dense, SparseBackEnd back_end);
  /// The numeric factorisation of K (same pattern as analysed, grounded when the dense term says so), on up
  /// to `threads` threads where the factor can (SparseFactor::factorise: the same factor whatever their
  /// number). Throws RefusedProblem when K is singular or not positive definite: the minimiser is not unique.
  void factorise(const SparseMatrix& K, std::size_t threads = 1);
  /// K into this minimiser and K_other into `other` (a copy of this one: the same analysis and dense term), on
  /// one thread, in one pass where the back-end can (SparseFactor::factorise_two): the factors factorise gives.
  void factorise_two(const SparseMatrix& K, SparseMinimiser& other, const SparseMatrix& K_other);
  /// G⁻¹ R, all columns in one solve, on up to `threads` threads where the factor can
  /// (SparseFactor::solve_in_place: the same result whatever their number).
  Dense solve(const Dense& R, std::size_t threads = 1) const;
  const SparseFactor<Scalar>& factor() const { return *factor_; }

 private:
  using Vector = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;
  /// After K's factorisation, y = K⁻¹α when K is definite.
  void prepare_dense_term();
  std::unique_ptr<SparseFactor<Scalar>> factor_;
  std::optional<DenseTerm> dense_;
  Vector alpha_;             ///< α in the scalar type
  Vector K_inverse_alpha_;   ///< y = K⁻¹α when K is definite
  Scalar alpha_K_alpha_{0};  ///< αᵀy
};

extern template class SparseMinimiser<double>;
extern template class SparseMinimiser<std::complex<double>>;

}  // namespace affinterp::global
