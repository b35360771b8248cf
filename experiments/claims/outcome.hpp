#pragma once
// What a check returns: the verdict on one claim and the evidence behind it.
#include "experiments/claims/verdict.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace affinterp::claims {

/// How a verdict was reached. Everything here except `measurements` must be deterministic for a seed.
struct Evidence {
  std::string method;                                      ///< e.g. "exact rational computation", "grid sweep"
  std::uint64_t sample_size = 0;                           ///< cases examined (grid points, random draws, ...)
  std::optional<std::uint64_t> seed;                       ///< RNG seed of the sample, when random
  std::optional<double> tolerance;                         ///< numerical tolerance of the comparison, when inexact
  std::optional<double> worst_deviation;                   ///< largest deviation seen from the claimed statement
  nlohmann::json details = nlohmann::json::object();       ///< further deterministic numbers
  nlohmann::json measurements = nlohmann::json::object();  ///< timings and speeds: vary run to run
};

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
};

/// A verdict decided for all reals (issue 10): the domain, the method (encoding level and the lemmas that
/// reduce the sentences) and every sentence with both deciders' results.
struct Proof {
  std::string scope;                     ///< the domain, in words
  std::string method;                    ///< encoding and lemmas
  std::vector<std::string> checked_by;   ///< the independent deciders, e.g. {"qepcad", "z3"}
  std::vector<ProofSentence> sentences;  ///< every sentence, in the order the method reads them
};

struct Outcome {
  Verdict verdict = Verdict::pending;
  Strength strength = Strength::unstated;  ///< how strong the verdict is
  std::string summary;                     ///< one line: what was found
  Evidence evidence;
  std::optional<Proof> proof;  ///< the proof for all reals, when there is one (strength proved)
  /// Every input needed to re-verify independently: matrices as arrays of rows, exact values as
  /// "p/q" strings, parameters under the paper's own names (x, y, h, alpha, beta, A, v, t).
  nlohmann::json counterexample = nullptr;
  std::optional<std::string> correction;  ///< the corrected statement, for `corrected`
  std::vector<std::string> figures;       ///< paths relative to the report's folder
};

}  // namespace affinterp::claims
