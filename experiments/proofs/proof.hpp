#pragma once
// A proof for all reals as claims.json records it: every first-order sentence with what
// each decider said of it. The claims' Outcome carries one (experiments/claims/outcome.hpp).
#include <optional>
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
    /// CPU time and peak memory of a decider's run, from its transcript; absent in transcripts written before
    /// they were recorded.
    std::optional<double> cpu_seconds{};
    std::optional<long> max_rss_kb{};
    std::string reason{};  ///< why the run answered "unknown", one line
  };
  std::string name;       ///< e.g. "cond-not-prop": ∃ domain ∧ condition ∧ ¬property
  std::string meaning;    ///< one line: what the sentence says, in words
  std::string result;     ///< the agreed result; disagreeing deciders make the check fail to run
  std::vector<Run> runs;  ///< one per decider, two independent ones for a proof
  /// Empty for propositional reasons alone (structural.hpp): its emptiness is no evidence for the claim.
  bool structural = false;
};

/// A formulation tried for the record that no decider answered: what was tried, with which tool,
/// how much CPU time and memory it took and how it ended; or a formulation no decider can be given (tool empty),
/// with the reason.
struct Attempt {
  std::string formulation;  ///< the formulation in words (encoding level, variables)
  std::string sentence;     ///< its file stem under the claim's folder; empty: none written
  std::string tool;         ///< "qepcad", "z3", "cvc5"; empty: not expressible for a decider
  std::string file;         ///< the input the tool read
  std::optional<double> cpu_seconds{};
  std::optional<long> max_rss_kb{};
  std::string outcome;  ///< "empty" / "non-empty" / the reason there was no answer
};

/// A verdict decided for all reals: the domain, the method (encoding level and the lemmas that
/// reduce the sentences) and every sentence with both deciders' results.
struct Proof {
  std::string scope;   ///< the domain, in words
  std::string method;  ///< encoding and lemmas
  /// The checkers that answered every sentence they ran on, e.g. {"qepcad", "z3"}: computed by make_proof.
  std::vector<std::string> checked_by;
  std::vector<ProofSentence> sentences;  ///< every sentence, in the order the method reads them
  /// An external published theorem the method uses as a step, with its full reference; empty: none.
  std::string cites{};
  /// Further complete formulations of the same claim, each a proof by itself: the literal one, straight
  /// from the paper's definition, whose method names the few lemmas it still uses, each a sentence or identity of
  /// it. The claim's strength is the best of this proof's and theirs (claims/proof_strength.hpp).
  std::vector<Proof> formulations{};
  /// What was tried and not answered: the formulations' unanswered runs and the attempts kept for the record.
  std::vector<Attempt> attempts{};

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
