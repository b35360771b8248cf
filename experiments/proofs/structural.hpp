#pragma once
// Structural sentences: a sentence that is empty for propositional reasons alone says nothing about
// the polynomials in it, so its emptiness is no evidence for the claim. Replace every polynomial atom by a
// boolean (the same boolean for the same atom, and its negation for the opposite sign condition, e.g. p > 0
// and p <= 0, or −p < 0); if the resulting propositional formula is unsatisfiable, the sentence is structural.
#include "theory/logic/formula.hpp"

namespace affinterp::proofs {

/// Whether `sentence` (quantifiers dropped) is unsatisfiable as a propositional formula over its atoms.
bool is_structural(const logic::Formula& sentence);

}  // namespace affinterp::proofs
