#pragma once
// How a local claim is proved for all reals: its sentences, decided by QEPCAD B and Z3
// (experiments/proofs), the lemmas that reduce them (L1–L13, reports/proofs/LEMMAS.md), the polynomial identities
// the method rests on (checked by exact polynomial arithmetic), and for a non-empty sentence a counterexample
// shrunk to small rationals and re-verified by the suite's own exact evaluators.
#include "experiments/claims/context.hpp"
#include "experiments/claims/outcome.hpp"
#include "experiments/claims/proof_strength.hpp"
#include "experiments/proofs/condition_sentences.hpp"
#include "experiments/proofs/decide_sentence.hpp"
#include "experiments/proofs/formulation.hpp"
#include "experiments/proofs/goodness_formulas.hpp"
#include "experiments/proofs/lemma_sentences.hpp"
#include "experiments/proofs/witness.hpp"

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace affinterp::claims::local {

// The sentences and the goodness formulas are built by experiments/proofs, the same builders as the atlas's.
using logic::Formula;
using logic::Polynomial;
using proofs::area_property;
using proofs::cond_not_prop;
using proofs::det;
using proofs::det_of_blend;
using proofs::lemma_L1;
using proofs::lemma_L2;
using proofs::lemma_L2_area;
using proofs::lemma_L3;
using proofs::lemma_L4;
using proofs::lemma_L6_directions;
using proofs::norm_property;
using proofs::norm_squared_of_blend;
using proofs::PolyMat2;
using proofs::product;
using proofs::prop_not_cond;
using proofs::rotation;
using proofs::sentence;
using proofs::svd_norm_G;
using proofs::svd_norm_property;
using proofs::trace;
using proofs::transpose;
using proofs::var;

/// A proof's plan: what it is about, how it reads, and what it decides and checks.
struct ProofPlan {
  std::string scope;                        ///< the domain, in words
  std::string method;                       ///< encoding levels and lemmas
  std::vector<proofs::Sentence> sentences;  ///< in the order the method reads them
  /// Identities the method rests on: name → (lhs − rhs), which must be the zero polynomial.
  std::vector<std::pair<std::string, Polynomial>> identities;
  /// An external published theorem the method uses as a step (experiments/proofs/citations.hpp); empty: none.
  std::string cites{};
  /// Further formulations, each a complete proof: the literal one first.
  std::vector<proofs::FormulationPlan> formulations{};
  /// Formulations tried for the record: decided once under their own limits, or not expressible.
  std::vector<proofs::AttemptPlan> attempts{};
};

/// A plan carried out: the proof as claims.json records it, and each sentence's decision (for witnesses).
struct ProofRun {
  Proof proof;
  std::map<std::string, proofs::SentenceDecision> decisions;
  nlohmann::json identities;  ///< name → "zero polynomial"

  /// Every sentence decided, by one decider at least and with no other answering otherwise.
  bool decided() const { return proof.decided(); }
  /// The agreed result of the named sentence.
  std::string result(const std::string& name) const;
};

/// Checks the identities (throws std::logic_error naming one that fails), reads every sentence's answers
/// (files in ctx.proof_files(); `affinterp prove` gives each decider 300 s; throws when the deciders disagree),
/// assembles the proof and adds the further formulations and the attempts.
ProofRun run_proof(const ClaimContext& ctx, const ProofPlan& plan);

/// A point of the named non-empty sentence's set: the deciders' sample point (or, when they printed none, the
/// first of `simple_points` where `exact` holds), shrunk to small rationals while `exact` (the suite's own
/// evaluators on the quantifier-free statement) holds; `simple_points` are tried first. nullopt when the
/// sentence is not non-empty or no point is found.
std::optional<logic::Point> counterexample(const ProofRun& run, const std::string& name, const proofs::Predicate& exact,
                                           const std::vector<logic::Point>& simple_points = {});

/// A point as claims.json writes exact values: variable → "p/q".
nlohmann::json exact_point(const logic::Point& p);

/// Attaches the proof. A confirmed verdict whose sentences were decided takes the proof's strength
/// (proof_strength: proved, one decider, citing), and a non-empty sentence of any formulation then contradicts it
/// (throws std::runtime_error naming it: the check fails loudly); refuted and corrected verdicts keep an exact
/// counterexample as their strength, with the proof attached.
void attach_proof(Outcome& outcome, ProofRun run);

/// Throws std::runtime_error when the verdict the proof reaches (when it reaches one) differs from the
/// grid's: the check then fails loudly instead of reporting two lines of evidence that disagree.
void require_agreement(const Outcome& outcome, const std::optional<Verdict>& proved);

}  // namespace affinterp::claims::local
