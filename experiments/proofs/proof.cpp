#include "experiments/proofs/proof.hpp"

#include <algorithm>

namespace affinterp::proofs {

bool Proof::decided_by_two() const {
  if (checked_by.size() < 2 || sentences.empty()) return false;
  for (const ProofSentence& s : sentences)
    for (const std::string& tool : checked_by)
      if (s.result == "unknown" || std::none_of(s.runs.begin(), s.runs.end(), [&](const ProofSentence::Run& r) {
            return r.tool == tool && r.result == s.result;
          }))
        return false;
  return true;
}

bool Proof::all_empty() const {
  return std::all_of(sentences.begin(), sentences.end(), [](const ProofSentence& s) { return s.result == "empty"; });
}

}  // namespace affinterp::proofs
