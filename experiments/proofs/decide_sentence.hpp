#pragma once
// Deciding one first-order sentence with two independent deciders, QEPCAD B (cylindrical algebraic
// decomposition) and Z3 (nlsat), run concurrently under limits; the input files and the tools' outputs are
// written side by side so that anyone can rerun the sentence with the tool alone.
#include "experiments/proofs/decider_output.hpp"
#include "experiments/proofs/proof.hpp"
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
};

struct DeciderLimits {
  /// Each decider's limit in CPU seconds, so that whether a sentence is decided does not depend on the load.
  double seconds = 60;
  /// The wall-clock limit, as a multiple of `seconds`: a backstop for proofs; `decide` uses 1, so that its
  /// answer comes within the time it states.
  double wall_factor = 4;
  std::size_t address_space_bytes = std::size_t{1536} << 20;  ///< RLIMIT_AS of each decider
  long qepcad_cells = 100'000'000;                            ///< QEPCAD's +N (garbage-collected space)
  long z3_megabytes = 1024;                                   ///< z3 -memory:
};

/// Where a sentence's files go.
struct SentenceFiles {
  std::filesystem::path dir;  ///< written here; empty: a temporary folder, removed afterwards
  std::string reference;      ///< how claims.json names `dir`, e.g. "proofs/atlas.linear.area"
};

struct DeciderRun {
  std::string tool;  ///< "qepcad", "z3"
  std::string file;  ///< reference/name.ext
  DeciderAnswer answer;
  double seconds = 0;
};

struct SentenceDecision {
  std::string name;
  std::vector<DeciderRun> runs;           ///< qepcad, then z3
  SetResult result = SetResult::unknown;  ///< what the deciders that finished agree on
  bool disagreement = false;              ///< one said empty, the other non-empty
  /// A point of the set from a decider's output, exact ones preferred (Z3 omits unconstrained variables;
  /// they are 0 here).
  std::optional<Witness> witness;
  /// The unknown deciders' reasons, "qepcad: …; z3: …".
  std::string reasons() const;
};

/// Writes <dir>/<name>.qepcad and <name>.smt2, runs both deciders at once, writes their outputs (timings
/// removed) to <name>.qepcad.out and <name>.smt2.out, and reads their answers.
SentenceDecision decide_sentence(const Sentence& sentence, const SentenceFiles& files, const DeciderLimits& limits);

/// The record of a decided sentence for claims.json; throws std::runtime_error when the deciders disagree.
ProofSentence to_proof_sentence(const Sentence& sentence, const SentenceDecision& decision);

/// decide_sentence, then to_proof_sentence.
ProofSentence prove_sentence(const Sentence& sentence, const SentenceFiles& files, const DeciderLimits& limits = {});

/// A proof of the sentences: checked_by names the deciders that decided every sentence.
Proof make_proof(std::string scope, std::string method, std::vector<ProofSentence> sentences);

}  // namespace affinterp::proofs
