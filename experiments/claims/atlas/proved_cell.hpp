#pragma once
// What the eight atlas claims share: the claim is that a cell's condition is exactly
// where its homotopy is good. Its proof is two (or more) sentences decided empty by QEPCAD B and Z3; the
// second line of evidence is the suite's own exact decider at random rational points; the figure is the
// region the condition describes, evaluated exactly on a grid.
#include "experiments/claims/context.hpp"
#include "experiments/claims/outcome.hpp"
#include "experiments/proofs/atlas.hpp"
#include "experiments/proofs/decide_sentence.hpp"
#include "experiments/proofs/formulation.hpp"

#include <string>
#include <vector>

namespace affinterp::claims::atlas {

using exact::Rational;

/// A plane slice of the parameters for the region map: two variables on [lo, hi]², the others fixed.
struct Slice {
  std::string x, y;
  double lo, hi;
  logic::Point fixed;  ///< the other variables
  std::string label;   ///< e.g. "h = 1/2"
};

struct AtlasProof {
  std::string scope;   ///< the domain, in words
  std::string method;  ///< encoding levels and lemmas (reports/proofs/LEMMAS.md)
  std::vector<proofs::Sentence> sentences;
  /// A sentence of these names may be decided by Z3 alone: QEPCAD decides the same direction through the
  /// lemma sentences the method names instead (svd norm, Lemma L12).
  std::vector<std::string> z3_only;
  /// Identities the method rests on, checked by exact polynomial arithmetic: name → (lhs − rhs) which must be 0.
  std::vector<std::pair<std::string, logic::Polynomial>> identities;
  /// An external published theorem the method uses as a step (experiments/proofs/citations.hpp); empty: none.
  std::string cites{};
  /// Further formulations, each a complete proof: the literal one first.
  std::vector<proofs::FormulationPlan> formulations{};
  /// Formulations tried for the record: decided once under their own limits, or not expressible.
  std::vector<proofs::AttemptPlan> attempts{};
};

/// Decides the proof's sentences and assembles the outcome: confirmed and proved when every sentence is empty
/// (by both deciders, or as `z3_only` allows; or every sentence of a further formulation) and every identity holds;
/// refuted with the deciders' point when a sentence is non-empty; inconclusive otherwise. Adds the random-point
/// comparison with the suite's exact decider (when it has one) and the region maps of `slices`.
Outcome atlas_outcome(const ClaimContext& ctx, const proofs::AtlasCell& cell, const AtlasProof& proof,
                      const std::vector<Slice>& slices);

/// ∃ cell variables (and `extra`): domain ∧ `set`.
proofs::Sentence atlas_sentence(const proofs::AtlasCell& cell, const std::string& name, const std::string& meaning,
                                const logic::Formula& set, const std::vector<std::string>& extra = {});
/// The cell's condition against `property` (at encoding `level`): "cond-not-prop.<level>" and
/// "prop-not-cond.<level>" over the cell's variables and domain (experiments/proofs/condition_sentences.hpp).
std::vector<proofs::Sentence> condition_sentences(const proofs::AtlasCell& cell, const std::string& level,
                                                  const logic::Formula& property);

}  // namespace affinterp::claims::atlas
