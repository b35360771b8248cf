#pragma once
// Thesis Defs 2.2.1 (good for area) and 2.2.2 (good for norm) as first-order formulas over the reals:
// the properties in the sentences that prove the local claims and the goodness atlas for all reals
// (condition_sentences.hpp).
// Every polynomial is built from the homotopy itself, A(t) = U(t)((1−t)I + tB)V(t) with rotations U, V that
// leave det and ‖·‖ alone (Lemma L5): det((1−t)I + tB) and ‖((1−t)I + tB)v‖², the same formulas that
// theory/local/goodness.hpp decides exactly at rational points. A property is written at one encoding level
// (reports/proofs/LEMMAS.md), each step a lemma:
//   L  as written: monotone = ∀ 0 ≤ s ≤ t ≤ 1: f(s) ≤ f(t) (or ≥); unit v, v1² + v2² = 1
//   D  monotone ⇔ f′ ≥ 0 on [0, 1] or f′ ≤ 0 on [0, 1]                                         (L1)
//   E  f′ affine in t: its sign on [0, 1] read at t = 0 and t = 1                              (L2, L3)
//   N  norm: no v with P(v) < 0 < Q(v) ⇔ Q ⪯ 0 or ∃ν ≥ 0: P − νQ ⪰ 0                          (L6, L8)
//   G  svd norm: ∀t ∈ [0, 1]: G(t) ≥ 0                                                          (L9)
#include "theory/logic/formula.hpp"

#include <array>
#include <string>

namespace affinterp::proofs {

using logic::Formula;
using logic::Polynomial;

/// A 2×2 matrix with polynomial entries, [row][column].
using PolyMat2 = std::array<std::array<Polynomial, 2>, 2>;

Polynomial var(const std::string& name);
Polynomial det(const PolyMat2& W);
Polynomial trace(const PolyMat2& W);
PolyMat2 product(const PolyMat2& A, const PolyMat2& B);
PolyMat2 transpose(const PolyMat2& A);
/// R = [[c, −s], [s, c]] (a rotation when c² + s² = 1).
PolyMat2 rotation(const Polynomial& c, const Polynomial& s);

/// (1 − t)I + tB.
PolyMat2 blend(const PolyMat2& B, const Polynomial& t);
/// det((1 − t)I + tB), a polynomial of degree ≤ 2 in t (det A(t) of every homotopy here, Lemma L5).
Polynomial det_of_blend(const PolyMat2& B, const std::string& t);
/// ‖((1 − t)I + tB)v‖² for v = (v1, v2).
Polynomial norm_squared_of_blend(const PolyMat2& B, const Polynomial& v1, const Polynomial& v2, const std::string& t);

/// 0 ≤ t ≤ 1.
Formula on_unit_interval(const Polynomial& t);
/// ∀t ∈ [0, 1]: body.
Formula for_all_times(const std::string& t, const Formula& body);
/// W ⪰ 0 for symmetric W (diagonal and determinant ≥ 0).
Formula positive_semidefinite(const PolyMat2& W);

/// f(t) weakly monotone on [0, 1] as written: ∀ 0 ≤ s ≤ t ≤ 1: f(s) ≤ f(t), or all ≥ (level L).
Formula monotone_literal(const Polynomial& f, const std::string& t);
/// f′ ≥ 0 on [0, 1] or f′ ≤ 0 on [0, 1] (level D, Lemma L1).
Formula monotone_derivative(const Polynomial& f, const std::string& t);
/// f′ does not take opposite strict signs at t = 0 and t = 1 (level E; Lemma L2 when f′ is affine).
Formula monotone_endpoints(const Polynomial& f, const std::string& t);

/// Def 2.2.1 for det A(t) = det((1−t)I + tB) at level "L", "D" or "E" (E needs deg_t ≤ 2 and f(0) = 1, L2).
Formula area_property(const PolyMat2& B, const std::string& level);
/// Def 2.2.2 for ‖((1−t)I + tB)v‖ at level "L" (unit v, the squared norm monotone as written: L4), "D" (unit v,
/// derivative), "E" (unit v, ¬(P(v) < 0 < Q(v)), L3, L4)
/// or "N" (Dines, L6, L8), with P = sym M, Q = P + MᵀM, M = B − I.
Formula norm_property(const PolyMat2& B, const std::string& level);

/// Def 2.2.2 for ‖((1−t)I + tB)v‖ over the directions v = (1, m), every real m, and v = (0, 1): every unit vector
/// is a non-zero multiple of one (Lemma L6, decided as lemma_L6_directions) and ‖A(t)(λv)‖ = |λ|‖A(t)v‖. At level
/// "L" (the squared norm monotone as written, for all 0 <= s <= t <= 1; Lemma L4), "D" (L1) or "E" (L1, L2); m is
/// bound inside. No lemma about quadratic forms (L3, Dines' L8) is used.
Formula norm_property_directions(const PolyMat2& B, const std::string& level);

/// Lemma L9's G(t) = 4(x−1)(y−1)(1 + t(x−1))(1 + t(y−1)) − β²t²(x−y)²(2 + t(x+y−2))² for the SVD homotopy.
Polynomial svd_norm_G(const Polynomial& x, const Polynomial& y, const Polynomial& beta, const Polynomial& t);
/// Def 2.2.2 for R_{tα}((1−t)I + tD)R_{tβ}, D = diag(x, y): ∀t ∈ [0, 1] G(t) ≥ 0 (level G, Lemma L9).
Formula svd_norm_property(const Polynomial& x, const Polynomial& y, const Polynomial& beta);

}  // namespace affinterp::proofs
