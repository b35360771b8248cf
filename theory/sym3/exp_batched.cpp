// Ours, batched: the spectral split of spectral_split.hpp evaluated on xsimd batches (as many matrices
// as the widest SIMD register of the build holds), structure-of-arrays inside each batch.
#include "theory/sym3/affinterp.hpp"
#include "theory/sym3/spectral_split.hpp"

#include <stdexcept>
#include <xsimd/xsimd.hpp>

namespace affinterp::sym3 {

// Flattened so that the split and the exponential stay in registers (no struct round trips).
[[gnu::flatten]] void exp_batched(std::span<const Mat3> in, std::span<Mat3> out) {
  if (in.size() != out.size()) throw std::invalid_argument("exp_batched: input and output sizes differ");
  using Batch = xsimd::batch<double>;
  constexpr std::size_t W = Batch::size;
  const std::size_t full = in.size() / W * W;
  for (std::size_t i = 0; i < full; i += W) {
    alignas(64) double lanes[6][W];
    for (std::size_t j = 0; j < W; ++j) {
      const Mat3& S = in[i + j];
      lanes[0][j] = S(0, 0), lanes[1][j] = S(1, 1), lanes[2][j] = S(2, 2);
      lanes[3][j] = S(0, 1), lanes[4][j] = S(0, 2), lanes[5][j] = S(1, 2);
    }
    const split::Sym<Batch> S{Batch::load_aligned(lanes[0]), Batch::load_aligned(lanes[1]),
                              Batch::load_aligned(lanes[2]), Batch::load_aligned(lanes[3]),
                              Batch::load_aligned(lanes[4]), Batch::load_aligned(lanes[5])};
    const split::Sym<Batch> X = split::exp_from_split(split::spectral_split(S));
    X.xx.store_aligned(lanes[0]), X.yy.store_aligned(lanes[1]), X.zz.store_aligned(lanes[2]);
    X.xy.store_aligned(lanes[3]), X.xz.store_aligned(lanes[4]), X.yz.store_aligned(lanes[5]);
    for (std::size_t j = 0; j < W; ++j) {
      Mat3& E = out[i + j];
      E(0, 0) = lanes[0][j], E(1, 1) = lanes[1][j], E(2, 2) = lanes[2][j];
      E(0, 1) = E(1, 0) = lanes[3][j], E(0, 2) = E(2, 0) = lanes[4][j], E(1, 2) = E(2, 1) = lanes[5][j];
    }
    // Entries beyond kWideEntry: the split's range ends there (spectral_split.hpp); the scalar function
    // takes those matrices to wide_range.
    if (xsimd::any(split::max_abs(S) > Batch(split::kWideEntry))) {
      for (std::size_t j = i; j < i + W; ++j)
        if (in[j].triangularView<Eigen::Upper>().toDenseMatrix().cwiseAbs().maxCoeff() > split::kWideEntry)
          out[j] = exp_affinterp(in[j]);
    }
  }
  for (std::size_t i = full; i < in.size(); ++i) out[i] = exp_affinterp(in[i]);
}

}  // namespace affinterp::sym3
