#pragma once
// The report from claims.json alone: REPORT.md, a summary page (the claims table, the legends, a paragraph per
// area, the engine's measurements), and a page per claim, claims/<id>.md, with its evidence, tables and proofs.
#include <nlohmann/json.hpp>

#include <filesystem>
#include <map>
#include <string>

namespace affinterp::report {

struct Pages {
  std::string summary;                        ///< REPORT.md
  std::map<std::string, std::string> claims;  ///< claims/<id>.md, by claim ID
};

/// Every page of `claims_document`; throws nlohmann::json's exceptions (or std::runtime_error) on a malformed one.
Pages render(const nlohmann::json& claims_document);

/// Writes `pages` into `folder`: claims/ replaced whole (staged beside it, then the pages of claims no longer in
/// `pages` removed and the new ones moved in), then REPORT.md (written beside and renamed). A failure before the
/// move leaves the earlier pages intact.
void write_pages(const Pages& pages, const std::filesystem::path& folder);

}  // namespace affinterp::report
