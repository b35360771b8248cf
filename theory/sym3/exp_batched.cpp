// Ours, batched: the spectral split of spectral_split.hpp evaluated on xsimd batches (as many matrices
// as the widest SIMD register of the build holds), structure-of-arrays inside each batch.
#include "theory/sym3/affinterp.hpp"
#include "theory/sym3/spectral_split.hpp"

#include <functional>
#include <stdexcept>
#include <xsimd/xsimd.hpp>

namespace affinterp::sym3 {
namespace {

using Batch = xsimd::batch<double>;
constexpr std::size_t W = Batch::size;

/// Two batches as one lane type for spectral_split.hpp: every operation is issued for both halves side by side,
/// so that the split's long chain of dependent operations (divisions and square roots among them) runs as two
/// independent chains the core overlaps. The same operations per lane as on a Batch, so the same results.
struct Twin {
  Batch a, b;
  Twin() = default;
  Twin(Batch a_, Batch b_) : a(a_), b(b_) {}
  explicit Twin(double x) : a(x), b(x) {}
};
struct TwinMask {
  Batch::batch_bool_type a, b;
};
/// `f` on the two halves.
template <class R = Twin, class F>
R both(F f, const Twin& x, const Twin& y) {
  return {f(x.a, y.a), f(x.b, y.b)};
}
inline Twin operator+(const Twin& x, const Twin& y) { return both(std::plus<>(), x, y); }
inline Twin operator-(const Twin& x, const Twin& y) { return both(std::minus<>(), x, y); }
inline Twin operator*(const Twin& x, const Twin& y) { return both(std::multiplies<>(), x, y); }
inline Twin operator/(const Twin& x, const Twin& y) { return both(std::divides<>(), x, y); }
inline TwinMask operator<(const Twin& x, const Twin& y) { return both<TwinMask>(std::less<>(), x, y); }
inline TwinMask operator>(const Twin& x, const Twin& y) { return both<TwinMask>(std::greater<>(), x, y); }
inline TwinMask operator<=(const Twin& x, const Twin& y) { return both<TwinMask>(std::less_equal<>(), x, y); }
inline TwinMask operator>=(const Twin& x, const Twin& y) { return both<TwinMask>(std::greater_equal<>(), x, y); }
inline TwinMask operator==(const Twin& x, const Twin& y) { return both<TwinMask>(std::equal_to<>(), x, y); }
inline TwinMask operator!=(const Twin& x, const Twin& y) { return both<TwinMask>(std::not_equal_to<>(), x, y); }
inline TwinMask operator&(const TwinMask& x, const TwinMask& y) { return {x.a & y.a, x.b & y.b}; }
inline TwinMask operator|(const TwinMask& x, const TwinMask& y) { return {x.a | y.a, x.b | y.b}; }
inline TwinMask operator!(const TwinMask& x) { return {!x.a, !x.b}; }
inline bool any(const TwinMask& m) { return xsimd::any(m.a | m.b); }
inline Twin select(const TwinMask& m, const Twin& x, const Twin& y) {
  return {xsimd::select(m.a, x.a, y.a), xsimd::select(m.b, x.b, y.b)};
}
inline Twin abs(const Twin& x) { return {xsimd::abs(x.a), xsimd::abs(x.b)}; }
inline Twin sqrt(const Twin& x) { return {xsimd::sqrt(x.a), xsimd::sqrt(x.b)}; }
inline Twin exp(const Twin& x) { return {xsimd::exp(x.a), xsimd::exp(x.b)}; }
inline Twin expm1(const Twin& x) { return {xsimd::expm1(x.a), xsimd::expm1(x.b)}; }
inline Twin max(const Twin& x, const Twin& y) {
  return both([](Batch p, Batch q) { return xsimd::max(p, q); }, x, y);
}
inline Twin copysign(const Twin& x, const Twin& y) {
  return both([](Batch p, Batch q) { return xsimd::copysign(p, q); }, x, y);
}

/// One batch's entries, one row per entry of split::Sym (xx, yy, zz, xy, xz, yz), a column per matrix.
struct alignas(64) Lanes {
  double entry[6][W];
};

/// Matrices in[0..W) as a batch, through `lanes`.
split::Sym<Batch> load(const Mat3* in, Lanes& lanes) {
  for (std::size_t j = 0; j < W; ++j) {
    const Mat3& S = in[j];
    lanes.entry[0][j] = S(0, 0), lanes.entry[1][j] = S(1, 1), lanes.entry[2][j] = S(2, 2);
    lanes.entry[3][j] = S(0, 1), lanes.entry[4][j] = S(0, 2), lanes.entry[5][j] = S(1, 2);
  }
  return {Batch::load_aligned(lanes.entry[0]), Batch::load_aligned(lanes.entry[1]),
          Batch::load_aligned(lanes.entry[2]), Batch::load_aligned(lanes.entry[3]),
          Batch::load_aligned(lanes.entry[4]), Batch::load_aligned(lanes.entry[5])};
}

/// out[j] = exp(in[j]) for j < W from the batch X = exp S, through `lanes`. Entries beyond kWideEntry: the
/// split's range ends there (spectral_split.hpp); the scalar function takes those matrices to wide_range.
void store(const split::Sym<Batch>& X, const split::Sym<Batch>& S, const Mat3* in, Mat3* out, Lanes& lanes) {
  X.xx.store_aligned(lanes.entry[0]), X.yy.store_aligned(lanes.entry[1]), X.zz.store_aligned(lanes.entry[2]);
  X.xy.store_aligned(lanes.entry[3]), X.xz.store_aligned(lanes.entry[4]), X.yz.store_aligned(lanes.entry[5]);
  for (std::size_t j = 0; j < W; ++j) {
    Mat3& E = out[j];
    E(0, 0) = lanes.entry[0][j], E(1, 1) = lanes.entry[1][j], E(2, 2) = lanes.entry[2][j];
    E(0, 1) = E(1, 0) = lanes.entry[3][j], E(0, 2) = E(2, 0) = lanes.entry[4][j];
    E(1, 2) = E(2, 1) = lanes.entry[5][j];
  }
  if (xsimd::any(split::max_abs(S) > Batch(split::kWideEntry)))
    for (std::size_t j = 0; j < W; ++j)
      if (in[j].triangularView<Eigen::Upper>().toDenseMatrix().cwiseAbs().maxCoeff() > split::kWideEntry)
        out[j] = exp_affinterp(in[j]);
}

}  // namespace

// Flattened so that the split and the exponential stay in registers (no struct round trips). Two batches a step,
// as a Twin: two independent chains keep the core busy where a single chain leaves it waiting on each step's
// latency (bench_exp3's exp3/affinterp-batched measures it).
[[gnu::flatten]] void exp_batched(std::span<const Mat3> in, std::span<Mat3> out) {
  if (in.size() != out.size()) throw std::invalid_argument("exp_batched: input and output sizes differ");
  const std::size_t full = in.size() / W * W;
  std::size_t i = 0;
  for (; i + 2 * W <= full; i += 2 * W) {
    Lanes lanes0, lanes1;
    const split::Sym<Batch> S0 = load(&in[i], lanes0), S1 = load(&in[i + W], lanes1);
    const split::Sym<Twin> S{{S0.xx, S1.xx}, {S0.yy, S1.yy}, {S0.zz, S1.zz},
                             {S0.xy, S1.xy}, {S0.xz, S1.xz}, {S0.yz, S1.yz}};
    const split::Sym<Twin> X = split::exp_from_split(split::spectral_split(S));
    store({X.xx.a, X.yy.a, X.zz.a, X.xy.a, X.xz.a, X.yz.a}, S0, &in[i], &out[i], lanes0);
    store({X.xx.b, X.yy.b, X.zz.b, X.xy.b, X.xz.b, X.yz.b}, S1, &in[i + W], &out[i + W], lanes1);
  }
  for (; i < full; i += W) {
    Lanes lanes;
    const split::Sym<Batch> S = load(&in[i], lanes);
    store(split::exp_from_split(split::spectral_split(S)), S, &in[i], &out[i], lanes);
  }
  for (; i < in.size(); ++i) out[i] = exp_affinterp(in[i]);
}

}  // namespace affinterp::sym3
