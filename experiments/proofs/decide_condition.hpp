#pragma once
// `affinterp decide`: is a condition the exact region where a homotopy is good? The
// property is replaced by the atlas condition proved equivalent to it (experiments/claims/atlas), so both
// sentences, "condition ∧ ¬property" and "¬condition ∧ property" over the domain, are quantifier-free
// existential problems that QEPCAD B and Z3 decide within seconds (wall times: reports/claims.json).
#include "experiments/proofs/atlas.hpp"
#include "experiments/proofs/decide_sentence.hpp"

#include <optional>
#include <string>
#include <vector>

namespace affinterp::proofs {

/// A point where the condition and the property differ: shrunk to small rationals, re-verified exactly.
struct Counterexample {
  logic::Point point;  ///< in the cell's variables
  bool condition = false;
  bool property = false;
  bool checked_by_suite = false;  ///< the suite's own exact decider (goodness.hpp) confirmed `property`
};

struct ConditionVerdict {
  enum class Verdict { equivalent, not_equivalent, unknown } verdict = Verdict::unknown;
  std::optional<Counterexample> counterexample;
  std::string reason;  ///< why unknown, or what a verdict rests on when only one decider finished
  std::vector<SentenceDecision> sides;
};

/// The cell `affinterp decide` answers for: dimension 2 (notions "area", "norm", atlas.hpp) or 3 ("volume",
/// "norm", atlas3.hpp); homotopy "linear", "svd", "polar" or "exp-log". Throws std::invalid_argument, with a
/// one-line reason, for anything else (the 3D SVD norm is open: no cell).
const AtlasCell& decide_cell(int dimension, const std::string& homotopy, const std::string& notion);

/// "equivalent", "not-equivalent", "unknown".
std::string_view to_string(ConditionVerdict::Verdict v);

/// Decides whether `condition` (over the cell's variables) holds exactly where the cell's homotopy is good.
/// Sides are decided one after the other, each by both deciders at once within `limits`; the second side is
/// skipped when the first already has a counterexample. Disagreeing deciders give `unknown` with the reason.
ConditionVerdict decide_condition(const AtlasCell& cell, const logic::Formula& condition, const DeciderLimits& limits,
                                  const SentenceFiles& files = {});

}  // namespace affinterp::proofs
