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
  /// Rows `rows` of L and D from A = P K Pᵀ, K's values `k_value`; y is zero on entry and on return.
  template <class Rows>
  void factorise_rows(const Scalar* k_value, const Rows& rows, std::vector<Scalar>& y);

  std::shared_ptr<const LdlSymbolic> symbolic_;  ///< shared by the clones, which factorise other frames
  std::vector<Scalar> l_value_, d_;              ///< L's values in the slots of symbolic_->l_row; D
  /// A dense row per group of subtrees, zero between rows (Davis's y in §4.7)
  std::vector<Scalar> y_[2];
};

extern template class SimplicialFactor<double>;
extern template class SimplicialFactor<std::complex<double>>;

}  // namespace affinterp::global
