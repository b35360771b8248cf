#pragma once
// The SparseFactor back-end on CHOLMOD's supernodal Cholesky LLᴴ (SuiteSparse), for large meshes
// (sparse_factor.hpp). Ordering by AMD: METIS halves the 1M-triangle factor's flops but takes several times AMD's
// time to order, more than the set-up's budget. A real factor, solved many times, is turned into
// simplicial L D Lᵀ columns of its own after its factorisation and solved by ldl_substitution.hpp.
#include "theory/global/ldl_subtrees.hpp"
#include "theory/global/sparse_factor.hpp"

#include <cholmod.h>

#include <optional>
#include <vector>

namespace affinterp::global {

template <class Scalar>
class CholmodFactor final : public SparseFactor<Scalar> {
 public:
  using typename SparseFactor<Scalar>::SparseMatrix;
  using typename SparseFactor<Scalar>::Block;

  CholmodFactor();
  ~CholmodFactor() override;
  CholmodFactor(const CholmodFactor&) = delete;
  CholmodFactor& operator=(const CholmodFactor&) = delete;

  void analyse(const SparseMatrix& K) override;
  /// Supernodal, on the calling thread (its BLAS on one thread: the engine runs frames in parallel itself);
  /// then, for a real K, simplicial L D Lᵀ columns (a second call analyses again).
  bool factorise(const SparseMatrix& K, std::size_t threads) override;
  /// Each call uses a cholmod_common of its own, so that calls on one factor may run concurrently. A real
  /// factor's solve runs its two groups of subtrees side by side on `threads` > 1; a complex one (CHOLMOD's
  /// own solve) stays on the calling thread.
  void solve_in_place(Block& X, std::size_t threads) const override;
  std::unique_ptr<SparseFactor<Scalar>> clone() const override;
  SparseBackEnd back_end() const override { return SparseBackEnd::cholmod; }
  double factor_bytes() const override;

 private:
  cholmod_common common_;
  cholmod_factor* L_ = nullptr;
  /// A real factor turned into simplicial L D Lᵀ columns of its own (factorise(); L_ is then null): L's
  /// strictly lower entries by columns, the pivots, the permutation (perm[k]: the unknown of pivot k), and
  /// the split of its columns into two groups of subtrees of CHOLMOD's postordered elimination tree, for a
  /// solve on two threads.
  struct Columns {
    std::vector<int> start, row;
    std::vector<double> value;
    Eigen::VectorXd D;
    std::vector<int> perm;
    std::optional<LdlSubtrees> subtrees;
  };
  Columns columns_;
};

extern template class CholmodFactor<double>;
extern template class CholmodFactor<std::complex<double>>;

}  // namespace affinterp::global
