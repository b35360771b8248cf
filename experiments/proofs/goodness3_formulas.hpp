#pragma once
// The 3D goodness definitions (reports/proofs/LEMMAS.md, "3D") as first-order formulas over the reals, for the
// sentences that prove the 3D atlas (experiments/claims/atlas3/). Each is built from the homotopy's own
// polynomials at an encoding level of LEMMAS.md (D: derivative, E: derivative read at the ends, C: the cone of
// per-axis slopes, Lemma L15), the same quantities theory/local/goodness3.hpp evaluates at rational points.
#include "theory/logic/formula.hpp"

#include <array>
#include <string>

namespace affinterp::proofs {

using Eigenvalues = std::array<logic::Polynomial, 3>;

/// det((1−t)I + t diag(l1, l2, l3)) = ∏ (1 + t(l_i − 1)): det A(t) of the polar and SVD homotopies (Lemma L14).
logic::Polynomial det_of_diagonal_blend(const Eigenvalues& l, const logic::Polynomial& t);
/// 1 + c1 t + c2 t² + c3 t³ = det(I + tM) for M with invariants c1, c2, c3 (Lemma L16).
logic::Polynomial det_by_invariants(const logic::Polynomial& c1, const logic::Polynomial& c2,
                                    const logic::Polynomial& c3, const logic::Polynomial& t);
/// Volume at level D: ∀t ∈ [0, 1]: p(t) > 0, and p′ ≥ 0 on [0, 1] or p′ ≤ 0 on [0, 1] (Lemma L1); p in "t".
logic::Formula volume_property(const logic::Polynomial& p);
/// Norm of the polar homotopy at level E in S's eigenbasis (Lemmas L3, L14, L15): for every v = (v1, v2, v3),
/// ‖((1−t)I + t diag(l))v‖²'s derivative does not take opposite strict signs at t = 0 and t = 1.
logic::Formula polar_norm_property(const Eigenvalues& l);
/// Norm at level C (Lemma L15): no pair of axes i, j with g_i(0) > 0 > g_j(0) and g_i(0)g_j(1) − g_j(0)g_i(1) > 0,
/// given the per-axis slopes at t = 0 and 1 (polar: μ_i, μ_i l_i) or polynomials of their signs (exp-log).
logic::Formula cone_property(const std::array<logic::Polynomial, 3>& sign_at_0,
                             const std::array<std::array<logic::Polynomial, 3>, 3>& cross);
/// The exp-log slopes' signs: g_i(0), g_i(1) have the sign of l_i − 1, and the cross term
/// log l_i log l_j (l_j² − l_i²) the sign of (l_i − 1)(l_j − 1)(l_j² − l_i²) (Lemma L17).
logic::Formula exp_log_norm_property(const Eigenvalues& l);
/// The polar slopes μ_i = l_i − 1 at t = 0 and μ_i l_i at t = 1 at level C.
logic::Formula polar_norm_cone_property(const Eigenvalues& l);
/// Lemma L15 (b) fails: generators (a_i, b_i) with a_i b_i > 0 or a_i = b_i = 0, weights w_i ≥ 0 with
/// Σ w_i a_i < 0 < Σ w_i b_i, and no pair i, j with a_i > 0 > a_j and a_i b_j − a_j b_i > 0 (variables a1 … w3).
logic::Formula cone_lemma_fails();

}  // namespace affinterp::proofs
