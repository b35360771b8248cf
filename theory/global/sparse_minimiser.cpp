#include "theory/global/sparse_minimiser.hpp"

#include "theory/global/refused_problem.hpp"

namespace affinterp::global {

template <class Scalar>
SparseMinimiser<Scalar>::SparseMinimiser(const SparseMinimiser& other)
    : factor_(other.factor_ ? other.factor_->clone() : nullptr),
      dense_(other.dense_),
      alpha_(other.alpha_),
      K_inverse_alpha_(other.K_inverse_alpha_),
      alpha_K_alpha_(other.alpha_K_alpha_) {}

template <class Scalar>
void SparseMinimiser<Scalar>::analyse(const SparseMatrix& K, std::optional<DenseTerm> dense) {
  factor_ = make_sparse_factor<Scalar>(K.rows());
  factor_->analyse(K);
  dense_ = std::move(dense);
  if (dense_) alpha_ = dense_->alpha.cast<Scalar>();
}

template <class Scalar>
void SparseMinimiser<Scalar>::analyse(const SparseMatrix& K, std::optional<DenseTerm> dense, SparseBackEnd back_end) {
  factor_ = make_sparse_factor<Scalar>(back_end);
  factor_->analyse(K);
  dense_ = std::move(dense);
  if (dense_) alpha_ = dense_->alpha.cast<Scalar>();
}

namespace {

RefusedProblem singular_form() {
  return RefusedProblem(
      "the quadratic form G of the global error plus constraints is singular, so the minimiser is not unique "
      "(is the mesh in one connected piece, with every vertex in a triangle?)");
}

}  // namespace

template <class Scalar>
void SparseMinimiser<Scalar>::factorise(const SparseMatrix& K, std::size_t threads) {
  if (!factor_->factorise(K, threads)) throw singular_form();
  prepare_dense_term();
}

template <class Scalar>
void SparseMinimiser<Scalar>::factorise_two(const SparseMatrix& K, SparseMinimiser& other,
                                            const SparseMatrix& K_other) {
  if (!factor_->factorise_two(K, *other.factor_, K_other)) throw singular_form();
  prepare_dense_term();
  other.prepare_dense_term();
}

template <class Scalar>
void SparseMinimiser<Scalar>::prepare_dense_term() {
  if (!dense_ || dense_->grounded) return;
  typename SparseFactor<Scalar>::Block y = alpha_;
  factor_->solve_in_place(y, 1);
  K_inverse_alpha_ = y.col(0);
  alpha_K_alpha_ = alpha_.dot(K_inverse_alpha_);
}

template <class Scalar>
typename SparseMinimiser<Scalar>::Dense SparseMinimiser<Scalar>::solve(const Dense& R, std::size_t threads) const {
  typename SparseFactor<Scalar>::Block X = R;
  if (!dense_) {
    factor_->solve_in_place(X, threads);
    return X;
  }
  const double c = dense_->weight;
  if (!dense_->grounded) {  // z = x − y (c αᵀx) / (1 + c αᵀy)
    factor_->solve_in_place(X, threads);
    for (Eigen::Index j = 0; j < X.cols(); ++j)
      X.col(j) -= K_inverse_alpha_ * (c * alpha_.dot(X.col(j)) / (Scalar(1) + c * alpha_K_alpha_));
    return X;
  }
  const Scalar s = alpha_.sum();
  const Eigen::Matrix<Scalar, 1, Eigen::Dynamic> S = X.colwise().sum();
  X -= alpha_ * (S / s);  // K z = b − α S / s
  X.row(0).setZero();     // grounded: w_0 = 0
  factor_->solve_in_place(X, threads);
  const Eigen::Matrix<Scalar, 1, Eigen::Dynamic> delta = (S / (c * s) - alpha_.transpose() * X) / s;
  X.rowwise() += delta;  // z = w + δ 1
  return X;
}

template class SparseMinimiser<double>;
template class SparseMinimiser<std::complex<double>>;

}  // namespace affinterp::global
