#pragma once
// The SparseFactor back-end on CHOLMOD's supernodal Cholesky LLᴴ (SuiteSparse), for large meshes
// (sparse_factor.hpp). Ordering by AMD alone: METIS gained nothing on these planar meshes (issue 19).
#include "theory/global/sparse_factor.hpp"

#include <cholmod.h>

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
  bool factorise(const SparseMatrix& K) override;
  /// Each call uses a cholmod_common of its own, so that calls on one factor may run concurrently.
  void solve_in_place(Block& X) const override;
  std::unique_ptr<SparseFactor<Scalar>> clone() const override;
  SparseBackEnd back_end() const override { return SparseBackEnd::cholmod; }
  double factor_bytes() const override;

 private:
  cholmod_common common_;
  cholmod_factor* L_ = nullptr;
};

extern template class CholmodFactor<double>;
extern template class CholmodFactor<std::complex<double>>;

}  // namespace affinterp::global
