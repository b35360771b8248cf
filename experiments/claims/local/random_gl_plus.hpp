#pragma once
// Random matrices of GL+(2) in Real50 (50 digits), for the claims on the exp-log homotopy A^E(t) = R_{tθ} S^t
// (Kaji eq. (3)), which is transcendental in t.
#include "experiments/support/random.hpp"
#include "theory/exact/rational.hpp"
#include "theory/local/local.hpp"

#include <cmath>
#include <numbers>

namespace affinterp::claims::local {

using affinterp::local::Mat2;
using affinterp::local::Svd;
using exact::Real50;

/// A random A = R_α diag(x, y) R_β ∈ GL+(2) in Real50 with 1 ≤ x/y ≤ max_ratio and det A in [1/16, 16].
inline Mat2<Real50> random_gl_plus(Rng& rng, double max_ratio) {
  const double log_det = rng.uniform(-std::log(16.0), std::log(16.0)), log_ratio = rng.uniform(0, std::log(max_ratio));
  const Real50 x = exp(Real50((log_det + log_ratio) / 2)), y = exp(Real50((log_det - log_ratio) / 2));
  return Svd<Real50>{Real50(rng.uniform(-std::numbers::pi, std::numbers::pi)), x, y,
                     Real50(rng.uniform(-std::numbers::pi, std::numbers::pi))}
      .matrix();
}

}  // namespace affinterp::claims::local
