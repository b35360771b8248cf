#pragma once
// What a check returns: the verdict on one claim and the evidence behind it.
#include "experiments/claims/verdict.hpp"
#include "experiments/proofs/proof.hpp"

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

/// A proof for all reals and its sentences: experiments/proofs/proof.hpp.
using proofs::Proof;
using proofs::ProofSentence;

/// How many of a proof's empty sentences Coq's kernel checked through a certificate, of those tried.
struct SentenceCertificates {
  int certified = 0, tried = 0;
};

struct Outcome {
  Verdict verdict = Verdict::pending;
  Strength strength = Strength::unstated;  ///< how strong the verdict is
  std::string summary;                     ///< one line: what was found
  Evidence evidence;
  std::optional<Proof> proof;  ///< the proof for all reals, when there is one (strength proved)
  /// The steps of a proved claim taken by hand, each a lemma of reports/proofs/LEMMAS.md by its ID: the check
  /// names those outside its proof's methods, kernel_checks.hpp adds the named lemmas Coq has not checked.
  std::vector<std::string> hand_steps;
  /// "<file>: <theorem>" of reports/proofs/coq/ when the claim's statement is a theorem Coq's kernel checked.
  std::optional<std::string> kernel_checked;
  SentenceCertificates certificates;  ///< of its proof's empty sentences, from reports/proofs/coq/MANIFEST.json
  /// Every input needed to re-verify independently: matrices as arrays of rows, exact values as
  /// "p/q" strings, parameters under the paper's own names (x, y, h, alpha, beta, A, v, t).
  nlohmann::json counterexample = nullptr;
  std::optional<std::string> correction;  ///< the corrected statement, for `corrected`
  /// The exact region a goodness-atlas claim states, in the `affinterp decide` grammar.
  std::optional<std::string> condition;
  std::vector<std::string> figures;  ///< paths relative to the report's folder
};

}  // namespace affinterp::claims
