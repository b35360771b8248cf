#pragma once
// Ours beyond the reach of double arithmetic: the same functions of S ∈ Sym(3) evaluated on an
// eigen-decomposition computed at 1152 or 2304 bits (cyclic Jacobi in Boost's cpp_bin_float, whose
// exponent range is unbounded for our purposes), then rounded once to double.
//
// Why: any double eigen-solver has absolute eigenvalue errors of about ε‖S‖. When ‖S‖ is huge
// (diag(−10³⁰⁰, 1, 2), or Q diag(−10³⁰⁰, 0, 0) Qᵀ rounded to double) the moderate eigenvalues that
// decide exp S, and whether exp S overflows at all, are lost; when S is SPD the small eigenvalues that
// decide S^t and log S carry relative errors ε κ₂(S) (all of them beyond 1/ε, where even positive
// definiteness is lost). affinterp.cpp sends exactly those matrices
// here (max |S_ij| > 2⁴⁰ for exp; κ₂ beyond 2²⁰ for S^t and log), so the double path keeps its speed and
// only these rare matrices pay for the wide arithmetic.
//
// Accuracy: 1152 bits resolve eigenvalues to 2⁻¹¹⁵⁰‖S‖ ≤ 2⁻¹²⁴ absolutely, enough for exp of any double
// matrix; S^t and log need the smallest eigenvalue to relative accuracy and use 2304 bits when 1152 do
// not give 64 correct bits of it.
#include "theory/sym3/algorithms.hpp"

namespace affinterp::sym3::wide_range {

/// exp(S) for any finite symmetric S (upper triangle read). Entries beyond the largest double are +∞
/// (exp S overflows); entries below the smallest subnormal are 0.
Mat3 exp(const Mat3& S);
/// Eigenvalues of S, ascending, correctly rounded to double up to an absolute error 2⁻¹¹⁴⁰‖S‖_F
/// (±∞ beyond the double range).
Vec3 eigenvalues(const Mat3& S);
/// S^t for symmetric positive definite S. Throws std::domain_error when S is not positive definite,
/// decided exactly (leading principal minors in rational arithmetic).
Mat3 pow_spd(const Mat3& S, double t);
/// The principal logarithm of symmetric positive definite S; std::domain_error as pow_spd.
Mat3 log_spd(const Mat3& S);

}  // namespace affinterp::sym3::wide_range
