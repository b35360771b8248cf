#pragma once
// The SparseFactor back-end of our own: an up-looking LDLᴴ factorisation (Davis, "Direct Methods for Sparse
// Linear Systems", SIAM 2006, §4.7, as in his LDL package and Eigen's SimplicialLDLT) over the index lists of
// ldl_symbolic.hpp, made once per pattern, so that a frame's factorisation does no symbolic work: no
// permuted copy of K, no search for each row's pattern. Ordered by AMD and postordered, so that the rows of
// L's two groups of subtrees factorise, and their columns solve, side by side (ldl_subtrees.hpp). The solve
// carries all right-hand sides through one pass over L: P x = L D Lᴴ Pᵀ x (ldl_substitution.hpp).
#include "theory/global/ldl_symbolic.hpp"
#include "theory/global/sparse_factor.hpp"

#include <memory>
#include <vector>

namespace affinterp::global {

template <class Scalar>
class SimplicialFactor final : public SparseFactor<Scalar> {
 public:
  using typename SparseFactor<Scalar>::SparseMatrix;
  using typename SparseFactor<Scalar>::Block;

  void analyse(const SparseMatrix& K) override;
  /// L's two groups of subtrees side by side on `threads` > 1, when L has them (the same L whatever `threads`).
  bool factorise(const SparseMatrix& K, std::size_t threads) override;
  /// The same split as factorise's.
  void solve_in_place(Block& X, std::size_t threads) const override;
  std::unique_ptr<SparseFactor<Scalar>> clone() const override;
  SparseBackEnd back_end() const override { return SparseBackEnd::simplicial; }
  double factor_bytes() const override;

 private:
  // Of A = P K Pᵀ, K's values `k_value`; a dense row y is zero before and after each row.
  /// Adds A's entries [first, last) of a row (LdlSymbolic::a_start) into y.
  void scatter(const Scalar* k_value, int first, int last, Scalar* y) const;
  /// L(k, i) for the pattern's entries [first, last) of row k (LdlSymbolic::r_start), their shares taken from d_k.
  void eliminate(int first, int last, Scalar* y, double& d_k);
  /// Rows `rows` of L and D.
  template <class Rows>
  void factorise_rows(const Scalar* k_value, const Rows& rows, Scalar* y);
  /// Group g's part of every top row, its sums left in partial_[g] (LdlSymbolic::TopRow).
  void factorise_top_rows_in_group(const Scalar* k_value, std::size_t g);
  /// The top's part of every top row, after both groups'.
  void factorise_top_rows(const Scalar* k_value);

  std::shared_ptr<const LdlSymbolic> symbolic_;  ///< shared by the clones, which factorise other frames
  std::vector<Scalar> l_value_, d_;              ///< L's values in the slots of symbolic_->l_row; D
  /// Per group of subtrees, a dense row (Davis's y in §4.7) and the sums its part of the top rows leaves
  std::vector<Scalar> y_[2], partial_[2];
};

extern template class SimplicialFactor<double>;
extern template class SimplicialFactor<std::complex<double>>;

}  // namespace affinterp::global
