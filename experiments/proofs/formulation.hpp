#pragma once
// Two formulations of a claim: besides the lemma chain, a formulation straight from the paper's
// definition (Def 2.2.1: for all 0 <= s <= t <= 1; Def 2.2.2: for all t in [0, 1] and all unit v) with as few
// lemmas as a decider allows, each lemma it does use a sentence of its own. A formulation is a complete proof by
// itself (Proof::formulations); what was tried and not answered is kept for the record (Proof::attempts): the
// formulations' unanswered runs, the sentences tried once under their own limits, and the formulations no decider
// can be given (a transcendental homotopy), with the reason.
#include "experiments/proofs/decide_sentence.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace affinterp::proofs {

/// Why Def 2.2.2 as written is no sentence for a decider when a rotation on the right turns with t (the SVD
/// homotopy R_{tα}((1−t)I + tD)R_{tβ}, Lemma L9).
inline constexpr std::string_view not_first_order_rotation =
    "not a first-order sentence over the reals: the entries cos(t beta), sin(t beta) of R_{t beta} are not "
    "semi-algebraic functions of t (beta != 0), and QEPCAD B, Z3 and cvc5 decide polynomial sentences only; "
    "Lemma L9 (by hand) reduces Def 2.2.2 to G(t) >= 0 on [0, 1]";

/// Why Defs 2.2.1 and 2.2.2 as written are no sentences for a decider for the exp-log homotopy R_{tθ}S^t (Lemma L10).
inline constexpr std::string_view not_first_order_exponential =
    "not a first-order sentence over the reals: S^t = exp(t log S) and det S^t = (det S)^t are exponential in t, "
    "and QEPCAD B, Z3 and cvc5 decide polynomial sentences only (the reals with exp are not known to be "
    "decidable); Lemma L10 (by hand, citing the exponential's monotonicity) leaves algebraic residues";

/// A formulation as the claim plans it: the lemmas its method names and its sentences.
struct FormulationPlan {
  std::string method;  ///< the encoding level and the lemmas it uses (reports/proofs/LEMMAS.md)
  std::vector<Sentence> sentences;
};

/// A formulation tried for the record: its sentences, decided once under `limits` (limits.attempt is set), or,
/// when `sentences` is empty, why no decider can be given it (`not_expressible`).
struct AttemptPlan {
  std::string formulation;  ///< in words: the level, the variables, the QEPCAD options
  std::vector<Sentence> sentences;
  DeciderLimits limits{.seconds = 300, .address_space_bytes = std::size_t{4} << 30, .attempt = true};
  std::string not_expressible{};
};

/// Decides the formulation's sentences (answers read from `files`, as decide_sentence) into a proof of `scope`;
/// throws std::runtime_error when two deciders disagree.
Proof decide_formulation(const std::string& scope, const FormulationPlan& plan, const SentenceFiles& files,
                         const DeciderLimits& limits);

/// Every run of the attempt, answered or not, as claims.json records it; the reason for a formulation without
/// sentences.
std::vector<Attempt> decide_attempt(const AttemptPlan& plan, const SentenceFiles& files);

/// The runs of `proof`'s sentences that answered nothing, as attempts at the formulation `words`.
std::vector<Attempt> unanswered_runs(const Proof& proof, const std::string& words);

/// Adds the formulations and the attempts to `proof`: each formulation decided, its unanswered runs (a run two
/// formulations share, once) and the attempts recorded.
void add_formulations(Proof& proof, const std::vector<FormulationPlan>& formulations,
                      const std::vector<AttemptPlan>& attempts, const SentenceFiles& files,
                      const DeciderLimits& limits);

}  // namespace affinterp::proofs
