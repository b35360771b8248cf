#pragma once
// Ours ("affinterp"): functions of S ∈ Sym(3) through the spectral split of spectral_split.hpp.
// exp is accurate to a few units of roundoff times max(1, ‖S‖₂) for every spectrum (clustered, repeated,
// wide, |λ| up to 700) and needs no eigenvalue gap in a denominator; no heap allocation.
#include "theory/sym3/algorithms.hpp"

namespace affinterp::sym3 {

/// exp(S) for S ∈ Sym(3) (the upper triangle is read).
Mat3 exp_affinterp(const Mat3& S);
/// Eigenvalues of S ∈ Sym(3), ascending, each with absolute error of order roundoff · ‖S‖.
Vec3 eigenvalues_affinterp(const Mat3& S);
/// S^t for symmetric positive definite S (real t); throws std::domain_error if S is not SPD.
Mat3 pow_spd(const Mat3& S, double t);
/// The principal logarithm of symmetric positive definite S; throws std::domain_error if S is not SPD.
Mat3 log_spd(const Mat3& S);

}  // namespace affinterp::sym3
