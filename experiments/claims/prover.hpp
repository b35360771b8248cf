#pragma once
// `affinterp prove`: proofs as data. The claims' checks read their deciders' answers from stored
// transcripts and never start a decider; this collects the decider runs their proofs need (the proof plan) and
// decides the ones whose stored transcript is missing or stale, into the store the checks read.
#include "experiments/claims/registry.hpp"
#include "experiments/proofs/proof_plan.hpp"

#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

namespace affinterp::claims {

struct ProveOptions {
  std::vector<std::string> ids;  ///< the claims whose proofs to decide; empty: every claim
  bool all = false;              ///< re-decide every run, not only the missing or stale ones
  unsigned jobs = 1;             ///< deciders at once (one core each)
  std::filesystem::path answer_dir = RunSettings::committed_answers();
};

struct ProveSummary {
  std::size_t planned = 0;                 ///< decider runs in the plan
  std::vector<proofs::ProvedRun> decided;  ///< the runs decided now, with the stored answer before
};

/// Collects the proof plan of the claims (their checks at quick size, answers read from the store, no
/// figures), decides what is missing or stale (everything with `all`) into options.answer_dir, and collects
/// again while a new answer brings new runs (a sentence built from an earlier answer). Unknown IDs throw
/// std::invalid_argument before anything runs.
ProveSummary prove_claims(const ClaimRegistry& registry, const ProveOptions& options, std::ostream& progress);

}  // namespace affinterp::claims
