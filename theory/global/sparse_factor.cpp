#include "theory/global/sparse_factor.hpp"

#include "theory/global/simplicial_factor.hpp"
#ifdef AFFINTERP_HAS_CHOLMOD
#include "theory/global/cholmod_factor.hpp"
#endif

#include <stdexcept>

namespace affinterp::global {

bool has_cholmod() {
#ifdef AFFINTERP_HAS_CHOLMOD
  return true;
#else
  return false;
#endif
}

template <class Scalar>
std::unique_ptr<SparseFactor<Scalar>> make_sparse_factor(Eigen::Index unknowns) {
  return make_sparse_factor<Scalar>(
      has_cholmod() && unknowns >= cholmod_from_unknowns<Scalar> ? SparseBackEnd::cholmod : SparseBackEnd::simplicial);
}

template <class Scalar>
std::unique_ptr<SparseFactor<Scalar>> make_sparse_factor(SparseBackEnd back_end) {
  if (back_end == SparseBackEnd::simplicial) return std::make_unique<SimplicialFactor<Scalar>>();
#ifdef AFFINTERP_HAS_CHOLMOD
  return std::make_unique<CholmodFactor<Scalar>>();
#else
  throw std::invalid_argument("this build has no CHOLMOD back-end (SuiteSparse was not found)");
#endif
}

template std::unique_ptr<SparseFactor<double>> make_sparse_factor<double>(Eigen::Index);
template std::unique_ptr<SparseFactor<std::complex<double>>> make_sparse_factor<std::complex<double>>(Eigen::Index);
template std::unique_ptr<SparseFactor<double>> make_sparse_factor<double>(SparseBackEnd);
template std::unique_ptr<SparseFactor<std::complex<double>>> make_sparse_factor<std::complex<double>>(SparseBackEnd);

}  // namespace affinterp::global
