#pragma once
// The lemmas of reports/proofs/LEMMAS.md that are first-order sentences themselves, each empty iff the lemma
// holds: a proof that uses one decides it as its own sentence (the local claims, the atlas, and the literal
// formulations). The quadratic lemmas are stated for f = 1 + c1 t + c2 t²; their sentences contain
// no constant term (only differences f(s) − f(t) and the derivative occur), so each is the lemma for every
// quadratic c0 + c1 t + c2 t².
#include "experiments/proofs/decide_sentence.hpp"

namespace affinterp::proofs {

Sentence lemma_L1();       ///< monotone as written ⇔ f′ of one sign on [0, 1]
Sentence lemma_L2();       ///< f′ affine: f′ of one sign on [0, 1] ⇔ read at t = 0, 1
Sentence lemma_L2_area();  ///< (f > 0 on [0, 1] ∧ monotone) ⇔ (f(1) > 0 ∧ endpoint-monotone)
Sentence lemma_L3();       ///< g affine with slope ≥ 0 takes both strict signs ⇔ g(0) < 0 < g(1)
Sentence lemma_L4();       ///< for a, b ≥ 0: a ≤ b ⇔ a² ≤ b² (a norm is monotone iff its square is)
/// Every unit vector is a non-zero multiple of (1, m) for some real m or of (0, 1): with ‖A(t)(λv)‖ =
/// |λ|‖A(t)v‖, Def 2.2.2 for every unit v is Def 2.2.2 for these directions (Lemma L6).
Sentence lemma_L6_directions();
/// Every real 2×2 A has a rotation O = [[co, −si], [si, co]] with sym(OᵀAO) diagonal, i.e. OᵀAO = [[p, −k], [k, r]]
/// (Lemma L7 (c), the spectral theorem's step, decided instead of taken from L13).
Sentence lemma_L7_normal_form();

}  // namespace affinterp::proofs
