#pragma once
// Defs 2.2.1 and 2.2.2 as first-order formulas at the encoding levels of reports/proofs/LEMMAS.md, for
// A(t) = U(t)((1−t)I + tB)V(t) with U, V leaving det and ‖·‖ alone (Lemma L5):
//   area, level D (Lemma L1): det A(t) > 0 on [0, 1] and its t-derivative ≥ 0 on [0, 1] or ≤ 0 on [0, 1];
//   area, level E (Lemmas L1, L2): det B > 0 and the derivative's values at t = 0, 1 (tr B − 2, 2 det B − tr B)
//     not of opposite strict signs;
//   norm, level N (Lemmas L3, L4, L6, L8): with M = B − I, P = sym M, Q = P + MᵀM: Q ⪯ 0 or ∃ν ≥ 0: P − νQ ⪰ 0.
#include "theory/logic/formula.hpp"

#include <array>

namespace affinterp::proofs {

/// B = [[b00, b01], [b10, b11]] with polynomial entries.
using PolyMat2 = std::array<std::array<logic::Polynomial, 2>, 2>;

logic::Formula area_level_D(const PolyMat2& B, const std::string& t);
logic::Formula area_level_E(const PolyMat2& B);
logic::Formula norm_level_N(const PolyMat2& B, const std::string& nu);

}  // namespace affinterp::proofs
