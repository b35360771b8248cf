#include "theory/certified/sym3.hpp"

#include "theory/certified/arb_balls.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>

namespace affinterp::certified {
namespace {

using detail::Num;
using Matrix = std::array<std::array<Num, 3>, 3>;

/// Drops the radius: the approximate computations below work on midpoints only.
void keep_mid(Num& x) { mag_zero(arb_radref(x.get())); }

/// An approximate eigenbasis of S at `bits` bits: cyclic Jacobi on midpoints (rounding errors are
/// irrelevant here; the certificate comes afterwards). Rotates while |a_pq| exceeds both
/// 2^−(bits+8) √|a_pp a_qq| (relative accuracy for graded matrices) and 2^−(2·bits+8) ‖S‖_F.
Matrix approximate_eigenbasis(const Mat3& S, slong bits) {
  Matrix a, V;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      arb_set_d(a[i][j].get(), S(std::min(i, j), std::max(i, j)));
      arb_set_si(V[i][j].get(), i == j ? 1 : 0);
    }
  // Compared in squares: a_pq² against 2^−2(bits+8) |a_pp a_qq| and 2^−4·bits−16 ‖S‖²_F.
  Num norm2, t, u, theta, c, s, g, h, threshold2, floor2, apq2;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) arb_addmul(norm2.get(), a[i][j].get(), a[i][j].get(), bits);
  arb_mul_2exp_si(floor2.get(), norm2.get(), -4 * bits - 16);
  keep_mid(floor2);
  constexpr std::array<std::array<int, 2>, 3> pairs{{{0, 1}, {0, 2}, {1, 2}}};
  for (int sweep = 0; sweep < 200; ++sweep) {
    bool rotated = false;
    for (const auto [p, q] : pairs) {
      Num& apq = a[p][q];
      arb_mul(threshold2.get(), a[p][p].get(), a[q][q].get(), bits);
      arb_mul_2exp_si(threshold2.get(), threshold2.get(), -2 * bits - 16);
      arb_sqr(apq2.get(), apq.get(), bits);
      keep_mid(threshold2), keep_mid(apq2);
      if (arf_cmpabs(apq2.mid(), threshold2.mid()) <= 0 || arf_cmpabs(apq2.mid(), floor2.mid()) <= 0) continue;
      rotated = true;
      // θ = (a_qq − a_pp)/(2 a_pq), t = sign θ / (|θ| + √(θ² + 1)), c = 1/√(t² + 1), s = t c.
      arb_sub(theta.get(), a[q][q].get(), a[p][p].get(), bits);
      arb_div(theta.get(), theta.get(), apq.get(), bits);
      arb_mul_2exp_si(theta.get(), theta.get(), -1);
      keep_mid(theta);
      arb_sqr(u.get(), theta.get(), bits);
      arb_add_ui(u.get(), u.get(), 1, bits);
      arb_sqrt(u.get(), u.get(), bits);
      arb_abs(t.get(), theta.get());
      arb_add(t.get(), t.get(), u.get(), bits);
      arb_inv(t.get(), t.get(), bits);
      if (arf_sgn(theta.mid()) < 0) arb_neg(t.get(), t.get());
      keep_mid(t);
      arb_sqr(u.get(), t.get(), bits);
      arb_add_ui(u.get(), u.get(), 1, bits);
      arb_rsqrt(c.get(), u.get(), bits);
      arb_mul(s.get(), t.get(), c.get(), bits);
      keep_mid(c), keep_mid(s);
      // a_pp −= t a_pq, a_qq += t a_pq, a_pq = 0; the third row/column and V rotate by (c, s).
      arb_mul(u.get(), t.get(), apq.get(), bits);
      arb_sub(a[p][p].get(), a[p][p].get(), u.get(), bits);
      arb_add(a[q][q].get(), a[q][q].get(), u.get(), bits);
      keep_mid(a[p][p]), keep_mid(a[q][q]);
      arb_zero(a[p][q].get());
      arb_zero(a[q][p].get());
      const int r = 3 - p - q;
      g = a[r][p], h = a[r][q];
      arb_mul(a[r][p].get(), c.get(), g.get(), bits);
      arb_submul(a[r][p].get(), s.get(), h.get(), bits);
      arb_mul(a[r][q].get(), s.get(), g.get(), bits);
      arb_addmul(a[r][q].get(), c.get(), h.get(), bits);
      keep_mid(a[r][p]), keep_mid(a[r][q]);
      a[p][r] = a[r][p], a[q][r] = a[r][q];
      for (int i = 0; i < 3; ++i) {
        g = V[i][p], h = V[i][q];
        arb_mul(V[i][p].get(), c.get(), g.get(), bits);
        arb_submul(V[i][p].get(), s.get(), h.get(), bits);
        arb_mul(V[i][q].get(), s.get(), g.get(), bits);
        arb_addmul(V[i][q].get(), c.get(), h.get(), bits);
        keep_mid(V[i][p]), keep_mid(V[i][q]);
      }
    }
    if (!rotated) break;
  }
  return V;
}

/// An unnormalised quaternion q of the rotation V (det V = +1; Shepperd's choice of the largest of
/// 1 + tr V, 1 + 2V_kk − tr V), as exact dyadic numbers.
std::array<Num, 4> quaternion(const Matrix& V, slong bits) {
  const auto v = [&](int i, int j) { return V[i][j].get(); };
  Num trace, d[4];
  arb_add(trace.get(), v(0, 0), v(1, 1), bits);
  arb_add(trace.get(), trace.get(), v(2, 2), bits);
  // Candidates: 1 + tr, and 1 + 2 V_kk − tr for k = 0, 1, 2.
  arb_add_ui(d[0].get(), trace.get(), 1, bits);
  for (int k = 0; k < 3; ++k) {
    arb_mul_2exp_si(d[k + 1].get(), v(k, k), 1);
    arb_sub(d[k + 1].get(), d[k + 1].get(), trace.get(), bits);
    arb_add_ui(d[k + 1].get(), d[k + 1].get(), 1, bits);
  }
  int best = 0;
  for (int k = 1; k < 4; ++k)
    if (arf_cmp(d[k].mid(), d[best].mid()) > 0) best = k;
  std::array<Num, 4> q;  // (w, x, y, z)
  const auto diff = [&](Num& out, int i, int j, int k, int l) { arb_sub(out.get(), v(i, j), v(k, l), bits); };
  const auto sum = [&](Num& out, int i, int j, int k, int l) { arb_add(out.get(), v(i, j), v(k, l), bits); };
  switch (best) {
    case 0:  // ∝ w
      q[0] = d[0], diff(q[1], 2, 1, 1, 2), diff(q[2], 0, 2, 2, 0), diff(q[3], 1, 0, 0, 1);
      break;
    case 1:  // ∝ x
      diff(q[0], 2, 1, 1, 2), q[1] = d[1], sum(q[2], 0, 1, 1, 0), sum(q[3], 0, 2, 2, 0);
      break;
    case 2:  // ∝ y
      diff(q[0], 0, 2, 2, 0), sum(q[1], 0, 1, 1, 0), q[2] = d[2], sum(q[3], 1, 2, 2, 1);
      break;
    default:  // ∝ z
      diff(q[0], 1, 0, 0, 1), sum(q[1], 0, 2, 2, 0), sum(q[2], 1, 2, 2, 1), q[3] = d[3];
      break;
  }
  for (Num& x : q) keep_mid(x);  // exact dyadic numbers from here on
  return q;
}

/// The enclosure of S in an exactly orthogonal basis: R = Rq / N with Rq = R(q) |q|², N = |q|², and
/// T = Rᵀ S R as balls; D = diag(d) with d exact, η ≥ ‖T − D‖_F.
struct Enclosure {
  Num Rq[3][3];
  Num N;
  std::array<Num, 3> d;  ///< exact (radius 0)
  Num eta;               ///< exact upper bound of ‖T − D‖_F
  slong bits = 0;
};

Enclosure enclose(const Mat3& S, slong bits) {
  const std::array<Num, 4> q = quaternion(approximate_eigenbasis(S, bits), bits);
  const slong exact = 4 * bits + 64;  // q has bits-bit mantissas of comparable size: products are exact
  Enclosure e;
  e.bits = bits;
  const auto sq = [&](int i) {
    Num out;
    arb_sqr(out.get(), q[i].get(), exact);
    return out;
  };
  const auto twice_product = [&](int i, int j, int k, int l, int sign) {
    Num a, b;
    arb_mul(a.get(), q[i].get(), q[j].get(), exact);
    arb_mul(b.get(), q[k].get(), q[l].get(), exact);
    if (sign > 0)
      arb_add(a.get(), a.get(), b.get(), exact);
    else
      arb_sub(a.get(), a.get(), b.get(), exact);
    arb_mul_2exp_si(a.get(), a.get(), 1);
    return a;
  };
  const Num w2 = sq(0), x2 = sq(1), y2 = sq(2), z2 = sq(3);
  const auto combine = [&](int sw, int sx, int sy, int sz) {
    Num out;
    arb_zero(out.get());
    const Num* parts[4] = {&w2, &x2, &y2, &z2};
    const int signs[4] = {sw, sx, sy, sz};
    for (int k = 0; k < 4; ++k) {
      if (signs[k] > 0)
        arb_add(out.get(), out.get(), parts[k]->get(), exact);
      else
        arb_sub(out.get(), out.get(), parts[k]->get(), exact);
    }
    return out;
  };
  // R(q)|q|² (q = (w, x, y, z)): the rotation matrix of the quaternion, without the division.
  e.Rq[0][0] = combine(1, 1, -1, -1);
  e.Rq[1][1] = combine(1, -1, 1, -1);
  e.Rq[2][2] = combine(1, -1, -1, 1);
  e.Rq[0][1] = twice_product(1, 2, 0, 3, -1);  // 2(xy − wz)
  e.Rq[1][0] = twice_product(1, 2, 0, 3, +1);  // 2(xy + wz)
  e.Rq[0][2] = twice_product(1, 3, 0, 2, +1);  // 2(xz + wy)
  e.Rq[2][0] = twice_product(1, 3, 0, 2, -1);  // 2(xz − wy)
  e.Rq[1][2] = twice_product(2, 3, 0, 1, -1);  // 2(yz − wx)
  e.Rq[2][1] = twice_product(2, 3, 0, 1, +1);  // 2(yz + wx)
  e.N = combine(1, 1, 1, 1);

  // T = Rqᵀ S Rq / N², in ball arithmetic at bits + 64 bits (S exactly).
  const slong wp = bits + 64;
  Num Sb[3][3], SR[3][3], T[3][3], t;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) arb_set_d(Sb[i][j].get(), S(std::min(i, j), std::max(i, j)));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      arb_zero(SR[i][j].get());
      for (int k = 0; k < 3; ++k) arb_addmul(SR[i][j].get(), Sb[i][k].get(), e.Rq[k][j].get(), wp);
    }
  Num N2;
  arb_sqr(N2.get(), e.N.get(), exact);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      arb_zero(T[i][j].get());
      for (int k = 0; k < 3; ++k) arb_addmul(T[i][j].get(), e.Rq[k][i].get(), SR[k][j].get(), wp);
      arb_div(T[i][j].get(), T[i][j].get(), N2.get(), wp);
    }
  // η² = Σ_{i≠j} |T_ij|² + Σ_i |T_ii − d_i|², with d_i = mid T_ii; the true T is symmetric and lies in
  // both T_ij and T_ji, so the smaller of their magnitude bounds serves.
  Num sum, bound;
  arf_t u, v;
  arf_init(u);
  arf_init(v);
  for (int i = 0; i < 3; ++i) {
    arb_set_arf(e.d[i].get(), arb_midref(T[i][i].get()));
    arf_set_mag(u, arb_radref(T[i][i].get()));
    arb_set_arf(bound.get(), u);
    arb_addmul(sum.get(), bound.get(), bound.get(), wp);
    for (int j = i + 1; j < 3; ++j) {
      arb_get_abs_ubound_arf(u, T[i][j].get(), wp);
      arb_get_abs_ubound_arf(v, T[j][i].get(), wp);
      arb_set_arf(bound.get(), arf_cmp(u, v) < 0 ? u : v);
      arb_addmul(sum.get(), bound.get(), bound.get(), wp);
      arb_addmul(sum.get(), bound.get(), bound.get(), wp);
    }
  }
  arb_sqrtpos(t.get(), sum.get(), wp);
  arb_get_ubound_arf(u, t.get(), wp);
  arb_set_arf(e.eta.get(), u);
  arf_clear(u);
  arf_clear(v);
  return e;
}

/// R diag(f) Rᵀ + (ball of Frobenius radius lipschitz·η on every entry).
std::shared_ptr<Balls::Impl> assemble(const Enclosure& e, const std::array<Num, 3>& f, const Num& lipschitz, slong wp) {
  auto out = std::make_shared<Balls::Impl>(3, 3);
  Num N2, error, t;
  arb_sqr(N2.get(), e.N.get(), wp);
  arb_mul(error.get(), lipschitz.get(), e.eta.get(), wp);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      arb_ptr x = arb_mat_entry(out->m, i, j);
      arb_zero(x);
      for (int k = 0; k < 3; ++k) {
        arb_mul(t.get(), e.Rq[i][k].get(), e.Rq[j][k].get(), wp);
        arb_addmul(x, t.get(), f[k].get(), wp);
      }
      arb_div(x, x, N2.get(), wp);
      arb_add_error(x, error.get());
    }
  return out;
}

/// x ← x · factor (factor ≥ 0 a double), rounded down.
void scale_down(arf_t x, double factor) {
  arf_t f;
  arf_init(f);
  arf_set_d(f, factor);
  arf_mul(x, x, f, 64, ARF_RND_DOWN);
  arf_clear(f);
}

/// lower bound of ‖F‖_F ≥ 0 as an arf (0 when unknown).
void frobenius_lower(arf_t out, const Balls::Impl& F, slong wp) {
  Num sum, t;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      arb_sqr(t.get(), arb_mat_entry(F.m, i, j), wp);
      arb_add(sum.get(), sum.get(), t.get(), wp);
    }
  arb_sqrtpos(t.get(), sum.get(), wp);
  arb_get_lbound_arf(out, t.get(), wp);
  if (arf_sgn(out) < 0 || arf_is_nan(out)) arf_zero(out);
}

/// Whether every entry's radius is at most `relative` · ‖F‖_F (or zero).
bool within_target(const Balls::Impl& F, double relative, slong wp) {
  arf_t norm, r;
  arf_init(norm);
  arf_init(r);
  frobenius_lower(norm, F, wp);
  scale_down(norm, relative);
  bool ok = true;
  for (int i = 0; i < 3 && ok; ++i)
    for (int j = 0; j < 3 && ok; ++j) {
      arb_srcptr x = arb_mat_entry(F.m, i, j);
      if (!arb_is_finite(x)) {
        ok = false;
        break;
      }
      arf_set_mag(r, arb_radref(x));
      ok = arf_is_zero(r) || arf_cmp(r, norm) <= 0;
    }
  arf_clear(norm);
  arf_clear(r);
  return ok;
}

/// The smallest magnitude that rounds to ±∞ in double (round to nearest): 2¹⁰²⁴ − 2⁹⁷⁰.
void overflow_threshold(arf_t out) {
  arf_set_ui_2exp_si(out, 1, 1024);
  arf_t half_ulp;
  arf_init(half_ulp);
  arf_set_ui_2exp_si(half_ulp, 1, 970);
  arf_sub(out, out, half_ulp, ARF_PREC_EXACT, ARF_RND_DOWN);
  arf_clear(half_ulp);
}

enum class Overflow { no, yes, undecided };

Overflow overflow_of(const Balls::Impl& F) {
  arf_t omega, b;
  arf_init(omega);
  arf_init(b);
  overflow_threshold(omega);
  bool all_below = true, some_above = false;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      arb_srcptr x = arb_mat_entry(F.m, i, j);
      arb_get_abs_ubound_arf(b, x, 64);
      if (!(arf_is_finite(b) && arf_cmp(b, omega) < 0)) all_below = false;
      arb_get_abs_lbound_arf(b, x, 64);
      if (arf_is_finite(b) && arf_cmp(b, omega) >= 0) some_above = true;
    }
  arf_clear(omega);
  arf_clear(b);
  return some_above ? Overflow::yes : all_below ? Overflow::no : Overflow::undecided;
}

/// min d − η, max d + η as balls (exact inputs, rounded outward).
void spectrum_bounds(const Enclosure& e, Num& lo, Num& hi, slong wp) {
  lo = e.d[0], hi = e.d[0];
  for (int k = 1; k < 3; ++k) {
    if (arf_cmp(e.d[k].mid(), lo.mid()) < 0) lo = e.d[k];
    if (arf_cmp(e.d[k].mid(), hi.mid()) > 0) hi = e.d[k];
  }
  arb_sub(lo.get(), lo.get(), e.eta.get(), wp);
  arb_add(hi.get(), hi.get(), e.eta.get(), wp);
}

/// Positive definiteness decided exactly: Sylvester's criterion, the minors in exact dyadic arithmetic.
bool positive_definite(const Mat3& S) {
  arf_t a, b, c, d, e, f, t, u, minor;
  arf_init(a), arf_init(b), arf_init(c), arf_init(d), arf_init(e), arf_init(f);
  arf_init(t), arf_init(u), arf_init(minor);
  arf_set_d(a, S(0, 0)), arf_set_d(b, S(0, 1)), arf_set_d(c, S(0, 2));
  arf_set_d(d, S(1, 1)), arf_set_d(e, S(1, 2)), arf_set_d(f, S(2, 2));
  const auto mul = [](arf_t z, const arf_t x, const arf_t y) { arf_mul(z, x, y, ARF_PREC_EXACT, ARF_RND_DOWN); };
  const auto sub = [](arf_t z, const arf_t x, const arf_t y) { arf_sub(z, x, y, ARF_PREC_EXACT, ARF_RND_DOWN); };
  const auto add = [](arf_t z, const arf_t x, const arf_t y) { arf_add(z, x, y, ARF_PREC_EXACT, ARF_RND_DOWN); };
  bool positive = arf_sgn(a) > 0;
  mul(t, a, d), mul(u, b, b), sub(minor, t, u);  // a d − b²
  positive = positive && arf_sgn(minor) > 0;
  // det = a (d f − e²) − b (b f − e c) + c (b e − d c)
  arf_t det;
  arf_init(det);
  mul(t, d, f), mul(u, e, e), sub(t, t, u), mul(det, a, t);
  mul(t, b, f), mul(u, e, c), sub(t, t, u), mul(t, b, t), sub(det, det, t);
  mul(t, b, e), mul(u, d, c), sub(t, t, u), mul(t, c, t), add(det, det, t);
  positive = positive && arf_sgn(det) > 0;
  arf_clear(det);
  arf_clear(a), arf_clear(b), arf_clear(c), arf_clear(d), arf_clear(e), arf_clear(f);
  arf_clear(t), arf_clear(u), arf_clear(minor);
  return positive;
}

/// The precisions to try: start_bits, doubling, up to max_bits.
template <class Step>
auto with_doubling(const Options& options, Step step) {
  slong bits = std::max<slong>(64, options.start_bits);
  for (;;) {
    auto result = step(bits);
    if (result.status != Status::too_wide || 2 * bits > options.max_bits) return result;
    bits *= 2;
  }
}

}  // namespace

CertifiedMatrix exp(const Mat3& S, const Options& options) {
  return with_doubling(options, [&](slong bits) {
    const slong wp = bits + 64;
    const Enclosure e = enclose(S, bits);
    Num lo, hi;
    spectrum_bounds(e, lo, hi, wp);
    CertifiedMatrix out;
    out.bits = bits;
    // Beyond λ > 1000 an entry of exp S exceeds e^1000/3 (the diagonal entry of the eigenvector's
    // largest component): certainly infinite in double, and too large for arb_exp at this precision.
    Num top;  // max d − η ≤ λ_max
    arb_sub(top.get(), hi.get(), e.eta.get(), wp);
    arb_sub(top.get(), top.get(), e.eta.get(), wp);
    Num limit(1000.0);
    const bool huge = arb_gt(top.get(), limit.get());
    if (huge) {
      auto inf = std::make_shared<Balls::Impl>(3, 3);
      arb_mat_indeterminate(inf->m);
      out.status = Status::overflows;
      out.value = Balls(inf);
      return out;
    }
    std::array<Num, 3> f;
    for (int k = 0; k < 3; ++k) arb_exp(f[k].get(), e.d[k].get(), wp);
    Num lipschitz;
    arb_exp(lipschitz.get(), hi.get(), wp);
    auto F = assemble(e, f, lipschitz, wp);
    const Overflow overflow = overflow_of(*F);
    out.status = overflow == Overflow::yes                                                    ? Status::overflows
                 : overflow == Overflow::no && within_target(*F, options.relative_radius, wp) ? Status::certified
                                                                                              : Status::too_wide;
    out.value = Balls(F);
    return out;
  });
}

CertifiedMatrix exp_taylor(const Mat3& S, long bits) {
  auto F = std::make_shared<Balls::Impl>(3, 3);
  arb_mat_t A;
  arb_mat_init(A, 3, 3);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) arb_set_d(arb_mat_entry(A, i, j), S(std::min(i, j), std::max(i, j)));
  arb_mat_exp(F->m, A, bits);
  arb_mat_clear(A);
  CertifiedMatrix out;
  out.bits = bits;
  const Overflow overflow = overflow_of(*F);
  out.status = overflow == Overflow::yes                             ? Status::overflows
               : overflow == Overflow::no && arb_mat_is_finite(F->m) ? Status::certified
                                                                     : Status::too_wide;
  out.value = Balls(F);
  return out;
}

CertifiedEigenvalues eigenvalues(const Mat3& S, const Options& options) {
  return with_doubling(options, [&](slong bits) {
    const Enclosure e = enclose(S, bits);
    std::array<int, 3> order{0, 1, 2};
    std::sort(order.begin(), order.end(), [&](int i, int j) { return arf_cmp(e.d[i].mid(), e.d[j].mid()) < 0; });
    auto values = std::make_shared<Balls::Impl>(3, 1);
    arf_t largest;
    arf_init(largest);
    for (int k = 0; k < 3; ++k) {
      arb_ptr x = arb_mat_entry(values->m, k, 0);
      arb_set(x, e.d[order[k]].get());
      arb_add_error(x, e.eta.get());
      if (arf_cmpabs(e.d[order[k]].mid(), largest) > 0) arf_abs(largest, e.d[order[k]].mid());
    }
    // Target: η ≤ relative · max |d|.
    scale_down(largest, options.relative_radius);
    const bool ok = arf_cmp(arb_midref(e.eta.get()), largest) <= 0;
    arf_clear(largest);
    CertifiedEigenvalues out;
    out.status = ok ? Status::certified : Status::too_wide;
    out.value = Balls(values);
    out.bits = bits;
    return out;
  });
}

namespace {

/// S^t or log S: f(d_k) and the Lipschitz constant on [lo, hi] (lo > 0) from `values`.
template <class Values>
CertifiedMatrix spd_function(const Mat3& S, const Options& options, Values values) {
  if (!positive_definite(S)) return {Status::not_spd, Balls(), 0};
  return with_doubling(options, [&](slong bits) {
    const slong wp = bits + 64;
    const Enclosure e = enclose(S, bits);
    Num lo, hi;
    spectrum_bounds(e, lo, hi, wp);
    CertifiedMatrix out;
    out.bits = bits;
    if (!arb_is_positive(lo.get())) {  // the smallest eigenvalue is not yet resolved: more bits
      auto wide = std::make_shared<Balls::Impl>(3, 3);
      arb_mat_indeterminate(wide->m);
      out.value = Balls(wide);
      out.status = Status::too_wide;
      return out;
    }
    std::array<Num, 3> f;
    Num lipschitz;
    values(e, lo, hi, f, lipschitz, wp);
    auto F = assemble(e, f, lipschitz, wp);
    out.status = within_target(*F, options.relative_radius, wp) ? Status::certified : Status::too_wide;
    out.value = Balls(F);
    return out;
  });
}

}  // namespace

CertifiedMatrix pow_spd(const Mat3& S, double t, const Options& options) {
  return spd_function(
      S, options,
      [t](const Enclosure& e, const Num& lo, const Num& hi, std::array<Num, 3>& f, Num& lipschitz, slong wp) {
        Num tb(t), tm1, a, b;
        for (int k = 0; k < 3; ++k) arb_pow(f[k].get(), e.d[k].get(), tb.get(), wp);
        // |f′| = |t| ξ^{t−1}, monotone in ξ: its largest value on [lo, hi] is at one end.
        arb_sub_ui(tm1.get(), tb.get(), 1, wp);
        arb_pow(a.get(), lo.get(), tm1.get(), wp);
        arb_pow(b.get(), hi.get(), tm1.get(), wp);
        arb_union(a.get(), a.get(), b.get(), wp);
        arb_abs(tb.get(), tb.get());
        arb_mul(lipschitz.get(), a.get(), tb.get(), wp);
      });
}

CertifiedMatrix log_spd(const Mat3& S, const Options& options) {
  return spd_function(
      S, options, [](const Enclosure& e, const Num& lo, const Num&, std::array<Num, 3>& f, Num& lipschitz, slong wp) {
        for (int k = 0; k < 3; ++k) arb_log(f[k].get(), e.d[k].get(), wp);
        arb_inv(lipschitz.get(), lo.get(), wp);  // |f′| = 1/ξ ≤ 1/lo
      });
}

namespace {

/// Σ (X_ij − F_ij)² as a ball; false when X has a non-finite entry.
bool squared_distance(arb_t out, const Mat3& X, const Balls& F) {
  if (!X.allFinite()) return false;
  arb_zero(out);
  Num d;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      arb_set_d(d.get(), X(i, j));
      arb_sub(d.get(), d.get(), arb_mat_entry(F.impl().m, i, j), 256);
      arb_addmul(out, d.get(), d.get(), 256);
    }
  return true;
}

}  // namespace

Ball relative_error(const Mat3& X, const Balls& F) {
  Num num, den, t;
  if (!squared_distance(num.get(), X, F)) return {std::numeric_limits<double>::infinity(), 0};
  arb_sqrtpos(num.get(), num.get(), 256);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      arb_addmul(den.get(), arb_mat_entry(F.impl().m, i, j), arb_mat_entry(F.impl().m, i, j), 256);
  arb_sqrtpos(den.get(), den.get(), 256);
  arb_div(t.get(), num.get(), den.get(), 256);
  return detail::to_ball(t.get());
}

Ball absolute_error(const Mat3& X, const Balls& F) {
  Num num;
  if (!squared_distance(num.get(), X, F)) return {std::numeric_limits<double>::infinity(), 0};
  arb_sqrtpos(num.get(), num.get(), 256);
  return detail::to_ball(num.get());
}

Ball eigenvalue_error(const Vec3& x, const Balls& lambda) {
  if (!x.allFinite()) return {std::numeric_limits<double>::infinity(), 0};
  Num worst, scale, d;
  arb_one(scale.get());
  for (int i = 0; i < 3; ++i) {
    arb_srcptr l = arb_mat_entry(lambda.impl().m, i, 0);
    arb_set_d(d.get(), x(i));
    arb_sub(d.get(), d.get(), l, 256);
    arb_abs(d.get(), d.get());
    arb_max(worst.get(), worst.get(), d.get(), 256);
    arb_abs(d.get(), l);
    arb_max(scale.get(), scale.get(), d.get(), 256);
  }
  arb_div(d.get(), worst.get(), scale.get(), 256);
  return detail::to_ball(d.get());
}

}  // namespace affinterp::certified
