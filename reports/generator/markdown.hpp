#pragma once
// Markdown pieces every page of the report uses: table cells, numbers with a fixed number of digits, intervals,
// speed verdicts as cells, and links to a claim's page and to headings.
#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace affinterp::report {

/// A table cell: no bare '|', no line break.
std::string cell(std::string text);

/// A number as written by the stream's default (null: empty).
std::string number(const nlohmann::json& value);

/// `value` with `digits` decimals; "—" when it was not measured.
std::string fixed(const std::optional<double>& value, int digits);
std::string fixed(double value, int digits);

/// The anchor a heading's text gets (GitHub's rule: lower case, spaces to hyphens, other ASCII punctuation
/// dropped), so that a link can point at a heading of another page.
std::string heading_anchor(const std::string& heading);

/// The page of claim `id`, relative to the report's folder: claims/<id>.md.
std::string claim_page_path(const std::string& id);

}  // namespace affinterp::report
