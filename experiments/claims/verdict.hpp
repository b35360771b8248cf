#pragma once
// The verdicts a claim can receive (see reports/REPORT.md, "Verdicts").
#include <optional>
#include <string>
#include <string_view>

namespace affinterp::claims {

enum class Verdict {
  pending,            ///< no check implemented yet
  confirmed,          ///< holds on everything tried (exact proof-by-computation, or a stated sweep)
  refuted,            ///< fails; a re-verifiable counterexample is attached
  corrected,          ///< fails as printed, holds after the stated correction
  reproduced,         ///< a measured figure (speed-up, error level) matches the paper's
  not_reproduced,     ///< a measured figure does not match the paper's
  inconclusive,       ///< could not be decided; the summary says why and what would decide it
  machine_dependent,  ///< a measured figure reproduced on one recorded machine and not on another
};

std::string_view to_string(Verdict v);
std::optional<Verdict> parse_verdict(std::string_view text);

/// How strong a verdict is: every check states it, and the report shows it beside the verdict.
enum class Strength {
  unstated,               ///< the check has not said (the pinned-verdict test fails on it)
  proved_kernel_checked,  ///< as proved, and the claim's statement is a theorem checked by Coq's kernel
                          ///< (reports/proofs/coq/MANIFEST.json's "claims": every lemma and step in Coq)
  proved,                 ///< decided for all reals: every sentence of the proof (Outcome::proof) answered by two
                          ///< independent deciders, every identity by two independent checkers, none with an error,
                          ///< and every lemma it names checked by Coq's kernel: no step by hand
  proved_hand_steps,      ///< as proved, but some lemma it names is proved by hand only (Outcome::hand_steps)
  proved_one_decider,     ///< as proved, but some sentence answered by one decider only (the proof names it)
  proved_citing,          ///< as proved, with an external published theorem as a step (the proof cites it)
  exact_counterexample,   ///< fails at an exact counterexample anyone can re-verify; a correction, if any, is
                          ///< checked on the stated grid or sample only
  grid,                   ///< checked on the stated grid only
  sample,                 ///< checked on the stated random sample only
  measured,               ///< a measured figure, with its spread over repeated runs
};

std::string_view to_string(Strength s);
std::optional<Strength> parse_strength(std::string_view text);

}  // namespace affinterp::claims
