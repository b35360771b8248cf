#pragma once
// The local errors of local_error.hpp in the complex form of hermitian_form.hpp: over a triangle's complex
// vertices z = (z_0, z_1, z_2), E_i = z*Hz + Re(ũ*z) + c. Write μ_k for the complex number of the vector
// A D_kᵀ (A applied to the k-th row of D, B = V D), so that vec A's inner product with B's k-th term is
// Re(μ̄_k z_k) and vec JA's is Im(μ̄_k z_k). Then (the real forms' H, read through hermitian_block):
//     E^F:  H = D Dᵀ,                    ũ = −2μ      (‖B‖² = z*DDᵀz, −2⟨A, B⟩ = Re((−2μ)*z));
//     E^R:  H = D Dᵀ − μμ*/‖A‖²,         ũ = 0        (⟨A, B⟩² + ⟨JA, B⟩² = |μ*z|²);
//     E^S:  H = Π − x x*/‖X‖²,           ũ = 0        (x_k = the complex number of A p̃_k, Π = I − 𝟙𝟙ᵀ/3);
//     blend: w E^F + (1 − w) E^R.
// E^R (E^S) is the squared distance of B from the complex line {λA : λ ∈ C} (of Y from {λX}): it removes
// one complex dimension, the rank-2 real projection behind kaji.er.positive-definite.
#include "theory/global/options.hpp"

#include <Eigen/Core>

#include <complex>

namespace affinterp::global {

struct HermitianTriangleForm {
  Eigen::Matrix3cd H;
  Eigen::Vector3cd u;  ///< ũ
};

namespace detail {
inline Eigen::Vector3cd complex_columns(const Eigen::Matrix<double, 2, 3>& X) {
  return Eigen::Vector3cd({X(0, 0), X(1, 0)}, {X(0, 1), X(1, 1)}, {X(0, 2), X(1, 2)});
}

/// w of w E^F + (1 − w) E^R: 1 for E^F, the blend's weight, 0 for E^R.
inline double frobenius_share(Energy energy, double w) {
  return energy == Energy::F ? 1.0 : energy == Energy::blend ? w : 0.0;
}
}  // namespace detail

/// ũ = −2μ of E^F.
inline Eigen::Vector3cd hermitian_frobenius_linear_term(const Eigen::Matrix<double, 3, 2>& D,
                                                        const Eigen::Matrix2d& A) {
  return -2.0 * detail::complex_columns(A * D.transpose());
}

/// H of E^R, E^S and the blend split as H = H₀ − c v v*: H₀ the part that does not depend on A (D Dᵀ; Π for
/// E^S), and the rank-one term that removes the complex line of A (of X). E^F has c = 0.
struct HermitianRankOne {
  Eigen::Vector3cd v;  ///< μ (E^R, blend) or x (E^S)
  double c;            ///< (1 − w)/‖A‖² (E^R: w = 0; E^F: w = 1) or 1/‖X‖² (E^S)
};

/// H₀ of one triangle's E^F, E^R or blend (D Dᵀ) or E^S (Π), real.
inline Eigen::Matrix3d hermitian_constant_part(Energy energy, const Eigen::Matrix<double, 3, 2>& D) {
  if (energy == Energy::S) return Eigen::Matrix3d::Identity() - Eigen::Matrix3d::Constant(1.0 / 3);
  return D * D.transpose();
}

/// The rank-one term c v v* of one triangle's H at A (w the E^F share of a blend, p its corners for E^S).
inline HermitianRankOne hermitian_rank_one_part(Energy energy, const Eigen::Matrix<double, 3, 2>& D,
                                                const Eigen::Matrix<double, 2, 3>& p, const Eigen::Matrix2d& A,
                                                double w) {
  if (energy == Energy::S) {
    const Eigen::Vector3cd x = detail::complex_columns(A * (p.colwise() - p.rowwise().mean()));
    return {x, 1.0 / x.squaredNorm()};
  }
  return {detail::complex_columns(A * D.transpose()), (1.0 - detail::frobenius_share(energy, w)) / A.squaredNorm()};
}

/// One triangle's E^F, E^R or blend (w the E^F share), or E^S from its corners p: H = H₀ − c v v*, and ũ.
inline HermitianTriangleForm hermitian_local_error(Energy energy, const Eigen::Matrix<double, 3, 2>& D,
                                                   const Eigen::Matrix<double, 2, 3>& p, const Eigen::Matrix2d& A,
                                                   double w) {
  HermitianTriangleForm form{Eigen::Matrix3cd::Zero(), Eigen::Vector3cd::Zero()};
  form.H.real() = hermitian_constant_part(energy, D);
  const HermitianRankOne rank_one = hermitian_rank_one_part(energy, D, p, A, w);
  if (rank_one.c != 0) form.H -= rank_one.c * (rank_one.v * rank_one.v.adjoint());
  if (const double share = detail::frobenius_share(energy, w); energy != Energy::S && share > 0.0)
    form.u = -2.0 * share * rank_one.v;  // v = μ
  return form;
}

}  // namespace affinterp::global
