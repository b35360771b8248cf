#pragma once
// Kaji's "finer evaluators" in 3D: A(t) is good for singular values when each singular value
// σ1(t) ≥ σ2(t) ≥ σ3(t) of A(t) is monotone on [0, 1] (LEMMAS.md L25). For the polar, SVD and exp-log homotopies
// it always is; the cells share their parameters (l1, l2, l3) and their residue sentences here.
#include "experiments/claims/atlas/proved_cell.hpp"

namespace affinterp::claims::atlas3 {

/// The cell "always good for singular values" of the polar, SVD or exp-log homotopy, over l1, l2, l3 > 0.
const proofs::AtlasCell& singular_values_cell(proofs::Homotopy h);

/// L25's residue for σ_k(t) = 1 + t(l_(k) − 1) (polar, SVD): the blend's eigenvalues are positive on [0, 1] and
/// keep their order on (0, 1], as two sentences in a, b, t.
std::vector<proofs::Sentence> blend_order_sentences();
/// The polar or SVD cell (`homotopy`): by Lemma L25 the sorted singular values of A(t) are 1 + t(l_(k) − 1), each
/// monotone, the rotations changing none of them; proved by the residue sentences blend_order_sentences (the same at
/// every size; nothing is left for the suite's decider to compare), drawn over (l1, l2) at l3 = 1/2.
Outcome blend_singular_values_outcome(const ClaimContext& ctx, proofs::Homotopy homotopy);

/// L25's residue for σ_k(t) = e^{t L_(k)}, L = log l (exp-log): t L keeps the order of L for t ∈ (0, 1].
std::vector<proofs::Sentence> exponent_order_sentences();

}  // namespace affinterp::claims::atlas3
