#pragma once
// The sentences that prove a condition exact for a property: a condition C is where a property P
// holds on a domain exactly when both sets
//   cond-not-prop  {x in the domain : C(x) ∧ ¬P(x)}
//   prop-not-cond  {x in the domain : ¬C(x) ∧ P(x)}
// are empty; each is the existential sentence ∃x: domain ∧ …, decided for all reals by QEPCAD B and Z3
// (decide_sentence.hpp). The local claims (thesis §2.2, P from goodness_formulas.hpp at some encoding level)
// and the goodness atlas (experiments/claims/atlas) build theirs here.
#include "experiments/proofs/decide_sentence.hpp"
#include "theory/logic/formula.hpp"

#include <string>
#include <vector>

namespace affinterp::proofs {

/// ∃ variables: body, named and explained.
Sentence sentence(std::string name, std::string meaning, std::vector<std::string> variables, logic::Formula body);

/// "<prefix>cond-not-prop.<level>": ∃ variables: domain ∧ condition ∧ ¬property (property at encoding `level`).
Sentence cond_not_prop(const std::string& prefix, const std::string& level, const std::vector<std::string>& variables,
                       const logic::Formula& domain, const logic::Formula& condition, const logic::Formula& property);
/// "<prefix>prop-not-cond.<level>": ∃ variables: domain ∧ ¬condition ∧ property (property at encoding `level`).
Sentence prop_not_cond(const std::string& prefix, const std::string& level, const std::vector<std::string>& variables,
                       const logic::Formula& domain, const logic::Formula& condition, const logic::Formula& property);

}  // namespace affinterp::proofs
