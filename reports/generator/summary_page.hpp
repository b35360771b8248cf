#pragma once
// REPORT.md, the summary page: the claims table with a link to each claim's page, the verdicts' and the strength's
// legends, a paragraph per area of the papers, the global engine's speed and scale, how to reproduce, and the
// environment.
#include <nlohmann/json.hpp>

#include <string>

namespace affinterp::report {

std::string render_summary_page(const nlohmann::json& claims_document);

}  // namespace affinterp::report
