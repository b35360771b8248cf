#pragma once
// Deciding one first-order sentence with two independent deciders, QEPCAD B (cylindrical algebraic
// decomposition) and Z3 (nlsat). The input files and the deciders' transcripts are written side by side so
// that anyone can rerun the sentence with the tool alone. A check reads the answers from stored transcripts
// (proofs as data) and never starts a decider; `affinterp decide` runs them.
#include "experiments/proofs/decider.hpp"
#include "experiments/proofs/proof.hpp"
#include "experiments/proofs/proof_plan.hpp"
#include "theory/logic/formula.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace affinterp::proofs {

/// A sentence and how to present it to the deciders.
struct Sentence {
  std::string name;        ///< file stem, e.g. "cond-not-prop.E"
  std::string meaning;     ///< one line, in words
  logic::Formula formula;  ///< closed: every variable quantified
  /// QEPCAD's preferred variable order inside each quantifier block (it eliminates the last one first).
  std::vector<std::string> qepcad_order;
  /// QEPCAD commands before its default ones, e.g. {"proj-operator (h,h,h)"} (logic::QepcadInput::setup).
  std::vector<std::string> qepcad_setup{};
};

/// QEPCAD's command selecting Hong's projection at every level of `sentence` (complete, larger than McCallum's, which
/// fails on some sentences with "Error! Delineating polynomial should be added …"), for Sentence::qepcad_setup.
std::vector<std::string> hong_projection(const logic::Formula& sentence);

/// Where a sentence's files go, and where its answers come from.
struct SentenceFiles {
  std::filesystem::path dir;  ///< written here; empty: a temporary folder, removed afterwards
  std::string reference;      ///< how claims.json names `dir`, e.g. "proofs/atlas.linear.area"
  /// The stored transcripts to read the answers from (reports/proofs/<claim id>); no decider runs then,
  /// and a sentence without a transcript for its text is unknown. Empty: run the deciders now.
  std::filesystem::path answers{};
  /// When set, every decider run the sentence needs is recorded here, answered or not (`affinterp prove`).
  ProofPlan* plan = nullptr;
};

struct DeciderRun {
  std::string tool;  ///< "qepcad", "z3"
  std::string file;  ///< reference/name.ext
  DeciderAnswer answer;
  double seconds = 0;
  std::optional<double> cpu_seconds{};  ///< from the transcript, when it records them
  std::optional<long> max_rss_kb{};
};

struct SentenceDecision {
  std::string name;
  std::vector<DeciderRun> runs;           ///< in the order of sentence_deciders()
  SetResult result = SetResult::unknown;  ///< what the deciders that finished agree on
  bool disagreement = false;              ///< one said empty, another non-empty
  bool structural = false;                ///< empty for propositional reasons alone (structural.hpp)
  /// A point of the set from a decider's output, exact ones preferred (Z3 omits unconstrained variables;
  /// they are 0 here).
  std::optional<Witness> witness;
  /// The unknown deciders' reasons, "qepcad: …; z3: …".
  std::string reasons() const;
  /// What each decider answered, "name (qepcad empty, z3 empty, cvc5 unknown)".
  std::string answers() const;
};

/// Writes <dir>/<name>.qepcad and <name>.smt2 and the deciders' transcripts <name>.<tool>.out beside them,
/// read from files.answers (or, when that is empty, from running both deciders at once), and reads their
/// answers.
SentenceDecision decide_sentence(const Sentence& sentence, const SentenceFiles& files, const DeciderLimits& limits);

/// The record of a decided sentence for claims.json; throws std::runtime_error when the deciders disagree.
ProofSentence to_proof_sentence(const Sentence& sentence, const SentenceDecision& decision);

/// decide_sentence, then to_proof_sentence.
ProofSentence prove_sentence(const Sentence& sentence, const SentenceFiles& files, const DeciderLimits& limits = {});

/// A proof of the sentences: checked_by names the checkers that answered every sentence they ran on, computed
/// from the runs (never written by hand).
Proof make_proof(std::string scope, std::string method, std::vector<ProofSentence> sentences);

}  // namespace affinterp::proofs
