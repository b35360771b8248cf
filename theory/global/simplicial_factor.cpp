#include "theory/global/simplicial_factor.hpp"

#include "theory/global/ldl_substitution.hpp"
#include "theory/global/parallel_ranges.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <ranges>

namespace affinterp::global {

template <class Scalar>
void SimplicialFactor<Scalar>::analyse(const SparseMatrix& K) {
  SparseMatrix compressed;
  const SparseMatrix& C = K.isCompressed() ? K : (compressed = K, compressed.makeCompressed(), compressed);
  symbolic_ = std::make_shared<const LdlSymbolic>(ldl_symbolic(C.cols(), C.outerIndexPtr(), C.innerIndexPtr()));
  l_value_.assign(symbolic_->l_row.size(), Scalar(0));
  d_.assign(static_cast<std::size_t>(C.cols()), Scalar(0));
  for (std::vector<Scalar>& y : y_) y.assign(static_cast<std::size_t>(C.cols()), Scalar(0));
}

// Row k of L solves L(0:k−1, 0:k−1) D l = A(0:k−1, k) over row k's pattern, in the order of ldl_symbolic.hpp
// (Davis §4.7): A's row scattered into y, then each column i of the pattern takes y_i, gives
// L(k, i) = y_i / D_i and D_k its share −L(k, i) conj(y_i), and passes −conj(L(r, i)) y_i to the rows r of
// column i above k.
template <class Scalar>
template <class Rows>
void SimplicialFactor<Scalar>::factorise_rows(const Scalar* k_value, const Rows& rows, std::vector<Scalar>& y) {
  const LdlSymbolic& s = *symbolic_;
  const int* __restrict l_row = s.l_row.data();
  Scalar* __restrict l_value = l_value_.data();
  Scalar* __restrict d = d_.data();
  for (const auto k : rows) {
    const auto row = static_cast<std::size_t>(k);
    for (int e = s.a_start[row]; e < s.a_start[row + 1]; ++e) {
      const Scalar a = k_value[s.a_source[static_cast<std::size_t>(e)]];
      y[static_cast<std::size_t>(s.a_column[static_cast<std::size_t>(e)])] +=
          s.a_conjugated[static_cast<std::size_t>(e)] ? Eigen::numext::conj(a) : a;
    }
    double d_k = std::real(y[row]);
    y[row] = Scalar(0);
    for (int q = s.r_start[row]; q < s.r_start[row + 1]; ++q) {
      const auto i = static_cast<std::size_t>(s.r_column[static_cast<std::size_t>(q)]);
      const int slot = s.r_slot[static_cast<std::size_t>(q)];
      const Scalar y_i = y[i];
      y[i] = Scalar(0);
      const Scalar l_ki = y_i / std::real(d[i]);
      for (int p = s.l_start[i]; p < slot; ++p)
        y[static_cast<std::size_t>(l_row[p])] -= Eigen::numext::conj(l_value[p]) * y_i;
      d_k -= std::real(l_ki * Eigen::numext::conj(y_i));
      l_value[slot] = l_ki;
    }
    d[row] = d_k;
  }
}

template <class Scalar>
bool SimplicialFactor<Scalar>::factorise(const SparseMatrix& K, std::size_t threads) {
  SparseMatrix compressed;
  const SparseMatrix& C = K.isCompressed() ? K : (compressed = K, compressed.makeCompressed(), compressed);
  const LdlSymbolic& s = *symbolic_;
  const Scalar* k_value = C.valuePtr();
  if (s.subtrees) {
    // a group's rows reach only columns of its own subtrees; the top's, columns of both and of the top
    for_each_range(2, threads > 1 ? 2 : 1, [&](std::size_t first, std::size_t last) {
      for (std::size_t g = first; g < last; ++g)
        for (const auto& [column, root] : s.subtrees->ranges[g])
          factorise_rows(k_value, std::views::iota(column, root + 1), y_[g]);
    });
    factorise_rows(k_value, s.subtrees->top, y_[0]);
  } else {
    factorise_rows(k_value, std::views::iota(Eigen::Index{0}, s.n), y_[0]);
  }
  double smallest = std::numeric_limits<double>::infinity(), largest = 0;
  for (const Scalar& pivot : d_)  // real: D of an LDLᴴ factorisation
    smallest = std::min(smallest, std::real(pivot)), largest = std::max(largest, std::abs(pivot));
  // a zero or negative pivot (its row's quotients infinite or not a number) fails the ratio too
  return smallest > 1e-12 * largest && std::isfinite(largest);
}

template <class Scalar>
void SimplicialFactor<Scalar>::solve_in_place(Block& X, std::size_t threads) const {
  const LdlSymbolic& s = *symbolic_;
  ldl_solve_permuted(LdlColumns<Scalar>{s.n, s.l_start.data(), s.l_row.data(), l_value_.data(), 0, d_.data(),
                                        s.subtrees ? &*s.subtrees : nullptr},
                     s.pivot_unknown.data(), X, threads);
}

template <class Scalar>
std::unique_ptr<SparseFactor<Scalar>> SimplicialFactor<Scalar>::clone() const {
  return std::make_unique<SimplicialFactor>(*this);
}

template <class Scalar>
double SimplicialFactor<Scalar>::factor_bytes() const {
  return static_cast<double>(l_value_.size()) * static_cast<double>(sizeof(Scalar) + sizeof(int));
}

template class SimplicialFactor<double>;
template class SimplicialFactor<std::complex<double>>;

}  // namespace affinterp::global
