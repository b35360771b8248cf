#include "reports/generator/claim_page.hpp"

#include "reports/generator/claim_lines.hpp"
#include "reports/generator/markdown.hpp"
#include "reports/generator/proof_section.hpp"

#include <sstream>

namespace affinterp::report {
namespace {

using nlohmann::json;

/// The page lives in claims/: the report's folder, where claims.json's paths start, is one up.
const std::string up = "../";

/// A claim's tables (evidence.details.tables: [{"title", "columns": [...], "rows": [[cells]], "replaces": [keys of
/// details the table stands for in the report]}]) as Markdown.
void write_tables(std::ostringstream& md, const json& tables) {
  for (const auto& table : tables) {
    md << "**" << table.value("title", "") << "**\n\n|";
    for (const auto& column : table["columns"]) md << " " << cell(column.get<std::string>()) << " |";
    md << "\n|";
    for (std::size_t i = 0; i < table["columns"].size(); ++i) md << "---|";
    md << "\n";
    for (const auto& row : table["rows"]) {
      md << "|";
      for (const auto& entry : row)
        md << " " << cell(entry.is_string() ? entry.get<std::string>() : entry.dump()) << " |";
      md << "\n";
    }
    md << "\n";
  }
}

/// The evidence: its one line, its tables, the details no table stands for, and the run's measurements.
void write_evidence(std::ostringstream& md, const json& e) {
  md << "## Evidence\n\n" << one_line_evidence(e) << ".\n\n";
  json details = e["details"];
  if (details.is_object() && details.contains("tables")) {
    write_tables(md, details["tables"]);
    // A table stands for the details it names under "replaces" (claims.json keeps them in full).
    for (const auto& table : details["tables"])
      for (const auto& key : table.value("replaces", json::array())) details.erase(key.get<std::string>());
    details.erase("tables");
  }
  if (!details.empty()) md << "```json\n" << details.dump(2) << "\n```\n\n";
  if (!e["measurements"].empty())
    md << "Measurements (vary run to run):\n\n```json\n" << e["measurements"].dump(2) << "\n```\n\n";
}

/// The counterexample, the correction and the condition, where the claim has them.
void write_correction(std::ostringstream& md, const json& c) {
  if (!c["counterexample"].is_null())
    md << "## Counterexample\n\nExact values as \"p/q\":\n\n```json\n" << c["counterexample"].dump(2) << "\n```\n\n";
  if (!c["correction"].is_null()) md << "## Correction\n\n" << c["correction"].get<std::string>() << "\n\n";
  if (c.contains("condition") && c["condition"].is_string())
    md << "**Condition** (in the `affinterp decide` grammar): `" << c["condition"].get<std::string>() << "`\n\n";
}

/// The figures: each PNG shown, each interactive viewer linked.
void write_figures(std::ostringstream& md, const json& c) {
  if (c["figures"].empty()) return;
  md << "## Figures\n\n";
  for (const auto& f : c["figures"]) {
    const std::string path = f.get<std::string>();
    if (path.ends_with(".png")) md << "![" << c["id"].get<std::string>() << "](" << up << path << ")\n\n";
  }
  for (const auto& f : c["figures"])
    if (is_viewer(f.get<std::string>()))
      md << "[Interactive viewer](" << up << f.get<std::string>()
         << "): scrub through the frames, colour the triangles by area ratio, distortion or flips, see the "
            "energy over time (open in a browser; it works offline).\n\n";
}

}  // namespace

std::string render_claim_page(const json& c) {
  std::ostringstream md;
  md << "# `" << c["id"].get<std::string>() << "`: " << c["verdict"].get<std::string>() << "\n\n"
     << "[Report](" << up << "REPORT.md) · [all claims](" << up << "REPORT.md#claims) · " << c.value("group", "")
     << "\n\n*" << c["where"].get<std::string>() << ".* " << c["statement"].get<std::string>() << "\n\n"
     << "**Verdict:** " << c["verdict"].get<std::string>() << " ([what the verdicts mean](" << up
     << "REPORT.md#verdicts)); **strength:** " << strength_words(c) << " ([how strong](" << up
     << "REPORT.md#strength)).\n\n";
  if (!c["summary"].get<std::string>().empty()) md << "**Finding.** " << c["summary"].get<std::string>() << "\n\n";
  write_evidence(md, c["evidence"]);
  write_correction(md, c);
  if (c.contains("proof") && c["proof"].is_object()) write_proof(md, c["proof"], up);
  write_figures(md, c);
  return md.str();
}

}  // namespace affinterp::report
