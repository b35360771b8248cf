#pragma once
// The SparseFactor back-end on Eigen's SimplicialLDLT (sparse_factor.hpp), with a solve that carries all
// right-hand sides through one pass over L: P x = L D Lᴴ Pᵀ x, forward, diagonal, backward (ldl_substitution.hpp).
#include "theory/global/sparse_factor.hpp"

#include <Eigen/SparseCholesky>

namespace affinterp::global {

template <class Scalar>
class SimplicialFactor final : public SparseFactor<Scalar> {
 public:
  using typename SparseFactor<Scalar>::SparseMatrix;
  using typename SparseFactor<Scalar>::Block;

  void analyse(const SparseMatrix& K) override;
  bool factorise(const SparseMatrix& K) override;
  /// On the calling thread (Eigen's ordering is not postordered: ldl_subtrees.hpp).
  void solve_in_place(Block& X, std::size_t threads) const override;
  std::unique_ptr<SparseFactor<Scalar>> clone() const override;
  SparseBackEnd back_end() const override { return SparseBackEnd::simplicial; }
  double factor_bytes() const override;

 private:
  /// Eigen's solvers are not copyable; this one copies its analysis and factor, for clone().
  struct CopyableLDLT : Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower> {
    CopyableLDLT() = default;
    CopyableLDLT(const CopyableLDLT& other);
  };
  CopyableLDLT ldlt_;
};

extern template class SimplicialFactor<double>;
extern template class SimplicialFactor<std::complex<double>>;

}  // namespace affinterp::global
