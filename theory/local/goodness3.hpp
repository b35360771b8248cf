#pragma once
// "Good" interpolations of 3×3 maps, decided exactly at rational points: the 3D counterparts of thesis Defs
// 2.2.1 and 2.2.2 (reports/proofs/LEMMAS.md, "3D"): for A ∈ GL⁺(3) and A(t) with A(0) = I, A(1) = A,
//   good for volume  det A(t) monotone and positive on [0, 1];
//   good for norm    ‖A(t)v‖ monotone on [0, 1] for every v.
// Every homotopy here has the form A(t) = U(t)((1−t)I + tB)V(t) or U(t)B^tV(t) with rotations U, V of det 1
// that leave det and, on the left, ‖·‖ alone (Lemma L14), so the deciders take B: A (linear), S (polar, the
// eigenvalues of S after Lemma L15's reduction to its eigenbasis) or Σ (SVD, volume only).
//
// This header sits beside goodness.hpp (the 2D decider, over the same exact fields) rather than in theory/local3/,
// the 3D engine's floating-point homotopies: it shares no code with them and decides with exact arithmetic only.
// It is the atlas's second line of evidence, independent of the QE proofs (experiments/claims/atlas3/): it
// evaluates the definitions' reduced forms at a point, and never a cell's closed-form condition.
#include "theory/local/goodness.hpp"
#include "theory/local/matrix2.hpp"

#include <array>
#include <optional>

namespace affinterp::local {

template <class F>
Mat3<F> identity3() {
  Mat3<F> I;
  I << F(1), F(0), F(0), F(0), F(1), F(0), F(0), F(0), F(1);
  return I;
}

template <class F>
Mat3<F> diagonal3(const F& l1, const F& l2, const F& l3) {
  Mat3<F> D = identity3<F>();
  D(0, 0) = l1;
  D(1, 1) = l2;
  D(2, 2) = l3;
  return D;
}

/// det W by cofactor expansion along the first row.
template <class F>
F det3(const Mat3<F>& W) {
  return W(0, 0) * (W(1, 1) * W(2, 2) - W(1, 2) * W(2, 1)) - W(0, 1) * (W(1, 0) * W(2, 2) - W(1, 2) * W(2, 0)) +
         W(0, 2) * (W(1, 0) * W(2, 1) - W(1, 1) * W(2, 0));
}

/// (1−t)I + tB.
template <class F>
Mat3<F> blend3(const Mat3<F>& B, const F& t) {
  Mat3<F> W;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) W(i, j) = t * B(i, j) + (i == j ? F(1) - t : F(0));
  return W;
}

/// c0 + c1 t + c2 t² + c3 t³.
template <class F>
struct Cubic {
  F c0, c1, c2, c3;
  F operator()(const F& t) const { return c0 + t * (c1 + t * (c2 + t * c3)); }
  Quadratic<F> derivative() const { return {c1, F(2) * c2, F(3) * c3}; }
};

/// The cubic through (k/3, p_k), k = 0..3: Newton's forward differences in s = 3t.
template <class F>
Cubic<F> cubic_through(const std::array<F, 4>& p) {
  const F d1 = p[1] - p[0], d2 = p[2] - F(2) * p[1] + p[0], d3 = p[3] - F(3) * p[2] + F(3) * p[1] - p[0];
  // p = p0 + d1 s + d2 s(s−1)/2 + d3 s(s−1)(s−2)/6, expanded in s, then s = 3t
  return {p[0], F(3) * (d1 - d2 / F(2) + d3 / F(3)), F(9) * (d2 - d3) / F(2), F(27) * d3 / F(6)};
}

/// det((1−t)I + tB) as a polynomial in t, from four exact evaluations (not from the invariants of B − I).
template <class F>
Cubic<F> blend_determinant3(const Mat3<F>& B) {
  std::array<F, 4> p;
  for (int k = 0; k < 4; ++k) p[k] = det3<F>(blend3<F>(B, F(k) / F(3)));
  return cubic_through(p);
}

/// The smallest and largest value of a quadratic on [0, 1]: at an end or at an interior vertex.
template <class F>
std::pair<F, F> range_on_unit_interval(const Quadratic<F>& q) {
  F lo = q(F(0)), hi = q(F(0));
  const auto see = [&](const F& v) {
    if (v < lo) lo = v;
    if (v > hi) hi = v;
  };
  see(q(F(1)));
  if (const std::optional<F> t = interior_critical_point(q)) see(q(*t));
  return {lo, hi};
}

/// Volume (3D Def 2.2.1) for det A(t) = det((1−t)I + tB): monotone iff p′ does not take both signs on [0, 1];
/// a monotone p is positive on [0, 1] iff it is positive at both ends.
template <class F>
bool good_for_volume(const Mat3<F>& B) {
  const Cubic<F> p = blend_determinant3(B);
  const auto [lo, hi] = range_on_unit_interval(p.derivative());
  const bool monotone = lo >= F(0) || hi <= F(0);
  return monotone && p(F(0)) > F(0) && p(F(1)) > F(0);
}

/// The forms P = sym(M) and Q = sym(M) + MᵀM, M = B − I: ½ d/dt ‖(I + tM)v‖² = P(v) + t(Q(v) − P(v)), affine in
/// t with slope ‖Mv‖² ≥ 0, so ‖((1−t)I + tB)v‖ is not monotone on [0, 1] iff P(v) < 0 < Q(v) (Lemma L3, any dimension).
template <class F>
struct NormForms3 {
  Mat3<F> P, Q;
  explicit NormForms3(const Mat3<F>& B) {
    const Mat3<F> M = B - identity3<F>();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        P(i, j) = (M(i, j) + M(j, i)) / F(2);
        F gram(0);
        for (int k = 0; k < 3; ++k) gram += M(k, i) * M(k, j);
        Q(i, j) = P(i, j) + gram;
      }
  }
};

template <class F>
F quadratic_form(const Mat3<F>& W, const std::array<F, 3>& v) {
  F sum(0);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) sum += v[i] * W(i, j) * v[j];
  return sum;
}

/// W ⪰ 0 for symmetric W: every principal minor (three 1×1, three 2×2, the determinant) is ≥ 0.
template <class F>
bool positive_semidefinite3(const Mat3<F>& W) {
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    if (W(i, i) < F(0) || W(i, i) * W(j, j) - W(i, j) * W(j, i) < F(0)) return false;
  }
  return det3(W) >= F(0);
}

/// Whether ‖((1−t)I + tB)v‖ fails to be monotone on [0, 1] for this v: P(v) < 0 < Q(v).
template <class F>
bool norm_dips3(const Mat3<F>& B, const std::array<F, 3>& v) {
  const NormForms3<F> forms(B);
  return quadratic_form(forms.P, v) < F(0) && quadratic_form(forms.Q, v) > F(0);
}

/// A direction where ‖((1−t)I + tB)v‖ dips, searched over the integer vectors of [−n, n]³, or none.
template <class F>
std::optional<std::array<F, 3>> dipping_direction(const Mat3<F>& B, int n) {
  const NormForms3<F> forms(B);
  for (int a = -n; a <= n; ++a)
    for (int b = -n; b <= n; ++b)
      for (int c = 0; c <= n; ++c) {  // v and −v dip together
        const std::array<F, 3> v{F(a), F(b), F(c)};
        if (quadratic_form(forms.P, v) < F(0) && quadratic_form(forms.Q, v) > F(0)) return v;
      }
  return std::nullopt;
}

/// Norm (3D Def 2.2.2) for ((1−t)I + tB)v with any B, as far as certificates reach: good when P ⪰ 0 (every
/// derivative starts ≥ 0 and grows) or Q ⪯ 0 (every derivative ends ≤ 0 and grew to it); not good when an integer
/// direction of [−8, 8]³ dips; nullopt when neither certificate is found.
template <class F>
std::optional<bool> good_for_norm_certified(const Mat3<F>& B) {
  const NormForms3<F> forms(B);
  if (positive_semidefinite3<F>(forms.P) || positive_semidefinite3<F>(-forms.Q)) return true;
  if (dipping_direction(B, 8)) return false;
  return std::nullopt;
}

/// A homotopy whose squared norm along the eigenvector e_i of S has half-derivative g_i(t), with g_i(0) and
/// g_i(1) of one sign (both 0, both > 0 or both < 0) and the derivative along Σ w_i e_i (w_i = v_i² ≥ 0) the
/// combination Σ w_i g_i (Lemma L15). `sign[i]` is the sign of g_i; `cross[i][j]` the sign of
/// g_i(0) g_j(1) − g_j(0) g_i(1).
struct AxisSlopes {
  std::array<int, 3> sign{};
  std::array<std::array<int, 3>, 3> cross{};
};

/// Whether some v ≠ 0 has Σ w_i g_i(0) < 0 < Σ w_i g_i(1): by Carathéodory in the plane a cone point of three
/// generators (g_i(0), g_i(1)) lies in the cone of two; the generators lie in the closed first and third
/// quadrants, so the cone of g_i, g_j meets the open second quadrant iff one is in the open first, the other in
/// the open third quadrant, and the turn from the first to the second is counter-clockwise (cross > 0).
inline bool some_direction_dips(const AxisSlopes& s) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (s.sign[i] > 0 && s.sign[j] < 0 && s.cross[i][j] > 0) return true;
  return false;
}

template <class F>
int sign_of(const F& x) {
  return x > F(0) ? 1 : (x < F(0) ? -1 : 0);
}

/// Polar norm at S = diag(l1, l2, l3) ≻ 0: g_i(t) = μ_i + tμ_i², μ_i = l_i − 1, read off the forms P, Q
/// (diagonal here) as g_i(0) = P_ii, g_i(1) = Q_ii.
template <class F>
bool good_for_norm_polar(const F& l1, const F& l2, const F& l3) {
  const NormForms3<F> forms(diagonal3(l1, l2, l3));
  AxisSlopes s;
  for (int i = 0; i < 3; ++i) {
    s.sign[i] = sign_of<F>(forms.P(i, i));
    for (int j = 0; j < 3; ++j)
      s.cross[i][j] = sign_of<F>(forms.P(i, i) * forms.Q(j, j) - forms.P(j, j) * forms.Q(i, i));
  }
  return !some_direction_dips(s);
}

/// Exp-log norm at S = diag(l1, l2, l3) ≻ 0: ½ d/dt ‖S^t e_i‖² = g_i(t) = log(l_i) l_i^{2t}, so g_i(0) and g_i(1)
/// have the sign of l_i − 1, and g_i(0) g_j(1) − g_j(0) g_i(1) = log l_i log l_j (l_j² − l_i²) has the sign of
/// (l_i − 1)(l_j − 1)(l_j² − l_i²): exact, with no logarithm evaluated. Each Σ w_i g_i is non-decreasing in t
/// (its derivative is Σ 2 w_i log² l_i l_i^{2t} ≥ 0), so a dip is a sign change from t = 0 to t = 1.
template <class F>
bool good_for_norm_exp_log(const F& l1, const F& l2, const F& l3) {
  const std::array<F, 3> l{l1, l2, l3};
  AxisSlopes s;
  for (int i = 0; i < 3; ++i) {
    s.sign[i] = sign_of<F>(l[i] - F(1));
    for (int j = 0; j < 3; ++j)
      s.cross[i][j] = sign_of<F>(l[i] - F(1)) * sign_of<F>(l[j] - F(1)) * sign_of<F>(l[j] * l[j] - l[i] * l[i]);
  }
  return !some_direction_dips(s);
}

}  // namespace affinterp::local
