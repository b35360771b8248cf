#include "theory/global/simplicial_factor.hpp"

#include "theory/global/ldl_substitution.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace affinterp::global {

template <class Scalar>
SimplicialFactor<Scalar>::CopyableLDLT::CopyableLDLT(const CopyableLDLT& other)
    : Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower, PostorderedAmd>() {
  this->m_info = other.m_info;
  this->m_factorizationIsOk = other.m_factorizationIsOk;
  this->m_analysisIsOk = other.m_analysisIsOk;
  this->m_matrix = other.m_matrix;
  this->m_diag = other.m_diag;
  this->m_parent = other.m_parent;
  this->m_nonZerosPerCol = other.m_nonZerosPerCol;
  this->m_P = other.m_P;
  this->m_Pinv = other.m_Pinv;
  this->m_shiftOffset = other.m_shiftOffset;
  this->m_shiftScale = other.m_shiftScale;
}

template <class Scalar>
void SimplicialFactor<Scalar>::analyse(const SparseMatrix& K) {
  ldlt_.analyzePattern(K);
  subtrees_.reset(), split_ = false;
}

template <class Scalar>
bool SimplicialFactor<Scalar>::factorise(const SparseMatrix& K) {
  ldlt_.factorize(K);
  double smallest = std::numeric_limits<double>::infinity(), largest = 0;
  for (const Scalar& pivot : ldlt_.vectorD())  // real: D of an LDLᴴ factorisation
    smallest = std::min(smallest, std::real(pivot)), largest = std::max(largest, std::abs(pivot));
  // a zero pivot (Eigen's NumericalIssue) fails the ratio too; info() is not read since a copy (clone()) cannot
  // set the flag it asserts
  if (!(smallest > 1e-12 * largest && std::isfinite(largest))) return false;
  if (!split_) {
    const SparseMatrix& L = ldlt_.matrixL().nestedExpression();
    subtrees_ = split_subtrees(L.outerSize(), L.outerIndexPtr(), L.innerIndexPtr(), 0), split_ = true;
  }
  return true;
}

template <class Scalar>
void SimplicialFactor<Scalar>::solve_in_place(Block& X, std::size_t threads) const {
  const SparseMatrix& L = ldlt_.matrixL().nestedExpression();  // unit lower triangle, diagonal not stored
  const auto& pivots = ldlt_.permutationPinv().indices();      // the unknown of each pivot
  ldl_solve_permuted(LdlColumns<Scalar>{L.outerSize(), L.outerIndexPtr(), L.innerIndexPtr(), L.valuePtr(), 0,
                                        ldlt_.vectorD().data(), subtrees_ ? &*subtrees_ : nullptr},
                     pivots.size() > 0 ? pivots.data() : nullptr, X, threads);
}

template <class Scalar>
std::unique_ptr<SparseFactor<Scalar>> SimplicialFactor<Scalar>::clone() const {
  return std::make_unique<SimplicialFactor>(*this);
}

template <class Scalar>
double SimplicialFactor<Scalar>::factor_bytes() const {
  const SparseMatrix& L = ldlt_.matrixL().nestedExpression();
  return static_cast<double>(L.nonZeros()) * static_cast<double>(sizeof(Scalar) + sizeof(int));
}

template class SimplicialFactor<double>;
template class SimplicialFactor<std::complex<double>>;

}  // namespace affinterp::global
