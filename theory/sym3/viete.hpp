#pragma once
// Thesis §3.2: eigenvalues of S ∈ Sym(3) by Viète's trigonometric formula, written over any real type
// (double for the algorithm, Real100 for deciding the claim thesis.viete).
#include "theory/sym3/algorithms.hpp"

#include <array>
#include <boost/math/constants/constants.hpp>
#include <cmath>

namespace affinterp::sym3 {

/// The printed quantities: p = ((tr S)² − 3‖S‖²_F)/6, q = 5/54 (tr S)³ − 1/6 tr S ‖S‖²_F − det S,
/// r = √(−12p), k = −108q / r³.
template <class Real>
struct VieteParameters {
  Real trace, frobenius2, det, p, q, r, k;
};

/// The printed p and q alone: rational in the entries, so exact over exact::Rational.
template <class Real>
std::array<Real, 2> viete_pq(const Real& trace, const Real& frobenius2, const Real& det) {
  return {(trace * trace - 3 * frobenius2) / 6, Real(5) / 54 * trace * trace * trace - trace * frobenius2 / 6 - det};
}

template <class Real>
VieteParameters<Real> viete_parameters(const Real& trace, const Real& frobenius2, const Real& det) {
  using std::sqrt;
  VieteParameters<Real> v{trace, frobenius2, det, {}, {}, {}, {}};
  const auto [p, q] = viete_pq(trace, frobenius2, det);
  v.p = p;
  v.q = q;
  v.r = sqrt(-12 * v.p);
  v.k = -108 * v.q / (v.r * v.r * v.r);
  return v;
}

/// The printed λ1, λ2, λ3 = (r cos((arccos(k) + 2π(i−1))/3) + tr S)/3, i = 1, 2, 3, with the
/// printed special case p = 0: all equal to tr S / 3. In this order λ1 ≥ λ3 ≥ λ2.
template <class Real>
std::array<Real, 3> viete_printed(const VieteParameters<Real>& v) {
  using std::acos;
  using std::cos;
  if (v.p == 0) return {v.trace / 3, v.trace / 3, v.trace / 3};
  const Real two_pi = 2 * boost::math::constants::pi<Real>();
  const Real theta = acos(v.k);
  return {(v.r * cos(theta / 3) + v.trace) / 3, (v.r * cos((theta + two_pi) / 3) + v.trace) / 3,
          (v.r * cos((theta + 2 * two_pi) / 3) + v.trace) / 3};
}

/// The printed formula evaluated in double, in the printed order (NaN where rounding makes p > 0 or
/// |k| > 1, which the printed text does not provide for).
std::array<double, 3> viete_printed_order(const Mat3& S);
/// Thesis §3.2 as printed, sorted ascending.
Vec3 eigenvalues_viete(const Mat3& S);
/// The same formula with rounding guarded: p clamped to ≤ 0, k to [−1, 1], r = 0 giving tr S / 3.
std::array<double, 3> viete_clamped_order(const Mat3& S);
Vec3 eigenvalues_viete_clamped(const Mat3& S);

}  // namespace affinterp::sym3
