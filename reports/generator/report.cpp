#include "reports/generator/report.hpp"

#include "experiments/support/staged_output.hpp"
#include "reports/generator/claim_page.hpp"
#include "reports/generator/summary_page.hpp"

#include <fstream>
#include <stdexcept>

namespace affinterp::report {
namespace {

namespace fs = std::filesystem;

void write_text(const fs::path& file, const std::string& text) {
  std::ofstream out(file);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + file.string());
}

/// The pages in `claims_folder` of claims that `pages` no longer has.
void remove_stale_pages(const fs::path& claims_folder, const Pages& pages) {
  std::error_code absent;
  for (const auto& entry : fs::directory_iterator(claims_folder, absent))
    if (entry.path().extension() == ".md" && !pages.claims.contains(entry.path().stem().string()))
      fs::remove(entry.path());
}

}  // namespace

Pages render(const nlohmann::json& doc) {
  Pages pages{render_summary_page(doc), {}};
  for (const auto& claim : doc.at("claims")) pages.claims[claim.at("id")] = render_claim_page(claim);
  return pages;
}

void write_pages(const Pages& pages, const fs::path& folder) {
  StagedOutput staged(folder / "claims");
  for (const auto& [id, text] : pages.claims) write_text(staged.staging() / (id + ".md"), text);
  remove_stale_pages(folder / "claims", pages);
  staged.commit();
  const fs::path summary = folder / "REPORT.md", temporary = folder / "REPORT.md.tmp";
  write_text(temporary, pages.summary);
  fs::rename(temporary, summary);
}

}  // namespace affinterp::report
