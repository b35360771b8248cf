#pragma once
// The conditions thesis §2.2 prints for Defs 2.2.1 and 2.2.2, and the corrected area condition, as quantifier-free
// formulas over the reals: the conditions of the local claims' sentences (experiments/proofs/
// condition_sentences.hpp), the same as theory/local/thesis_conditions.hpp decides at rational points.
#include "theory/logic/formula.hpp"

namespace affinterp::claims::local {

using logic::Formula;
using logic::Polynomial;

/// Thm 2.2.1 as printed: tr ≥ det + 1, or 2 det ≤ tr < 2, or 2 ≤ tr < 2 det (theory/local/thesis_conditions.hpp).
Formula thm_2_2_1_formula(const Polynomial& trace, const Polynomial& det);
/// The corrected area condition: 2 det ≤ tr ≤ 2, or 2 ≤ tr ≤ 2 det.
Formula corrected_area_formula(const Polynomial& trace, const Polynomial& det);
/// Thm 2.2.3 as printed: x, y ≥ 1, or 0 < x, y ≤ 1.
Formula thm_2_2_3_formula(const Polynomial& x, const Polynomial& y);
/// Thm 2.2.5 as printed: (x−1)(y−1) ≥ h² and (x + y ≥ 2 or 0 < x, y ≤ 1).
Formula thm_2_2_5_formula(const Polynomial& x, const Polynomial& y, const Polynomial& h);

}  // namespace affinterp::claims::local
