#pragma once
// One claim's page, claims/<id>.md: its statement, verdict and strength, the finding, the evidence with its
// tables, the counterexample or correction, the proof for all reals with what was tried, and the figures.
#include <nlohmann/json.hpp>

#include <string>

namespace affinterp::report {

/// The page of `claim` (an entry of claims.json's "claims"), linking back to the summary, REPORT.md.
std::string render_claim_page(const nlohmann::json& claim);

}  // namespace affinterp::report
