#include "experiments/proofs/proof.hpp"

#include <algorithm>

namespace affinterp::proofs {

namespace {

/// Every sentence has an agreed result other than "unknown", given by at least `checkers` of its runs, and no
/// run gave another answer.
bool answered_by(const std::vector<ProofSentence>& sentences, int checkers) {
  if (sentences.empty()) return false;
  for (const ProofSentence& s : sentences) {
    if (s.result == "unknown") return false;
    int agreeing = 0;
    for (const ProofSentence::Run& r : s.runs) {
      if (r.result == s.result)
        ++agreeing;
      else if (r.result != "unknown")
        return false;
    }
    if (agreeing < checkers) return false;
  }
  return true;
}

}  // namespace

bool Proof::decided_by_two() const { return answered_by(sentences, 2); }

bool Proof::decided() const { return answered_by(sentences, 1); }

bool Proof::has_content() const {
  return std::any_of(sentences.begin(), sentences.end(), [](const ProofSentence& s) { return !s.structural; });
}

bool Proof::all_empty() const {
  return std::all_of(sentences.begin(), sentences.end(), [](const ProofSentence& s) { return s.result == "empty"; });
}

}  // namespace affinterp::proofs
