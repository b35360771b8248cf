#include "theory/global/sparse_minimiser.hpp"

#include "theory/global/refused_problem.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace affinterp::global {

template <class Scalar>
void SparseMinimiser<Scalar>::analyse(const SparseMatrix& K) {
  ldlt_.analyzePattern(K);
}

template <class Scalar>
void SparseMinimiser<Scalar>::factorise(const SparseMatrix& K, const Eigen::MatrixXd& U, const Eigen::VectorXd& c) {
  ldlt_.factorize(K);
  double smallest = std::numeric_limits<double>::infinity(), largest = 1.0;
  for (const Scalar& pivot : ldlt_.vectorD())  // real: D of an LDLᴴ factorisation
    smallest = std::min(smallest, std::real(pivot)), largest = std::max(largest, std::abs(pivot));
  if (ldlt_.info() != Eigen::Success || !(smallest > 1e-12 * largest) || !std::isfinite(largest))
    throw RefusedProblem(
        "the quadratic form G of the global error plus constraints is singular, so the minimiser is not unique "
        "(is the mesh in one connected piece, with every vertex in a triangle?)");
  U_ = U.cast<Scalar>();
  if (U.cols() == 0) return;
  K_inverse_U_ = ldlt_.solve(U_);
  Capacitance capacitance(c.size(), c.size());
  for (Eigen::Index i = 0; i < c.size(); ++i)
    for (Eigen::Index j = 0; j < c.size(); ++j)
      capacitance(i, j) = Scalar(i == j ? 1 / c[i] : 0.0) + U_.col(i).dot(K_inverse_U_.col(j));
  capacitance_.compute(capacitance);
  if (capacitance_.rank() < c.size())
    throw RefusedProblem("the global quadratic form with the barycentre term is singular: the minimiser is not unique");
}

template <class Scalar>
typename SparseMinimiser<Scalar>::Dense SparseMinimiser<Scalar>::solve(const Dense& R) const {
  Dense X = ldlt_.solve(R);
  for (Eigen::Index j = 0; j < X.cols() && U_.cols() > 0; ++j) {  // column by column: the capacitance is tiny
    const Eigen::Matrix<Scalar, Eigen::Dynamic, 1> y =
        capacitance_.solve(Eigen::Matrix<Scalar, Eigen::Dynamic, 1>(U_.adjoint() * X.col(j)));
    X.col(j) -= K_inverse_U_.lazyProduct(y);
  }
  return X;
}

template class SparseMinimiser<double>;
template class SparseMinimiser<std::complex<double>>;

}  // namespace affinterp::global
