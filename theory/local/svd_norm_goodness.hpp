#pragma once
// Def 2.2.2 (good for norm) for the SVD homotopy A_s(t) = R_{tα}((1−t)I + tD)R_{tβ} of thesis Def 2.2.4,
// D = diag(x, y), x, y > 0, decided exactly. The homotopy depends on the real angle β (radians), not only on
// the rotation R_β; α plays no part (R_{tα} is orthogonal).
//
// Lemma L9 (reports/proofs/LEMMAS.md): with m1 = x − 1, m2 = y − 1, a = 1 + t m1, b = 1 + t m2 and
// ψ = φ + tβ for v = (cos φ, sin φ), ‖A_s(t)v‖² = a² cos²ψ + b² sin²ψ and its t-derivative is
// 2 (cos ψ, sin ψ) G_t (cos ψ, sin ψ)ᵀ with G_t = [[m1 a, β(b² − a²)/2], [β(b² − a²)/2, m2 b]]; A_s is good for
// norm iff G(t) = 4 det G_t ≥ 0 for every t in [0, 1].
// Lemma L12 (worst time t = 1): on x, y > 0 that holds iff G(1) ≥ 0, i.e.
//     β² (x − y)² (x + y)² ≤ 4xy (x − 1)(y − 1).
// Both lemmas are proved in reports/proofs/LEMMAS.md (L12 also by quantifier elimination: atlas.svd.norm).
#include "theory/exact/rational.hpp"

namespace affinterp::local {

/// G(1) = 4 det G_1 of Lemma L9 as a function of β²: 4xy(x − 1)(y − 1) − β²(x − y)²(x + y)².
template <class F>
F svd_norm_margin(const F& x, const F& y, const F& beta_squared) {
  const F difference = x - y, sum = x + y;
  return F(4) * x * y * (x - F(1)) * (y - F(1)) - beta_squared * difference * difference * sum * sum;
}

/// Def 2.2.2 for A_s(t) with D = diag(x, y), x, y > 0, and right angle β given by β² (Lemmas L9, L12):
/// exact for an exact field F.
template <class F>
bool svd_good_for_norm(const F& x, const F& y, const F& beta_squared) {
  return svd_norm_margin(x, y, beta_squared) >= F(0);
}

/// Def 2.2.2 for A_s(t) with rational x, y > 0 and β = π·beta_over_pi, decided exactly: G(1) = a − π²c with
/// rational a, c, and π² is irrational, so G(1) = 0 only when c = 0; otherwise the sign of a/c − π² is read
/// against rational bounds on π (40 digits). Throws std::domain_error if a/c lies within them (never for
/// rationals of moderate height).
bool svd_good_for_norm_at_pi_multiple(const exact::Rational& x, const exact::Rational& y,
                                      const exact::Rational& beta_over_pi);

}  // namespace affinterp::local
