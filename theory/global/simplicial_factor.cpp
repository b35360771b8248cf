#include "theory/global/simplicial_factor.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace affinterp::global {

template <class Scalar>
SimplicialFactor<Scalar>::CopyableLDLT::CopyableLDLT(const CopyableLDLT& other)
    : Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower>() {
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
}

template <class Scalar>
bool SimplicialFactor<Scalar>::factorise(const SparseMatrix& K) {
  ldlt_.factorize(K);
  double smallest = std::numeric_limits<double>::infinity(), largest = 0;
  for (const Scalar& pivot : ldlt_.vectorD())  // real: D of an LDLᴴ factorisation
    smallest = std::min(smallest, std::real(pivot)), largest = std::max(largest, std::abs(pivot));
  // a zero pivot (Eigen's NumericalIssue) fails the ratio too; info() is not read since a copy (clone()) cannot
  // set the flag it asserts
  return smallest > 1e-12 * largest && std::isfinite(largest);
}

namespace {

/// L D Lᴴ y = x in place on the rows of Y (n × columns, row-major): forward over L's columns, the diagonal,
/// backward. `columns` is a template argument for the frames' one and two right-hand sides, so that the
/// inner loops over a row are unrolled and row j's entries stay in registers while its column of L is
/// applied (L is strictly lower: no entry of that column is row j); 0 is any count, read from Y.
template <int columns, class Scalar, class Block>
void substitute(const Eigen::SparseMatrix<Scalar>& L, const Eigen::Matrix<Scalar, Eigen::Dynamic, 1>& D, Block& Y) {
  constexpr int fixed = columns > 0 ? columns : Eigen::Dynamic;
  const Eigen::Index m = columns > 0 ? columns : Y.cols();
  Scalar* __restrict y = Y.data();  // no alias of L's arrays: its loads need not be repeated after each store
  const int* __restrict start = L.outerIndexPtr();
  const int* __restrict row = L.innerIndexPtr();
  const Scalar* __restrict value = L.valuePtr();
  Eigen::Matrix<Scalar, 1, fixed> y_j(m);
  for (Eigen::Index j = 0; j < L.outerSize(); ++j) {  // L y = P x
    for (Eigen::Index c = 0; c < m; ++c) y_j[c] = y[j * m + c];
    for (int s = start[j]; s < start[j + 1]; ++s)
      for (Eigen::Index c = 0; c < m; ++c) y[row[s] * m + c] -= value[s] * y_j[c];
  }
  for (Eigen::Index j = 0; j < L.outerSize(); ++j)
    for (Eigen::Index c = 0; c < m; ++c) y[j * m + c] /= D[j];
  for (Eigen::Index j = L.outerSize() - 1; j >= 0; --j) {  // Lᴴ w = D⁻¹ y
    for (Eigen::Index c = 0; c < m; ++c) y_j[c] = y[j * m + c];
    for (int s = start[j]; s < start[j + 1]; ++s)
      for (Eigen::Index c = 0; c < m; ++c) y_j[c] -= Eigen::numext::conj(value[s]) * y[row[s] * m + c];
    for (Eigen::Index c = 0; c < m; ++c) y[j * m + c] = y_j[c];
  }
}

}  // namespace

template <class Scalar>
void SimplicialFactor<Scalar>::solve_in_place(Block& X) const {
  const SparseMatrix& L = ldlt_.matrixL().nestedExpression();  // unit lower triangle, diagonal not stored
  Block Y = ldlt_.permutationP() * X;
  if (Y.cols() == 1)
    substitute<1>(L, ldlt_.vectorD(), Y);
  else if (Y.cols() == 2)
    substitute<2>(L, ldlt_.vectorD(), Y);
  else
    substitute<0>(L, ldlt_.vectorD(), Y);
  X = ldlt_.permutationPinv() * Y;
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
