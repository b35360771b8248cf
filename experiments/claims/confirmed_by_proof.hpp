#pragma once
// A claim its exact comparison confirmed, weighed against its proof: proved for all reals when every
// part of the proof is decided twice as stated, inconclusive when a part contradicts the comparison.
#include "experiments/claims/outcome.hpp"
#include "experiments/claims/proof_strength.hpp"
#include "experiments/proofs/identity.hpp"

#include <string_view>

namespace affinterp::claims {

/// `out` is confirmed and carries its proof; `scope` says for what the proof holds, e.g. "every origin".
inline void weigh_confirmation_against_proof(Outcome& out, std::string_view scope) {
  if (proofs::proves(*out.proof)) {
    out.strength = *proof_strength(*out.proof);
    std::string checkers;
    for (const std::string& c : out.proof->checked_by) checkers += (checkers.empty() ? "" : ", ") + c;
    out.summary += "; proved for " + std::string(scope) + " (identities and sentences; checked by " + checkers + ")";
  }
  if (proofs::contradicted(*out.proof)) {
    out.verdict = Verdict::inconclusive;
    out.summary = "a part of the proof fails although the exact comparison agreed: " + out.summary;
  }
}

}  // namespace affinterp::claims
