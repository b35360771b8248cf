#pragma once
// The external published theorems a proof uses as a step (Proof::cites, strength "proved, citing"), with their
// full references. Every other step is a decided sentence, a stored identity or a lemma written out in
// reports/proofs/LEMMAS.md.
#include <string_view>

namespace affinterp::proofs::citations {

/// Lemma L8 (level N of Def 2.2.2): for real quadratic forms P, Q on ℝ² with no v such that P(v) < 0 < Q(v),
/// Q ⪯ 0 or P − νQ ⪰ 0 for some ν ≥ 0.
inline constexpr std::string_view dines =
    "Dines' theorem: L. L. Dines, On the mapping of quadratic forms, Bull. Amer. Math. Soc. 47 (1941) 494-498";

/// Lemma L18 (the 3D linear norm): Dines' theorem holds for quadratic forms on ℝⁿ, every n (the joint range
/// {(P(v), Q(v))} is a convex cone), and a symmetric matrix is positive semidefinite iff every principal minor is ≥ 0.
inline constexpr std::string_view dines_and_principal_minors =
    "Dines' theorem on R^n: L. L. Dines, On the mapping of quadratic forms, Bull. Amer. Math. Soc. 47 (1941) "
    "494-498; principal minors: R. A. Horn, C. R. Johnson, Matrix Analysis, 2nd ed., Cambridge 2013, "
    "Theorem 7.2.5";

/// Lemma L10 (the exp-log homotopy): t ↦ c^t = exp(t log c) is positive, and strictly monotone unless c = 1.
inline constexpr std::string_view exponential =
    "the real exponential is positive and strictly increasing: W. Rudin, Principles of Mathematical Analysis, "
    "3rd ed., McGraw-Hill 1976, Theorem 8.6";

}  // namespace affinterp::proofs::citations
