#pragma once
// The polar and SVD volume cells through the linear one (Lemma L16): det((1−t)I + t diag(l)) is
// 1 + c1 t + c2 t² + c3 t³ with c1, c2, c3 the invariants of diag(l) − I, and 1 + c1 + c2 + c3 = l1 l2 l3 > 0 puts
// them in the linear cell's domain, where its condition (the same text) is proved exact. A second formulation for
// the eigenvalue cells, whose own level-D sentence "prop-not-cond" only QEPCAD B answers.
#include "experiments/claims/atlas/proved_cell.hpp"

namespace affinterp::claims::atlas3 {

/// The residue (the invariants of S − I lie in the linear cell's domain) and the linear cell's two sentences.
proofs::FormulationPlan through_linear_volume(const proofs::AtlasCell& eigenvalue_cell);
/// ∏(1 + t(l_i − 1)) − (1 + c1 t + c2 t² + c3 t³) with the cell's macros for c1, c2, c3: zero (Vieta).
std::pair<std::string, logic::Polynomial> vieta_identity(const proofs::AtlasCell& eigenvalue_cell);

/// The polar or SVD volume cell (`homotopy`), whose rotations have determinant 1 (Lemma L14) so that
/// det A(t) = det((1−t)I + t diag(l1, l2, l3)) = ∏(1 + t(l_i − 1)) in the eigenvalues of S (the singular values of
/// A): level D (Lemma L1) in l1, l2, l3 with t quantified, two sentences, and the formulation through the linear
/// cell; its region drawn over (l1, l2) at l3 = 1/4 and l3 = 3. The same sentences at every size; random points
/// 200 (quick) / 2000 (full).
Outcome eigenvalue_volume_outcome(const ClaimContext& ctx, proofs::Homotopy homotopy);

}  // namespace affinterp::claims::atlas3
