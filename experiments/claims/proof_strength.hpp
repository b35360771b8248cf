#pragma once
// How strong a verdict its proof makes it, computed from what the checkers answered, never stated by hand: `proved`
// when every sentence and identity of one complete formulation was answered by two independent checkers and it cites
// nothing, `proved-one-decider` when some sentence by one only, `proved-citing` when the method uses an external
// published theorem as a step (experiments/proofs/citations.hpp); no strength when a sentence is unanswered, or when
// every sentence is structural (empty for propositional reasons alone: no evidence for the claim) and nothing is cited.
// A proof's further formulations (Proof::formulations, e.g. the literal one) are each a complete proof: one of them
// `proved` makes the claim `proved`; otherwise the lemma chain's label holds.
#include "experiments/claims/verdict.hpp"
#include "experiments/proofs/proof.hpp"

#include <optional>

namespace affinterp::claims {

/// The strength of one formulation alone.
inline std::optional<Strength> formulation_strength(const proofs::Proof& proof) {
  if (!proof.decided()) return std::nullopt;
  // A cited theorem carries the step the sentences leave to it, structural residues included.
  if (!proof.cites.empty()) return Strength::proved_citing;
  if (!proof.has_content()) return std::nullopt;
  return proof.decided_by_two() ? Strength::proved : Strength::proved_one_decider;
}

inline std::optional<Strength> proof_strength(const proofs::Proof& proof) {
  std::optional<Strength> strength = formulation_strength(proof);
  for (const proofs::Proof& formulation : proof.formulations) {
    const std::optional<Strength> s = formulation_strength(formulation);
    if (s == Strength::proved) return s;
    if (!strength) strength = s;
  }
  return strength;
}

/// Whether `s` is one of the proved strengths.
inline bool is_proved(Strength s) {
  return s == Strength::proved_kernel_checked || s == Strength::proved || s == Strength::proved_hand_steps ||
         s == Strength::proved_one_decider || s == Strength::proved_citing;
}

}  // namespace affinterp::claims
