#include "theory/global/simplicial_factor.hpp"

#include "theory/global/ldl_substitution.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <ranges>

namespace affinterp::global {
namespace {

/// K itself when compressed (the symbolic part's a_source indexes its value array), else a compressed copy in
/// `storage`.
template <class SparseMatrix>
const SparseMatrix& compressed(const SparseMatrix& K, SparseMatrix& storage) {
  if (K.isCompressed()) return K;
  storage = K;
  storage.makeCompressed();
  return storage;
}

}  // namespace

template <class Scalar>
void SimplicialFactor<Scalar>::analyse(const SparseMatrix& K) {
  SparseMatrix storage;
  const SparseMatrix& C = compressed(K, storage);
  symbolic_ = std::make_shared<const LdlSymbolic>(ldl_symbolic(C.cols(), C.outerIndexPtr(), C.innerIndexPtr()));
  l_value_.assign(symbolic_->l_row.size(), Scalar(0));
  d_.assign(static_cast<std::size_t>(C.cols()), Scalar(0));
  for (std::vector<Scalar>& y : y_) y.assign(static_cast<std::size_t>(C.cols()), Scalar(0));
  for (std::vector<Scalar>& partial : partial_) partial.assign(symbolic_->partial_size, Scalar(0));
}

template <class Scalar>
void SimplicialFactor<Scalar>::scatter(const Scalar* k_value, int first, int last, Scalar* y) const {
  const LdlSymbolic& s = *symbolic_;
  for (int e = first; e < last; ++e) {
    const auto entry = static_cast<std::size_t>(e);
    const Scalar a = k_value[s.a_source[entry]];
    y[s.a_column[entry]] += s.a_conjugated[entry] ? Eigen::numext::conj(a) : a;
  }
}

// Row k of L solves L(0:k−1, 0:k−1) D l = A(0:k−1, k) over row k's pattern, in the order of ldl_symbolic.hpp
// (Davis §4.7): with A's row scattered into y, each column i of the pattern takes y_i, gives L(k, i) = y_i / D_i
// and D_k its share −L(k, i) conj(y_i), and passes −conj(L(r, i)) y_i to the rows r of column i above k.
template <class Scalar>
void SimplicialFactor<Scalar>::eliminate(int first, int last, Scalar* __restrict y, double& d_k) {
  const LdlSymbolic& s = *symbolic_;
  const int* __restrict l_row = s.l_row.data();
  Scalar* __restrict l_value = l_value_.data();
  const Scalar* __restrict d = d_.data();
  for (int q = first; q < last; ++q) {
    const auto i = static_cast<std::size_t>(s.r_column[static_cast<std::size_t>(q)]);
    const int slot = s.r_slot[static_cast<std::size_t>(q)];
    const Scalar y_i = y[i];
    y[i] = Scalar(0);
    const Scalar l_ki = y_i / std::real(d[i]);
    for (int p = s.l_start[i]; p < slot; ++p) y[l_row[p]] -= Eigen::numext::conj(l_value[p]) * y_i;
    d_k -= std::real(l_ki * Eigen::numext::conj(y_i));
    l_value[slot] = l_ki;
  }
}

template <class Scalar>
template <class Rows>
void SimplicialFactor<Scalar>::factorise_rows(const Scalar* k_value, const Rows& rows, Scalar* y) {
  const LdlSymbolic& s = *symbolic_;
  for (const auto k : rows) {
    const auto row = static_cast<std::size_t>(k);
    scatter(k_value, s.a_start[row], s.a_start[row + 1], y);
    double d_k = std::real(y[row]);
    y[row] = Scalar(0);
    eliminate(s.r_start[row], s.r_start[row + 1], y, d_k);
    d_[row] = d_k;
  }
}

template <class Scalar>
void SimplicialFactor<Scalar>::factorise_top_rows_in_group(const Scalar* k_value, std::size_t g) {
  const LdlSymbolic& s = *symbolic_;
  Scalar* y = y_[g].data();
  for (std::size_t t = 0; t < s.top_rows.size(); ++t) {
    const auto row = static_cast<std::size_t>(s.subtrees->top[t]);
    const LdlSymbolic::TopRow& top = s.top_rows[t];
    scatter(k_value, g == 0 ? s.a_start[row] : top.a_end[0], top.a_end[g], y);
    double d_share = 0;
    eliminate(g == 0 ? s.r_start[row] : top.r_end[0], top.r_end[g], y, d_share);
    // what the group's columns passed to the top's columns of the pattern, and its share of D_k
    Scalar* partial = partial_[g].data() + top.partial;
    for (int q = top.r_end[1]; q < s.r_start[row + 1]; ++q) {
      const auto c = static_cast<std::size_t>(s.r_column[static_cast<std::size_t>(q)]);
      *partial++ = y[c], y[c] = Scalar(0);
    }
    *partial = d_share;
  }
}

template <class Scalar>
void SimplicialFactor<Scalar>::factorise_top_rows(const Scalar* k_value) {
  const LdlSymbolic& s = *symbolic_;
  Scalar* y = y_[0].data();
  for (std::size_t t = 0; t < s.top_rows.size(); ++t) {
    const auto row = static_cast<std::size_t>(s.subtrees->top[t]);
    const LdlSymbolic::TopRow& top = s.top_rows[t];
    scatter(k_value, top.a_end[1], s.a_start[row + 1], y);
    const Scalar* partial[2] = {partial_[0].data() + top.partial, partial_[1].data() + top.partial};
    for (int q = top.r_end[1]; q < s.r_start[row + 1]; ++q) {
      const auto c = static_cast<std::size_t>(s.r_column[static_cast<std::size_t>(q)]);
      y[c] += *partial[0]++, y[c] += *partial[1]++;
    }
    double d_k = std::real(y[row]) + std::real(*partial[0]) + std::real(*partial[1]);
    y[row] = Scalar(0);
    eliminate(top.r_end[1], s.r_start[row + 1], y, d_k);
    d_[row] = d_k;
  }
}

template <class Scalar>
bool SimplicialFactor<Scalar>::factorise(const SparseMatrix& K, std::size_t threads) {
  SparseMatrix storage;
  const SparseMatrix& C = compressed(K, storage);
  const LdlSymbolic& s = *symbolic_;
  const Scalar* k_value = C.valuePtr();
  if (s.subtrees) {
    // a group's rows reach only its own columns, and its part of a top row only its own columns and the top's
    // rows; the top's part of each row comes after both groups'
    for_each_group(threads, [&](std::size_t g) {
      for (const auto& [column, root] : s.subtrees->ranges[g])
        factorise_rows(k_value, std::views::iota(column, root + 1), y_[g].data());
      factorise_top_rows_in_group(k_value, g);
    });
    factorise_top_rows(k_value);
  } else {
    factorise_rows(k_value, std::views::iota(Eigen::Index{0}, s.n), y_[0].data());
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
