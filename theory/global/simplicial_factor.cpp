#include "theory/global/simplicial_factor.hpp"

#include "theory/global/ldl_substitution.hpp"

#include <immintrin.h>

#include <algorithm>
#include <array>
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

// One step's arithmetic, spelled out with a fused multiply-add wherever the machine has one, so that no product
// is left for the compiler to contract: a frame factorised alone and beside another (factorise_two, whose lanes
// the compiler may vectorise) round alike on every machine.

/// c − a b
inline double minus_product(double c, double a, double b) {
#ifdef __FMA__
  return std::fma(-a, b, c);
#else
  return c - a * b;
#endif
}
/// c + a b
inline double plus_product(double c, double a, double b) {
#ifdef __FMA__
  return std::fma(a, b, c);
#else
  return c + a * b;
#endif
}

/// y −= conj(l) x
inline void subtract_conj_product(double& y, double l, double x) { y = minus_product(y, l, x); }
inline void subtract_conj_product(std::complex<double>& y, const std::complex<double>& l,
                                  const std::complex<double>& x) {
  // conj(l) x = (l_r x_r + l_i x_i) + i (l_r x_i − l_i x_r)
  y = {minus_product(minus_product(y.real(), l.real(), x.real()), l.imag(), x.imag()),
       plus_product(minus_product(y.imag(), l.real(), x.imag()), l.imag(), x.real())};
}
/// d −= Re(l conj(x))
inline void subtract_real_product(double& d, double l, double x) { d = minus_product(d, l, x); }
inline void subtract_real_product(double& d, const std::complex<double>& l, const std::complex<double>& x) {
  d = minus_product(minus_product(d, l.real(), x.real()), l.imag(), x.imag());
}

/// Entry j of a dense row's or L's Row: Scalar, or std::array<Scalar, 2> for two matrices' entries side by side.
template <class Scalar>
Scalar& lane(Scalar& r, std::size_t) {
  return r;
}
template <class Scalar>
Scalar& lane(std::array<Scalar, 2>& r, std::size_t j) {
  return r[j];
}
template <class Scalar>
const Scalar& lane(const Scalar& r, std::size_t) {
  return r;
}
template <class Scalar>
const Scalar& lane(const std::array<Scalar, 2>& r, std::size_t j) {
  return r[j];
}

/// One column i of row k's pattern (Davis §4.7), in each lane: with x = y_i final, L(k, i) = x / D_i into L's
/// slot `slot`, D_k's share −Re(L(k, i) conj x) into d_k, and −conj(L(r, i)) x into y_r for the rows r of
/// column i above k (L's slots [first, slot)).
template <class Scalar, class Row, std::size_t lanes>
void eliminate_column(Row* __restrict y, const int* __restrict row, Row* __restrict l, int first, int slot,
                      std::size_t i, const std::array<Scalar*, lanes>& d, std::array<double, lanes>& d_k) {
  Row x = y[i];
  y[i] = Row{};
  for (std::size_t j = 0; j < lanes; ++j) {
    const Scalar l_ki = lane(x, j) / std::real(d[j][i]);
    subtract_real_product(d_k[j], l_ki, lane(x, j));
    lane(l[slot], j) = l_ki;
  }
  for (int p = first; p < slot; ++p)
    for (std::size_t j = 0; j < lanes; ++j) subtract_conj_product(lane(y[row[p]], j), lane(l[p], j), lane(x, j));
}

#if defined(__AVX__) && defined(__FMA__)
/// Two complex lanes in one 256-bit register, (re₀, im₀, re₁, im₁), with the same roundings lane by lane: the
/// quotients by IEEE division, D's shares by the same fused steps, and the rows' updates y − l_r x, then
/// + l_i (−x_i, x_r), each one fused step as subtract_conj_product's two.
template <>
void eliminate_column<std::complex<double>, std::array<std::complex<double>, 2>, 2>(
    std::array<std::complex<double>, 2>* __restrict y, const int* __restrict row,
    std::array<std::complex<double>, 2>* __restrict l, int first, int slot, std::size_t i,
    const std::array<std::complex<double>*, 2>& d, std::array<double, 2>& d_k) {
  auto* y_i = reinterpret_cast<double*>(y + i);
  const __m256d x = _mm256_loadu_pd(y_i);
  _mm256_storeu_pd(y_i, _mm256_setzero_pd());
  const double d_0 = d[0][i].real(), d_1 = d[1][i].real();
  const __m256d l_ki = _mm256_div_pd(x, _mm256_set_pd(d_1, d_1, d_0, d_0));
  _mm256_storeu_pd(reinterpret_cast<double*>(l + slot), l_ki);
  alignas(32) double x_[4], l_[4];
  _mm256_store_pd(x_, x), _mm256_store_pd(l_, l_ki);
  d_k[0] = minus_product(minus_product(d_k[0], l_[0], x_[0]), l_[1], x_[1]);
  d_k[1] = minus_product(minus_product(d_k[1], l_[2], x_[2]), l_[3], x_[3]);
  const __m256d x_turned = _mm256_xor_pd(_mm256_permute_pd(x, 0b0101), _mm256_set_pd(0.0, -0.0, 0.0, -0.0));
  for (int p = first; p < slot; ++p) {
    const __m256d l_p = _mm256_loadu_pd(reinterpret_cast<const double*>(l + p));
    auto* target = reinterpret_cast<double*>(y + row[p]);
    __m256d y_r = _mm256_loadu_pd(target);
    y_r = _mm256_fnmadd_pd(_mm256_permute_pd(l_p, 0b0000), x, y_r);
    y_r = _mm256_fmadd_pd(_mm256_permute_pd(l_p, 0b1111), x_turned, y_r);
    _mm256_storeu_pd(target, y_r);
  }
}
#endif

/// Rows of the factorisation of `lanes` matrices of one pattern in one pass (Davis §4.7 for each): the dense
/// row y and L's values hold each matrix's entries side by side (Row = Scalar, or std::array<Scalar, 2>), so
/// that the pattern's index lists are read once for all and each step loads the matrices' entries together;
/// D goes to each matrix's factor. Every lane takes the steps of a factorisation of its matrix alone, in the
/// same order.
template <class Scalar, std::size_t lanes>
struct Elimination {
  using Row = std::conditional_t<lanes == 1, Scalar, std::array<Scalar, lanes>>;

  const LdlSymbolic& s;
  std::array<const Scalar*, lanes> k_value;  ///< each matrix's values in K's compressed storage
  Row* l_value;                              ///< L's values in the slots of s.l_row
  std::array<Scalar*, lanes> d;              ///< D (real) per matrix
  std::array<Row*, 2> y, partial;            ///< per group of subtrees (simplicial_factor.hpp)

  /// Adds A's entries [first, last) of a row (LdlSymbolic::a_start) into y.
  void scatter(int first, int last, Row* y_g) const {
    for (int e = first; e < last; ++e) {
      const auto entry = static_cast<std::size_t>(e);
      Row& target = y_g[s.a_column[entry]];
      for (std::size_t j = 0; j < lanes; ++j) {
        const Scalar a = k_value[j][s.a_source[entry]];
        lane(target, j) += s.a_conjugated[entry] ? Eigen::numext::conj(a) : a;
      }
    }
  }

  // Row k of L solves L(0:k−1, 0:k−1) D l = A(0:k−1, k) over row k's pattern, in the order of ldl_symbolic.hpp
  // (Davis §4.7), column by column (eliminate_column) once A's row is scattered into y.
  void eliminate(int first, int last, Row* __restrict y_g, std::array<double, lanes>& d_row) const {
    std::array<double, lanes> d_k = d_row;  // in registers, not through the reference
    for (int q = first; q < last; ++q) {
      const auto i = static_cast<std::size_t>(s.r_column[static_cast<std::size_t>(q)]);
      eliminate_column<Scalar, Row, lanes>(y_g, s.l_row.data(), l_value, s.l_start[i],
                                           s.r_slot[static_cast<std::size_t>(q)], i, d, d_k);
    }
    d_row = d_k;
  }

  void set_d(std::size_t row, const std::array<double, lanes>& d_k) const {
    for (std::size_t j = 0; j < lanes; ++j) d[j][row] = d_k[j];
  }

  template <class Rows>
  void factorise_rows(const Rows& rows, Row* y_g) const {
    for (const auto k : rows) {
      const auto row = static_cast<std::size_t>(k);
      scatter(s.a_start[row], s.a_start[row + 1], y_g);
      std::array<double, lanes> d_k;
      for (std::size_t j = 0; j < lanes; ++j) d_k[j] = std::real(lane(y_g[row], j));
      y_g[row] = Row{};
      eliminate(s.r_start[row], s.r_start[row + 1], y_g, d_k);
      set_d(row, d_k);
    }
  }

  /// Group g's part of every top row, its sums left in partial[g] (LdlSymbolic::TopRow).
  void factorise_top_rows_in_group(std::size_t g) const {
    Row* y_g = y[g];
    for (std::size_t t = 0; t < s.top_rows.size(); ++t) {
      const auto row = static_cast<std::size_t>(s.subtrees->top[t]);
      const LdlSymbolic::TopRow& top = s.top_rows[t];
      scatter(g == 0 ? s.a_start[row] : top.a_end[0], top.a_end[g], y_g);
      std::array<double, lanes> d_share{};
      eliminate(g == 0 ? s.r_start[row] : top.r_end[0], top.r_end[g], y_g, d_share);
      // what the group's columns passed to the top's columns of the pattern, and its share of D_k
      Row* sums = partial[g] + top.partial;
      for (int q = top.r_end[1]; q < s.r_start[row + 1]; ++q) {
        const auto c = static_cast<std::size_t>(s.r_column[static_cast<std::size_t>(q)]);
        *sums++ = y_g[c], y_g[c] = Row{};
      }
      for (std::size_t j = 0; j < lanes; ++j) lane(*sums, j) = d_share[j];
    }
  }

  /// The top's part of every top row, after both groups'.
  void factorise_top_rows() const {
    Row* y_g = y[0];
    for (std::size_t t = 0; t < s.top_rows.size(); ++t) {
      const auto row = static_cast<std::size_t>(s.subtrees->top[t]);
      const LdlSymbolic::TopRow& top = s.top_rows[t];
      scatter(top.a_end[1], s.a_start[row + 1], y_g);
      const Row* sums[2] = {partial[0] + top.partial, partial[1] + top.partial};
      for (int q = top.r_end[1]; q < s.r_start[row + 1]; ++q) {
        const auto c = static_cast<std::size_t>(s.r_column[static_cast<std::size_t>(q)]);
        for (std::size_t j = 0; j < lanes; ++j)
          lane(y_g[c], j) += lane(*sums[0], j), lane(y_g[c], j) += lane(*sums[1], j);
        ++sums[0], ++sums[1];
      }
      std::array<double, lanes> d_k;
      for (std::size_t j = 0; j < lanes; ++j)
        d_k[j] = std::real(lane(y_g[row], j)) + std::real(lane(*sums[0], j)) + std::real(lane(*sums[1], j));
      y_g[row] = Row{};
      eliminate(top.r_end[1], s.r_start[row + 1], y_g, d_k);
      set_d(row, d_k);
    }
  }

  /// Every row: a group's rows reach only its own columns, and its part of a top row only its own columns and
  /// the top's rows; the top's part of each row comes after both groups'.
  void run(std::size_t threads) const {
    if (s.subtrees) {
      for_each_group(threads, [&](std::size_t g) {
        for (const auto& [column, root] : s.subtrees->ranges[g])
          factorise_rows(std::views::iota(column, root + 1), y[g]);
        factorise_top_rows_in_group(g);
      });
      factorise_top_rows();
    } else {
      factorise_rows(std::views::iota(Eigen::Index{0}, s.n), y[0]);
    }
  }
};

/// Whether D's pivots are all above 10⁻¹² times the largest (and finite).
template <class Scalar>
bool positive_definite(const std::vector<Scalar>& D) {
  double smallest = std::numeric_limits<double>::infinity(), largest = 0;
  for (const Scalar& pivot : D)  // real: D of an LDLᴴ factorisation
    smallest = std::min(smallest, std::real(pivot)), largest = std::max(largest, std::abs(pivot));
  // a zero or negative pivot (its row's quotients infinite or not a number) fails the ratio too
  return smallest > 1e-12 * largest && std::isfinite(largest);
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
  paired_l_.clear();
  for (auto& y : paired_y_) y.clear();
  for (auto& partial : paired_partial_) partial.clear();
}

template <class Scalar>
bool SimplicialFactor<Scalar>::factorise(const SparseMatrix& K, std::size_t threads) {
  SparseMatrix storage;
  const SparseMatrix& C = compressed(K, storage);
  Elimination<Scalar, 1>{*symbolic_,
                         {C.valuePtr()},
                         l_value_.data(),
                         {d_.data()},
                         {y_[0].data(), y_[1].data()},
                         {partial_[0].data(), partial_[1].data()}}
      .run(threads);
  return positive_definite(d_);
}

template <class Scalar>
bool SimplicialFactor<Scalar>::factorise_two(const SparseMatrix& K, SparseFactor<Scalar>& other,
                                             const SparseMatrix& K_other) {
  auto* second = dynamic_cast<SimplicialFactor*>(&other);
  if (!second || second->symbolic_ != symbolic_) return SparseFactor<Scalar>::factorise_two(K, other, K_other);
  SparseMatrix storage[2];
  const SparseMatrix &A = compressed(K, storage[0]), &B = compressed(K_other, storage[1]);
  if (paired_l_.empty()) {  // kept from pair to pair (fresh pages for each would cost page faults)
    paired_l_.resize(l_value_.size());
    for (auto& y : paired_y_) y.assign(static_cast<std::size_t>(symbolic_->n), {});
    for (auto& partial : paired_partial_) partial.assign(symbolic_->partial_size, {});
  }
  Elimination<Scalar, 2>{*symbolic_,
                         {A.valuePtr(), B.valuePtr()},
                         paired_l_.data(),
                         {d_.data(), second->d_.data()},
                         {paired_y_[0].data(), paired_y_[1].data()},
                         {paired_partial_[0].data(), paired_partial_[1].data()}}
      .run(1);
  for (std::size_t p = 0; p < paired_l_.size(); ++p)  // each factor's L for its solves
    l_value_[p] = paired_l_[p][0], second->l_value_[p] = paired_l_[p][1];
  return positive_definite(d_) && positive_definite(second->d_);
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
