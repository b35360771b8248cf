#pragma once
// The complex form of the global error function. Identify a vertex v = (x, y) with z = x + iy, so that
// rotating every vertex by π/2 together, v ↦ Jv, is z ↦ iz. The quadratic part of every local error of
// Kaji §4 is unchanged by it: for E^F it is ‖B‖², ‖JB‖ = ‖B‖; for E^R (and E^S, the same expression in
// X = A P̃) it is ‖B‖² − (⟨A, B⟩² + ⟨JA, B⟩²)/‖A‖², and ⟨A, JB⟩ = −⟨JA, B⟩, ⟨JA, JB⟩ = ⟨A, B⟩ since
// JᵀJ = I, Jᵀ = −J. Every constraint term c ‖Σ α_k v_k − r‖² is unchanged as well. A real quadratic form
// vᵀGv that commutes with J in this way is a Hermitian form z*Hz: each 2×2 block of G is
//     G_kl = [[Re H_kl, −Im H_kl], [Im H_kl, Re H_kl]],   H_kl = G_{2k,2l} + i G_{2k+1,2l},
// and the linear part vᵀu is Re(ũ* z) with ũ_k = u_{2k} + i u_{2k+1}. So the minimiser of vᵀGv + vᵀu
// solves the n × n complex system H z = −ũ/2 instead of the 2n × 2n real one: a quarter of the non-zeros,
// and a numeric factorisation several times faster than the real form's (sparse_minimiser.hpp).
#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <complex>

namespace affinterp::global {

/// H of one triangle's 6×6 real form G (vertex-interleaved coordinates): H_ab = G_{2a,2b} + i G_{2a+1,2b}.
inline Eigen::Matrix3cd hermitian_block(const Eigen::Matrix<double, 6, 6>& G) {
  Eigen::Matrix3cd H;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) H(a, b) = {G(2 * a, 2 * b), G(2 * a + 1, 2 * b)};
  return H;
}

/// The real 2n × 2n form G of the Hermitian H, block by block: G holds the blocks of whichever entries of H
/// are stored (the lower triangle of H gives the lower triangle of G, its diagonal blocks being symmetric).
Eigen::SparseMatrix<double> realified(const Eigen::SparseMatrix<std::complex<double>>& H);

}  // namespace affinterp::global
