#pragma once
// "Good" interpolations (thesis Defs 2.2.1, 2.2.2), decided exactly, independently of the thesis's
// theorems, for every homotopy of the form A(t) = U(t)((1−t)I + tB)V(t) with rotations U(t), V(t) that
// leave det and ‖·‖ alone: the linear homotopy (B = A, U = V = I), the polar one (B = S, V = I) and,
// for area only, the SVD one (B = D). F is an exact ordered field (exact::Rational, QuadraticSurd).
//
// Area (Def 2.2.1, det A(t) monotone and positive on [0, 1]): det((1−t)I + tB) is a polynomial of degree
// ≤ 2 in t; it is recovered from its exact values at t = 0, ½, 1 and decided on [0, 1] exactly.
//
// Norm (Def 2.2.2, ‖A(t)v‖ monotone on [0, 1] for every unit v): with M = B − I,
//   q_v(t) = ‖(I + tM)v‖² = 1 + 2t vᵀMv + t² ‖Mv‖²,   ½ q_v'(t) = vᵀMv + t ‖Mv‖²,
// and q_v' is non-decreasing in t, so ‖A(t)v‖ fails to be monotone iff q_v'(0) < 0 < q_v'(1), i.e.
// P(v) < 0 < Q(v) for the quadratic forms P = sym(M), Q = sym(M) + MᵀM. No v has P(v) < 0 < Q(v) iff
// Q ⪯ 0 or P − νQ ⪰ 0 for some ν ≥ 0: "if" is immediate; "only if" separates the joint range
// {(P(v), Q(v))}, a convex cone by Dines' theorem (1941), from the open quadrant {a < 0 < b}.
// Deciding ∃ν ≥ 0: P − νQ ⪰ 0 needs only rational candidates (interval ends and the vertex of det).
#include "theory/local/matrix2.hpp"

#include <optional>

namespace affinterp::local {

/// c0 + c1 t + c2 t².
template <class F>
struct Quadratic {
  F c0, c1, c2;
  F operator()(const F& t) const { return c0 + t * (c1 + t * c2); }
  F derivative(const F& t) const { return c1 + F(2) * c2 * t; }
};

/// The quadratic through (0, p0), (½, p_half), (1, p1).
template <class F>
Quadratic<F> quadratic_through(const F& p0, const F& p_half, const F& p1) {
  return {p0, F(4) * p_half - F(3) * p0 - p1, F(2) * (p0 + p1) - F(4) * p_half};
}

/// det((1−t)I + tB) as a polynomial in t, from three exact evaluations.
template <class F>
Quadratic<F> blend_determinant(const Mat2<F>& B) {
  const auto det_at = [&](const F& t) { return det2<F>(scaled(F(1) - t, identity2<F>()) + scaled(t, B)); };
  return quadratic_through(det_at(F(0)), det_at(F(1) / F(2)), det_at(F(1)));
}

/// Weakly monotone on [0, 1]: the linear p' does not take both signs there.
template <class F>
bool monotone_on_unit_interval(const Quadratic<F>& p) {
  const F slope0 = p.derivative(F(0)), slope1 = p.derivative(F(1));
  return !((slope0 < F(0) && slope1 > F(0)) || (slope0 > F(0) && slope1 < F(0)));
}

/// The interior critical point of p in (0, 1), when there is one.
template <class F>
std::optional<F> interior_critical_point(const Quadratic<F>& p) {
  if (p.c2 == F(0)) return std::nullopt;
  const F t = -p.c1 / (F(2) * p.c2);
  if (t > F(0) && t < F(1)) return t;
  return std::nullopt;
}

template <class F>
bool positive_on_unit_interval(const Quadratic<F>& p) {
  if (!(p(F(0)) > F(0) && p(F(1)) > F(0))) return false;
  const std::optional<F> t = interior_critical_point(p);
  return !(t && p.c2 > F(0) && !(p(*t) > F(0)));
}

/// Def 2.2.1 for det A(t) = det((1−t)I + tB).
template <class F>
bool good_for_area(const Mat2<F>& B) {
  const Quadratic<F> det = blend_determinant(B);
  return positive_on_unit_interval(det) && monotone_on_unit_interval(det);
}

/// The forms P = sym(M) and Q = sym(M) + MᵀM of the norm criterion, M = B − I.
template <class F>
struct NormForms {
  Mat2<F> P, Q;
  explicit NormForms(const Mat2<F>& B) {
    const Mat2<F> M = B - identity2<F>();
    P = scaled(F(1) / F(2), M + M.transpose());
    Q = P + M.transpose().lazyProduct(M);
  }
};

template <class F>
bool positive_semidefinite(const Mat2<F>& W) {
  return W(0, 0) >= F(0) && W(1, 1) >= F(0) && det2(W) >= F(0);
}

/// Def 2.2.2 for ‖A(t)v‖ = ‖((1−t)I + tB)v‖.
template <class F>
bool good_for_norm(const Mat2<F>& B) {
  const NormForms<F> forms(B);
  const Mat2<F>&P = forms.P, &Q = forms.Q;
  if (positive_semidefinite<F>(-Q)) return true;
  // ν ≥ 0 with W(ν) = P − νQ ⪰ 0: the diagonal of W keeps ν in [lo, hi] ...
  F lo = F(0);
  std::optional<F> hi;  // none: unbounded
  for (int i = 0; i < 2; ++i) {
    if (Q(i, i) > F(0)) {
      const F bound = P(i, i) / Q(i, i);
      if (!hi || bound < *hi) hi = bound;
    } else if (Q(i, i) < F(0)) {
      const F bound = P(i, i) / Q(i, i);
      if (bound > lo) lo = bound;
    } else if (P(i, i) < F(0)) {
      return false;
    }
  }
  if (hi && *hi < lo) return false;
  // ... and det W(ν) = aν² + bν + c must be ≥ 0 somewhere on it; its maximum there is at lo, at hi, at
  // the vertex (a < 0) or at infinity (a > 0, or a = 0 < b).
  const F a = det2(Q), c = det2(P);
  const F b = F(2) * P(0, 1) * Q(0, 1) - P(0, 0) * Q(1, 1) - P(1, 1) * Q(0, 0);
  const Quadratic<F> det_W{c, b, a};
  if (det_W(lo) >= F(0)) return true;
  if (hi && det_W(*hi) >= F(0)) return true;
  if (!hi && (a > F(0) || (a == F(0) && b > F(0)))) return true;
  if (a < F(0)) {
    const F vertex = -b / (F(2) * a);
    if (vertex > lo && (!hi || vertex < *hi) && det_W(vertex) >= F(0)) return true;
  }
  return false;
}

/// For a unit-free direction v: whether ‖((1−t)I + tB)v‖ fails to be monotone on [0, 1], i.e.
/// P(v) < 0 < Q(v); then it dips to its minimum at t* = −vᵀMv / ‖Mv‖² ∈ (0, 1).
template <class F>
bool norm_dips(const Mat2<F>& B, const Vec2<F>& v) {
  const NormForms<F> forms(B);
  return v.dot(forms.P.lazyProduct(v)) < F(0) && v.dot(forms.Q.lazyProduct(v)) > F(0);
}

template <class F>
F norm_dip_time(const Mat2<F>& B, const Vec2<F>& v) {
  const Vec2<F> Mv = (B - identity2<F>()).lazyProduct(v);
  return -v.dot(Mv) / Mv.squaredNorm();
}

}  // namespace affinterp::local
