#pragma once
// The verdicts a claim can receive (see reports/REPORT.md, "Verdicts").
#include <optional>
#include <string>
#include <string_view>

namespace affinterp::claims {

enum class Verdict {
  pending,         ///< no check implemented yet
  confirmed,       ///< holds on everything tried (exact proof-by-computation, or a stated sweep)
  refuted,         ///< fails; a re-verifiable counterexample is attached
  corrected,       ///< fails as printed, holds after the stated correction
  reproduced,      ///< a measured figure (speed-up, error level) matches the paper's
  not_reproduced,  ///< a measured figure does not match the paper's
  inconclusive,    ///< could not be decided; the summary says why and what would decide it
};

std::string_view to_string(Verdict v);
std::optional<Verdict> parse_verdict(std::string_view text);

}  // namespace affinterp::claims
