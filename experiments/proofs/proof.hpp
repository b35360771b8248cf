#pragma once
// A proof for all reals as claims.json records it (issue 10, item 3): every first-order sentence with what
// each decider said of it. The claims' Outcome carries one (experiments/claims/outcome.hpp).
#include <string>
#include <vector>

namespace affinterp::proofs {

/// One first-order sentence (or polynomial identity) of a proof, and what each decider said of it. Files are
/// relative to the report's folder (proofs/<id>/<name>.<ext>) and are written with the tool's output beside
/// them (<file>.out), so anyone can rerun a sentence with the tool alone.
struct ProofSentence {
  struct Run {
    std::string tool;    ///< "qepcad", "z3", "ginac", "exact-grid"
    std::string file;    ///< the input the tool read
    std::string result;  ///< "empty" / "non-empty" (sentences), "zero" / "non-zero" (identities), "unknown"
    double seconds = 0;  ///< wall time (a timing: varies run to run)
  };
  std::string name;       ///< e.g. "cond-not-prop": ∃ domain ∧ condition ∧ ¬property
  std::string meaning;    ///< one line: what the sentence says, in words
  std::string result;     ///< the agreed result; disagreeing deciders make the check fail to run
  std::vector<Run> runs;  ///< one per decider, two independent ones for a proof
  /// Empty for propositional reasons alone (structural.hpp): its emptiness is no evidence for the claim.
  bool structural = false;
};

/// A verdict decided for all reals (issue 10): the domain, the method (encoding level and the lemmas that
/// reduce the sentences) and every sentence with both deciders' results.
struct Proof {
  std::string scope;   ///< the domain, in words
  std::string method;  ///< encoding and lemmas
  /// The checkers that answered every sentence they ran on, e.g. {"qepcad", "z3"}: computed by make_proof.
  std::vector<std::string> checked_by;
  std::vector<ProofSentence> sentences;  ///< every sentence, in the order the method reads them
  /// An external published theorem the method uses as a step, with its full reference; empty: none.
  std::string cites{};

  /// Every sentence has an agreed result other than "unknown", given by at least two of its runs, and no run
  /// gave another answer.
  bool decided_by_two() const;
  /// Every sentence has an agreed result other than "unknown", and no run gave another answer.
  bool decided() const;
  /// Every sentence's agreed result is "empty".
  bool all_empty() const;
  /// Some sentence carries the claim's content: not structural (an identity never is).
  bool has_content() const;
};

}  // namespace affinterp::proofs
