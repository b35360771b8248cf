#pragma once
// REPORT.md from claims.json alone: the claims table first, a section per claim with its evidence,
// counterexample and figures, then how to reproduce and the environment.
#include <nlohmann/json.hpp>

#include <string>

namespace affinterp::report {

std::string render_markdown(const nlohmann::json& claims_document);

}  // namespace affinterp::report
