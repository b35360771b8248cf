#pragma once
// The 3D goodness atlas: for each homotopy of a 3×3 map A ∈ GL⁺(3) and each notion (volume, norm; the 3D
// counterparts of thesis Defs 2.2.1, 2.2.2, reports/proofs/LEMMAS.md "3D"), the parameters a user evaluates,
// their domain and the region where the homotopy is good, in the `decide` grammar (experiments/claims/atlas3/).
//
//   linear   volume: c1, c2, c3 = tr M, σ₂(M), det M of M = A − I (det(I + tM) = 1 + c1 t + c2 t² + c3 t³, L16)
//            norm:   a11 … a33, the entries of A
//   polar    l1, l2, l3: the eigenvalues of S in A = RS (the singular values of A); R^t has det 1 and is
//   exp-log    orthogonal, and S's eigenbasis carries ‖·‖ (Lemmas L14, L15)
//   svd      l1, l2, l3: the singular values (volume only; the norm cell is open, LEMMAS.md L19)
// Macros: c1, c2, c3 also for the eigenvalue cells (the invariants of S − I); for the linear norm p11 … p33 and
// q11 … q33, the entries of P = sym(A) − I and Q = AᵀA − sym(A), and detP, detQ.
#include "experiments/proofs/atlas.hpp"

#include <optional>
#include <vector>

namespace affinterp::proofs {

const std::vector<AtlasCell>& atlas3_cells();
/// The 3D cell of a homotopy and notion (Notion::volume or Notion::norm); throws std::invalid_argument for a
/// cell the 3D atlas does not have (svd norm).
const AtlasCell& atlas3_cell(Homotopy h, Notion n);

/// Whether the homotopy is good at `p` by theory/local/goodness3.hpp, or nullopt where it has no decider (exp-log
/// volume and the singular-value cells: always good by Lemmas L17, L25, nothing to evaluate) or, for the linear
/// norm, no certificate either way.
std::optional<bool> suite_says_good3(const AtlasCell& cell, const logic::Point& p);

}  // namespace affinterp::proofs
