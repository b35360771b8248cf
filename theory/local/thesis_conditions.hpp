#pragma once
// The conditions of the thesis's goodness theorems exactly as printed (Matsushita 2015, §2.2), and the
// corrected area condition that the exact deciders of goodness.hpp support. Templated on an exact field.
namespace affinterp::local {

/// Thm 2.2.1 as printed: (tr ≥ det + 1) ∨ (2 det ≤ tr < 2) ∨ (2 ≤ tr < 2 det). Thms 2.2.2 and 2.2.4 print
/// the same condition with tr D, resp. tr S, in place of tr A (and det A).
template <class F>
bool thm_2_2_1_condition(const F& trace, const F& det) {
  return trace >= det + F(1) || (F(2) * det <= trace && trace < F(2)) || (F(2) <= trace && trace < F(2) * det);
}

/// The corrected area condition: det((1−t)I + tB) = 1 + (tr B − 2)t + (1 − tr B + det B)t² has slope
/// tr B − 2 at t = 0 and 2 det B − tr B at t = 1, so it is monotone on [0, 1] iff these do not differ
/// in sign: (2 det ≤ tr ≤ 2) ∨ (2 ≤ tr ≤ 2 det). (Thm 2.2.1's case (iii) divides by the negative
/// 1 − tr A + det A without flipping the inequalities, which adds the false branch tr ≥ det + 1.)
template <class F>
bool corrected_area_condition(const F& trace, const F& det) {
  return (F(2) * det <= trace && trace <= F(2)) || (F(2) <= trace && trace <= F(2) * det);
}

/// Thm 2.2.3 as printed: (x ≥ 1 ∧ y ≥ 1) ∨ (0 < x ≤ 1 ∧ 0 < y ≤ 1), D = diag(x, y).
template <class F>
bool thm_2_2_3_condition(const F& x, const F& y) {
  return (x >= F(1) && y >= F(1)) || (F(0) < x && x <= F(1) && F(0) < y && y <= F(1));
}

/// Thm 2.2.5 as printed: ((x−1)(y−1) ≥ h²) ∧ ((x + y ≥ 2) ∨ (0 < x ≤ 1 ∧ 0 < y ≤ 1)), S = [[x, h], [h, y]].
template <class F>
bool thm_2_2_5_condition(const F& x, const F& y, const F& h) {
  return (x - F(1)) * (y - F(1)) >= h * h && (x + y >= F(2) || (F(0) < x && x <= F(1) && F(0) < y && y <= F(1)));
}

}  // namespace affinterp::local
