#pragma once
// A proof plan: every decider run the claims' proofs need, each with its input text and where its
// transcript is stored. The checks record it while reading their answers (SentenceFiles::plan); `affinterp
// prove` decides the runs whose stored transcript is missing or stale (prove_plan).
#include "experiments/proofs/decider.hpp"

#include <filesystem>
#include <mutex>
#include <string>
#include <vector>

namespace affinterp::proofs {

struct PlannedRun {
  std::filesystem::path store;  ///< the folder of the stored transcripts, reports/proofs/<claim id>
  std::string sentence;         ///< the sentence's file stem, e.g. "cond-not-prop.E"
  Decider decider;
  std::string input_text;  ///< the text of <sentence><decider.input_extension>
  DeciderLimits limits;

  std::filesystem::path input_file() const { return store / (sentence + std::string(decider.input_extension)); }
  std::filesystem::path transcript_file() const { return store / transcript_file_name(sentence, decider.tool); }
};

/// The runs recorded so far; checks may record from several threads.
class ProofPlan {
 public:
  void add(PlannedRun run);
  std::vector<PlannedRun> runs() const;

 private:
  mutable std::mutex mutex_;
  std::vector<PlannedRun> runs_;
};

/// Why a planned run needs deciding: "" when its stored transcript answers this input with the installed
/// version of the decider; else "missing", "input changed" or "decider version <old> → <new>".
std::string staleness(const PlannedRun& run);

struct ProvedRun {
  PlannedRun run;
  std::string before;  ///< the stored answer before ("empty", "non-empty", "unknown"), or "missing"
  std::string after;   ///< the answer now
};

/// Decides `runs` (at most `jobs` deciders at once), writing each input file and transcript into its store
/// folder; `progress` gets a line per run. A decider that is not installed stops it (std::runtime_error)
/// before anything is written.
std::vector<ProvedRun> prove_plan(const std::vector<PlannedRun>& runs, unsigned jobs, std::ostream& progress);

}  // namespace affinterp::proofs
