#pragma once
// Rational symmetric matrices with exactly known eigenvalues, for deciding the chapter-3 claims:
// S = Q diag(λ) Qᵀ with Q = (I − K)(I + K)⁻¹ the Cayley transform of a rational skew-symmetric K, an
// exact rational orthogonal matrix.
#include "experiments/support/random.hpp"
#include "theory/exact/rational.hpp"
#include "theory/sym3/reference.hpp"

#include <array>

namespace affinterp::claims::sym3 {

using exact::Mat3Q;
using exact::Rational;
using Vec3Q = Eigen::Matrix<Rational, 3, 1>;

/// Resolution of the 100-digit comparisons: deviations below this are rounding, above it a failure.
inline constexpr const char* kResolution = "1e-80";

/// The Cayley transform (I − K)(I + K)⁻¹ of the skew matrix K with axial vector k (K v = k × v):
/// exact, orthogonal, det +1.
Mat3Q cayley(const Vec3Q& k);

/// A rational S ∈ Sym(3) with eigenvalues lambda, and the orthogonal Q with S = Q diag(lambda) Qᵀ.
struct ExactSpectrum {
  Vec3Q lambda;
  Mat3Q Q;
  Mat3Q S;
};
ExactSpectrum with_exact_eigenvalues(const Vec3Q& lambda, const Vec3Q& k);

/// A small rational: p/q with |p| ≤ max_numerator, 1 ≤ q ≤ max_denominator.
Rational small_rational(Rng& rng, int max_numerator, int max_denominator);
/// A random axial vector of small rationals (entries p/q, |p| ≤ 3, q ≤ 2).
Vec3Q small_axis(Rng& rng);

/// exp S = Q diag(e^λ) Qᵀ at 100 digits, from the exact eigen-decomposition.
affinterp::sym3::Mat3R100 exact_exp(const ExactSpectrum& e);

/// ‖A − B‖_F / ‖B‖_F at 100 digits.
exact::Real100 relative_deviation(const affinterp::sym3::Mat3R100& A, const affinterp::sym3::Mat3R100& B);

}  // namespace affinterp::claims::sym3
