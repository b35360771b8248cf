#pragma once
// The SparseFactor back-end on Eigen's SimplicialLDLT (sparse_factor.hpp), with a solve that carries all
// right-hand sides through one pass over L: P x = L D Lᴴ Pᵀ x, forward, diagonal, backward (ldl_substitution.hpp).
// Ordered by AMD and postordered (postordered_amd.hpp), so that the solve splits into two groups of subtrees.
#include "theory/global/ldl_subtrees.hpp"
#include "theory/global/postordered_amd.hpp"
#include "theory/global/sparse_factor.hpp"

#include <Eigen/SparseCholesky>

#include <optional>

namespace affinterp::global {

template <class Scalar>
class SimplicialFactor final : public SparseFactor<Scalar> {
 public:
  using typename SparseFactor<Scalar>::SparseMatrix;
  using typename SparseFactor<Scalar>::Block;

  void analyse(const SparseMatrix& K) override;
  bool factorise(const SparseMatrix& K) override;
  /// L's two groups of subtrees side by side on `threads` > 1 (ldl_subtrees.hpp), when L has them.
  void solve_in_place(Block& X, std::size_t threads) const override;
  std::unique_ptr<SparseFactor<Scalar>> clone() const override;
  SparseBackEnd back_end() const override { return SparseBackEnd::simplicial; }
  double factor_bytes() const override;

 private:
  /// Eigen's solvers are not copyable; this one copies its analysis and factor, for clone().
  struct CopyableLDLT : Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower, PostorderedAmd> {
    CopyableLDLT() = default;
    CopyableLDLT(const CopyableLDLT& other);
  };
  CopyableLDLT ldlt_;
  /// The split of L's columns, found at the first factorisation after an analysis (L's structure is the
  /// analysis's); empty when L has none worth two threads.
  std::optional<LdlSubtrees> subtrees_;
  bool split_ = false;  ///< whether subtrees_ is for the current analysis
};

extern template class SimplicialFactor<double>;
extern template class SimplicialFactor<std::complex<double>>;

}  // namespace affinterp::global
