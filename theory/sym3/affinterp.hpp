#pragma once
// Ours ("affinterp"): functions of S ∈ Sym(3) through the spectral split of spectral_split.hpp, for every
// finite double matrix: subnormal, tiny, huge and mixed-scale entries, spectra whose exponential is near
// overflow or subnormal. No eigenvalue gap is divided by; no heap allocation on the double path.
//
// Where double arithmetic cannot decide the answer (exp: an entry beyond 2⁴⁰, so that the absolute
// eigenvalue error ε‖S‖ exceeds 10⁻⁴; S^t and log: κ₂(S) beyond 2²⁰) the matrix goes to
// wide_range.hpp (an eigen-decomposition at 1152 or 2304 bits, far slower); every bound below
// covers both paths and is tested against Arb-certified references (checks/sym3/full_range_test.cpp).
// ε = 2⁻⁵³; κ₂ = λmax/λmin.
#include "theory/sym3/algorithms.hpp"

namespace affinterp::sym3 {

/// exp(S) for S ∈ Sym(3) (the upper triangle is read). Where exp S is finite in double,
///   ‖X − exp S‖_F ≤ 2·10⁻¹⁵ max(1, ‖S‖₂) ‖exp S‖_F + 2⁻¹⁰⁷²
/// (the last term: entries near and below the smallest normal double, rounded once). Where an entry of
/// exp S exceeds the largest double (λmax > log DBL_MAX ≈ 709.78, up to log 3 more when the eigenvector
/// is spread), the result has an infinite or NaN entry; nowhere else (up to the bound at the threshold).
Mat3 exp_affinterp(const Mat3& S);
/// Eigenvalues of S ∈ Sym(3), ascending, each with absolute error at most 4·10⁻¹⁵ max(1, ‖S‖₂); those
/// beyond the double range are ±∞.
Vec3 eigenvalues_affinterp(const Mat3& S);
/// S^t for symmetric positive definite S (real t): where S^t is finite in double,
///   ‖X − S^t‖_F ≤ 16 ε (1 + |t|) min(κ₂, 2²⁰)^c ‖S^t‖_F,  c = clamp(1 − t, 0, 1).
/// Throws std::domain_error if S is not SPD, decided exactly (not by the rounded eigenvalues).
Mat3 pow_spd(const Mat3& S, double t);
/// The principal logarithm of symmetric positive definite S:
///   ‖X − log S‖_F ≤ 16 ε (‖log S‖_F + min(κ₂, 2²⁰)).
/// Throws std::domain_error if S is not SPD, decided exactly.
Mat3 log_spd(const Mat3& S);

}  // namespace affinterp::sym3
