#pragma once
// A brute-force reference for the exact decider of theory/local/svd_norm_goodness.hpp (tests only).
// Def 2.2.2 for the SVD homotopy A_s(t) = R_{tα}((1−t)I + tD)R_{tβ} (thesis Def 2.2.4), which is not
// polynomial in t: ‖A_s(t)v‖² = ‖((1−t)I + tD) R_{tβ} v‖² (R_{tα} is orthogonal and drops out, so α does
// not matter) is sampled on a grid of directions v = (cos φ, sin φ) and times t, in double precision.
// A direction fails when its sampled ‖A_s(t)v‖² both rises and falls by more than a relative tolerance;
// the witness is three grid times t_a < t_b < t_c where the middle value is an extreme, which a caller
// re-verifies in high precision. "Good" means no such direction at the stated resolution.
#include <cstddef>
#include <optional>

namespace affinterp::local {

struct SamplingResolution {
  std::size_t directions = 96;  ///< φ = kπ/directions, k < directions (v and −v give the same norm)
  std::size_t times = 96;       ///< t = j/times, j ≤ times
  double relative_tolerance = 1e-9;
};

struct NormWitness {
  double phi;            ///< v = (cos φ, sin φ)
  double t_a, t_b, t_c;  ///< ‖A(t_b)v‖ is above both or below both of ‖A(t_a)v‖, ‖A(t_c)v‖
};

/// ‖((1−t)I + tD) R_{tβ} v‖² for v = (cos φ, sin φ), D = diag(x, y).
double svd_norm_squared(double x, double y, double beta, double phi, double t);

/// A failing direction of the SVD homotopy with singular values (x, y) and right angle β, if any is
/// found at `resolution`.
std::optional<NormWitness> svd_norm_failure(double x, double y, double beta, const SamplingResolution& resolution);

}  // namespace affinterp::local
