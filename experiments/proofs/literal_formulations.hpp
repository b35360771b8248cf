#pragma once
// The second formulations, the definitions as written, for the homotopies A(t) = U(t)((1−t)I + tB)V(t) whose
// rotations leave det and ‖·‖ alone (Lemma L5): a condition against Def 2.2.1 or 2.2.2 taken as nearly as
// written as a decider answers it, each lemma still used a sentence of the formulation
// (experiments/proofs/lemma_sentences.hpp). The local claims and the atlas build theirs here.
#include "experiments/proofs/formulation.hpp"
#include "experiments/proofs/goodness_formulas.hpp"

#include <string>
#include <vector>

namespace affinterp::proofs {

/// What the formulations compare: a condition on a domain against the homotopy's B.
struct ConditionOnDomain {
  std::string prefix;                  ///< of the sentence names, e.g. "printed."
  std::vector<std::string> variables;  ///< the parameters
  logic::Formula domain, condition;
  PolyMat2 B;
  /// QEPCAD with Hong's projection (hong_projection), where McCallum's errs.
  bool hong = false;
};

/// Def 2.2.1 as written (level L: det > 0 for every t in [0, 1] and monotone for all 0 <= s <= t <= 1), against
/// the condition: "<prefix>cond-not-prop.L" and "<prefix>prop-not-cond.L"; lemmas: L5 only (an identity).
FormulationPlan area_literal(const ConditionOnDomain& c);

/// Def 2.2.2 without Dines' theorem and without Lemma L3, over the directions (1, m), (0, 1)
/// (norm_property_directions): at level D (lemmas L4, L6, L1 as sentences) and at level E (and L2); the
/// sentences "<prefix>directions.cond-not-prop.<level>" and "…prop-not-cond.<level>".
std::vector<FormulationPlan> norm_directions(const ConditionOnDomain& c);

/// The same at level L (the squared norm monotone as written; lemmas L4, L6), as an attempt for the record.
AttemptPlan norm_directions_literal(const ConditionOnDomain& c);

}  // namespace affinterp::proofs
