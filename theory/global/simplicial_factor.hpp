#pragma once
// The SparseFactor back-end of our own: an up-looking LDLᴴ factorisation (Davis, "Direct Methods for Sparse
// Linear Systems", SIAM 2006, §4.7, as in his LDL package and Eigen's SimplicialLDLT) over the index lists of
// ldl_symbolic.hpp, made once per pattern, so that a frame's factorisation does no symbolic work: no
// permuted copy of K, no search for each row's pattern. Ordered by AMD and postordered, so that the rows of
// L's two groups of subtrees factorise, and their columns solve, side by side (ldl_subtrees.hpp). The solve
// carries all right-hand sides through one pass over L: P x = L D Lᴴ Pᵀ x (ldl_substitution.hpp). Two
// matrices of one pattern (two frames) factorise in one pass, each the same factor as alone (factorise_two).
#include "theory/global/ldl_symbolic.hpp"
#include "theory/global/sparse_factor.hpp"

#include <array>
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
  /// Both in one pass over the pattern when `other` shares this factor's analysis (a clone), on one thread:
  /// each row's index lists read once for the two matrices, whose entries lie side by side in a dense row: the
  /// index lists and the dense row's random reads paid once for two frames. The same factors as factorise gives.
  bool factorise_two(const SparseMatrix& K, SparseFactor<Scalar>& other, const SparseMatrix& K_other) override;
  bool two_in_one_pass() const override { return true; }
  /// The same split as factorise's.
  void solve_in_place(Block& X, std::size_t threads) const override;
  std::unique_ptr<SparseFactor<Scalar>> clone() const override;
  SparseBackEnd back_end() const override { return SparseBackEnd::simplicial; }
  double factor_bytes() const override;

 private:
  std::shared_ptr<const LdlSymbolic> symbolic_;  ///< shared by the clones, which factorise other frames
  std::vector<Scalar> l_value_, d_;              ///< L's values in the slots of symbolic_->l_row; D
  /// Per group of subtrees, a dense row (Davis's y in §4.7) and the sums its part of the top rows leaves; and
  /// for two matrices at once (factorise_two, made at its first call) their L's values side by side and the same
  std::vector<Scalar> y_[2], partial_[2];
  std::vector<std::array<Scalar, 2>> paired_l_, paired_y_[2], paired_partial_[2];
};

extern template class SimplicialFactor<double>;
extern template class SimplicialFactor<std::complex<double>>;

}  // namespace affinterp::global
