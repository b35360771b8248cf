#pragma once
// The eigen-structure of S ∈ Sym(3) that our algorithms ("affinterp") use: the mean eigenvalue, the
// eigenpair that lies farthest from the other two, and the remaining pair described by its mean, its
// half-gap and its deviatoric part on the orthogonal complement. No eigenvalue gap is ever divided by,
// so clustered and repeated eigenvalues are as accurate as distinct ones.
//
// Written once over a lane type T: double (one matrix) or an xsimd batch (several matrices, see
// exp_batched.cpp). Functions of T are called unqualified so that xsimd's overloads are found by ADL.
//
// Range: the split is computed in double for matrices whose entries are at most kWideEntry in magnitude
// (down to subnormal ones and zero); callers send wider matrices elsewhere (affinterp.cpp), because there
// the absolute error ε‖S‖ of any double eigenvalue exceeds 10⁻⁴ and can no longer tell whether exp S
// overflows.
#include <cmath>
#include <type_traits>

namespace affinterp::sym3::split {

/// The six independent entries of a symmetric 3×3 matrix.
template <class T>
struct Sym {
  T xx, yy, zz, xy, xz, yz;
};

/// Lane-wise choice for plain doubles; xsimd::select serves the batches.
inline double select(bool condition, double if_true, double if_false) { return condition ? if_true : if_false; }

/// S = λ_far P + λ_mid (I − P) + K, P = v vᵀ: the pair's eigenvalues are λ_mid ± ρ.
template <class T>
struct SpectralSplit {
  T lambda_far;  ///< the eigenvalue farthest from the other two
  T far_gap;     ///< λ_far − λ_mid, without the cancellation of the difference (tiny matrices)
  Sym<T> P;      ///< the projector v vᵀ onto its unit eigenvector v
  T lambda_mid;  ///< mean of the other two eigenvalues
  T rho;         ///< half their gap (≥ 0)
  Sym<T> K;      ///< S − λ_far P − λ_mid (I − P): eigenvalues 0, ±ρ
};

/// Largest root of x³ − x/2 − τ = 0 for 0 ≤ τ ≤ 1/(3√6): the characteristic equation of a traceless
/// symmetric matrix of unit Frobenius norm (thesis §3.2 with tr S = 0, ‖S‖_F = 1, τ = det S).
/// On that range the root lies in [1/√2, √(2/3)] where the derivative 3x² − 1/2 ≥ 1; a degree-5 fit
/// (Chebyshev nodes, error < 6·10⁻⁷) and one Halley step give it to within 2·10⁻¹⁶.
template <class T>
T far_root(T tau) {
  const T x =
      T(0.70710731784884318) +
      tau * (T(0.99971313909022519) +
             tau * (T(-2.0954166147569828) +
                    tau * (T(7.0954792598411522) + tau * (T(-21.348259797242321) + tau * T(34.069988976208933)))));
  const T f = x * x * x - T(0.5) * x - tau, df = T(3.0) * x * x - T(0.5), ddf = T(6.0) * x;
  return x - T(2.0) * f * df / (T(2.0) * df * df - f * ddf);
}

/// Lane-wise "any" for plain booleans; xsimd::any serves the batches.
inline bool any(bool condition) { return condition; }

/// Entries up to 2⁴⁰ (about 1.1·10¹²) in magnitude are computed in double; see the file comment.
inline constexpr double kWideEntry = 0x1p40;

/// The largest magnitude among the six entries.
template <class T>
T max_abs(const Sym<T>& S) {
  using std::abs;
  using std::max;
  return max(max(max(abs(S.xx), abs(S.yy)), max(abs(S.zz), abs(S.xy))), max(abs(S.xz), abs(S.yz)));
}

template <class T>
T frobenius2(const Sym<T>& B) {
  return B.xx * B.xx + B.yy * B.yy + B.zz * B.zz + T(2.0) * (B.xy * B.xy + B.xz * B.xz + B.yz * B.yz);
}

template <class T>
Sym<T> scaled(const Sym<T>& B, T factor) {
  return {B.xx * factor, B.yy * factor, B.zz * factor, B.xy * factor, B.xz * factor, B.yz * factor};
}

/// The split of S. Shift by the mean eigenvalue m = tr S / 3; in B = S − mI, with σ = ‖B‖_F and
/// τ = det B / σ³, the eigenvalue farthest from the other two is ℓ = σ · far_root(|τ|) · sign τ (the
/// largest when det B ≥ 0, else the smallest; its distance to the pair is at least σ/√2). Its
/// eigenvector spans the columns of the adjugate of B − ℓI = (λ_pair1 − ℓ)(λ_pair2 − ℓ) v vᵀ, of which
/// the column with the largest diagonal entry is taken; the pair is what remains.
/// The adjugate scales like σ⁴ and its squared norm like σ⁸: for σ outside [10⁻³⁵, 10³⁵] (including
/// B = 0) B is first divided by its largest entry. That divisor is never subnormal: a deviatoric part
/// below 2⁻⁵⁰⁰ (subnormal entries such as 10⁻³¹⁰ included) is first multiplied by 2⁶⁰⁰, exactly.
/// Only the lanes that need it are rescaled, so a batch gives each matrix what the scalar code gives it.
/// Precondition: max_abs(S) ≤ kWideEntry (or at least no overflow in tr S and ‖B‖²_F).
template <class T>
SpectralSplit<T> spectral_split(const Sym<T>& S) {
  using std::abs;
  using std::copysign;
  using std::max;
  using std::sqrt;
  const T m = (S.xx + S.yy + S.zz) * T(1.0 / 3.0);
  Sym<T> B{S.xx - m, S.yy - m, S.zz - m, S.xy, S.xz, S.yz};
  T n2 = frobenius2(B);
  T scale = T(1.0);
  const auto rare = !((n2 >= T(1e-70)) & (n2 <= T(1e70)));
  if (any(rare)) {  // zero, tiny or huge deviatoric part
    const T amax = max_abs(B);
    const auto tiny = amax < T(0x1p-500);
    const T up = select(rare & tiny, T(0x1p600), T(1.0));
    const T a = amax * up;  // 0 or a normal number
    const T divisor = select(rare & (a != T(0.0)), a, T(1.0));
    B = scaled(scaled(B, up), T(1.0) / divisor);  // two steps: up / divisor may overflow
    scale = divisor * select(rare & tiny, T(0x1p-600), T(1.0));
    n2 = frobenius2(B);
  }
  const T sigma = sqrt(n2);
  const T inv_sigma = T(1.0) / select(sigma == T(0.0), T(1.0), sigma);
  const T det =
      B.xx * (B.yy * B.zz - B.yz * B.yz) - B.xy * (B.xy * B.zz - B.yz * B.xz) + B.xz * (B.xy * B.yz - B.yy * B.xz);
  const T tau = det * (inv_sigma * inv_sigma * inv_sigma);
  const T ell = copysign(far_root(abs(tau)), tau) * sigma;

  const T cxx = B.xx - ell, cyy = B.yy - ell, czz = B.zz - ell;
  const T axx = cyy * czz - B.yz * B.yz, ayy = czz * cxx - B.xz * B.xz, azz = cxx * cyy - B.xy * B.xy;
  const T axy = B.xz * B.yz - B.xy * czz, axz = B.xy * B.yz - B.xz * cyy, ayz = B.xy * B.xz - cxx * B.yz;
  const auto take_x = (abs(axx) >= abs(ayy)) & (abs(axx) >= abs(azz));
  const auto take_y = abs(ayy) >= abs(azz);
  const T u0 = select(take_x, axx, select(take_y, axy, axz));
  const T u1 = select(take_x, axy, select(take_y, ayy, ayz));
  const T u2 = select(take_x, axz, select(take_y, ayz, azz));
  const T uu = u0 * u0 + u1 * u1 + u2 * u2;
  const T inv_uu = T(1.0) / select(uu == T(0.0), T(1.0), uu);  // uu = 0 only for B = 0

  SpectralSplit<T> out;
  out.P = Sym<T>{u0 * u0 * inv_uu, u1 * u1 * inv_uu, u2 * u2 * inv_uu,
                 u0 * u1 * inv_uu, u0 * u2 * inv_uu, u1 * u2 * inv_uu};
  // K = B − ℓ P + (ℓ/2)(I − P) = B + (ℓ/2) I − (3ℓ/2) P, traceless with eigenvalues 0, ±ρ.
  const T half = T(0.5) * ell, three_half = T(1.5) * ell;
  const Sym<T>& P = out.P;
  const Sym<T> K{B.xx + half - three_half * P.xx, B.yy + half - three_half * P.yy, B.zz + half - three_half * P.zz,
                 B.xy - three_half * P.xy,        B.xz - three_half * P.xz,        B.yz - three_half * P.yz};
  out.lambda_far = m + scale * ell;
  out.far_gap = scale * three_half;
  out.lambda_mid = m - scale * half;
  out.rho = scale * sqrt(T(0.5) * frobenius2(K));
  out.K = scaled(K, scale);
  return out;
}

/// f(S) = f_pair I + w P + f_dd K with w = f_far − f_pair, i.e. f_far P + f_pair (I − P) + f_dd K, where
/// f_pair = (f(λ_mid + ρ) + f(λ_mid − ρ))/2 and f_dd = f[λ_mid − ρ, λ_mid + ρ] is the divided difference
/// (f′(λ_mid) when ρ = 0).
template <class T>
Sym<T> assemble_difference(const SpectralSplit<T>& s, T w, T f_pair, T f_dd) {
  const Sym<T>& P = s.P;
  return Sym<T>{f_pair + w * P.xx + f_dd * s.K.xx, f_pair + w * P.yy + f_dd * s.K.yy, f_pair + w * P.zz + f_dd * s.K.zz,
                w * P.xy + f_dd * s.K.xy,          w * P.xz + f_dd * s.K.xz,          w * P.yz + f_dd * s.K.yz};
}

template <class T>
Sym<T> assemble(const SpectralSplit<T>& s, T f_far, T f_pair, T f_dd) {
  return assemble_difference(s, f_far - f_pair, f_pair, f_dd);
}

/// exp(S − cI) from the split: e^{λ_mid − c} cosh ρ and e^{λ_mid − c} sinh ρ / ρ, the latter by its
/// Taylor series for ρ < 1/2 (no cancellation for tiny or zero gaps) and otherwise as
/// (e^{λ_hi − c} ± e^{λ_lo − c})/2 with λ_hi, λ_lo = λ_mid ± ρ, so that a wide pair (ρ > 709, e^ρ
/// overflows) whose upper eigenvalue is moderate gives no ∞·0. When the far eigenvalue lies within 1/2
/// of the pair's mean (then ρ ≤ |λ_far − λ_mid|/3 < 1/6), w = e^{λ_far} − f_pair would cancel: it is
/// e^{λ_mid − c} (expm1(λ_far − λ_mid) − (cosh ρ − 1)), whose terms do not (e^δ − cosh ρ ≥ sinh ρ for
/// δ ≥ 3ρ), so that exp of a tiny S is I + S entry by entry, not only in norm.
template <class T>
Sym<T> exp_shifted(const SpectralSplit<T>& s, T c) {
  using std::abs;
  using std::exp;
  using std::expm1;
  const T mid = s.lambda_mid - c;
  const T e_mid = exp(mid);
  const T e_hi = exp(mid + s.rho);
  const T e_lo = exp(mid - s.rho);
  const T r2 = s.rho * s.rho;
  // Series of (cosh ρ − 1)/ρ² and sinh ρ / ρ in ρ², enough terms for ρ ≤ 1/2 (next term < 10⁻¹⁹).
  T cosh_tail = T(1.0 / 20922789888000.0);      // 1/16!
  T sinhc_series = T(1.0 / 355687428096000.0);  // 1/17!
  constexpr double inv_fact_even[] = {1.0 / 87178291200.0, 1.0 / 479001600.0, 1.0 / 3628800.0, 1.0 / 40320.0,
                                      1.0 / 720.0,         1.0 / 24.0,        1.0 / 2.0};
  constexpr double inv_fact_odd[] = {1.0 / 1307674368000.0, 1.0 / 6227020800.0, 1.0 / 39916800.0, 1.0 / 362880.0,
                                     1.0 / 5040.0,          1.0 / 120.0,        1.0 / 6.0,        1.0};
  for (int i = 0; i < 7; ++i) cosh_tail = cosh_tail * r2 + T(inv_fact_even[i]);
  for (int i = 0; i < 8; ++i) sinhc_series = sinhc_series * r2 + T(inv_fact_odd[i]);
  const T coshm1_series = cosh_tail * r2;
  const auto small = s.rho < T(0.5);
  const T f_pair = select(small, e_mid * (coshm1_series + T(1.0)), T(0.5) * (e_hi + e_lo));
  const T f_dd = select(small, e_mid * sinhc_series, (e_hi - e_lo) / (T(2.0) * select(small, T(1.0), s.rho)));
  const auto near = abs(s.far_gap) < T(0.5);
  T w;
  if constexpr (std::is_same_v<T, double>) {
    w = near ? e_mid * (expm1(s.far_gap) - coshm1_series) : exp(s.lambda_far - c) - f_pair;
  } else {
    w = exp(s.lambda_far - c) - f_pair;
    if (any(near)) w = select(near, e_mid * (expm1(s.far_gap) - coshm1_series), w);
  }
  return assemble_difference(s, w, f_pair, f_dd);
}

/// Above this largest eigenvalue, exp is evaluated as e^709 exp(S − 709 I), so that exp S is finite
/// wherever its entries are (up to λ ≈ 709.78 + log 3 when the eigenvector is spread); below
/// kUnderflowShift as e^−700 exp(S + 700 I), so that entries near and below the smallest normal number
/// are rounded once, at the end. Both also keep xsimd's exp inside its range: it returns ∞ above
/// ≈ 709.44 and flushes results below the smallest normal double (arguments below ≈ −708.4) to 0, which
/// is harmless only for terms at least e⁻³⁷ ≈ ε below the largest (λmax ≥ −600 without the shift,
/// λmax + 700 ≥ −671 with it, or else exp S is below the smallest subnormal anyway).
inline constexpr double kOverflowShift = 709.0, kUnderflowShift = -600.0;

/// exp(S) from the split. Where an entry of exp S exceeds the largest double the result has infinite
/// (or NaN) entries; nowhere else.
template <class T>
Sym<T> exp_from_split(const SpectralSplit<T>& s) {
  using std::max;
  const T top = max(s.lambda_far, s.lambda_mid + s.rho);
  const auto high = top > T(kOverflowShift), low = top < T(kUnderflowShift);
  if (!any(high | low)) return exp_shifted(s, T(0.0));
  const T c = select(high, T(709.0), select(low, T(-700.0), T(0.0)));
  // e^709 and e^−700 rounded to nearest (relative error below 2⁻⁵³).
  const T factor = select(high, T(0x1.d422d2be5dc9bp+1022), select(low, T(0x1.14f2b0fb9307fp-1010), T(1.0)));
  return scaled(exp_shifted(s, c), factor);
}

}  // namespace affinterp::sym3::split
