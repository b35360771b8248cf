// Every relative link of the report resolves: on REPORT.md and each claim's page (reports/claims/*.md), a link
// [text](path) or [text](path#anchor) must name a file that exists and, with an anchor, a heading of that page
// (GitHub's anchors: lower case, spaces to hyphens, other ASCII punctuation dropped, "-1", "-2" after repeats).
// Checked on the committed report and on one generated afresh from the committed claims.json into a temporary
// folder; the checker itself is shown to catch a missing file and a missing anchor, and the generator to remove
// the page of a claim that no longer exists.
#include "reports/generator/report.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace affinterp::report::links_test {
namespace {

namespace fs = std::filesystem;

const fs::path committed = AFFINTERP_SOURCE_DIR "/reports";

std::vector<std::string> lines_of(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

/// The anchor GitHub gives a heading's text.
std::string github_anchor(const std::string& text) {
  std::string anchor;
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (u >= 0x80 || std::isalnum(u) || c == '_' || c == '-')
      anchor += static_cast<char>(u < 0x80 ? std::tolower(u) : u);
    else if (c == ' ')
      anchor += '-';
  }
  return anchor;
}

/// The anchors of a page's headings ("# ..." to "###### ..." outside fenced code), repeats numbered.
std::set<std::string> anchors_of(const fs::path& page) {
  std::set<std::string> anchors;
  std::map<std::string, int> seen;
  bool fenced = false;
  for (const std::string& line : lines_of(page)) {
    if (line.starts_with("```")) fenced = !fenced;
    const std::size_t hashes = line.find_first_not_of('#');
    if (fenced || hashes == 0 || hashes > 6 || hashes == std::string::npos || line[hashes] != ' ') continue;
    const std::string anchor = github_anchor(line.substr(hashes + 1));
    const int n = seen[anchor]++;
    anchors.insert(n == 0 ? anchor : anchor + "-" + std::to_string(n));
  }
  return anchors;
}

/// The targets of a page's links outside fenced code: what stands between "](" and the next ")".
std::vector<std::string> link_targets(const fs::path& page) {
  std::vector<std::string> targets;
  bool fenced = false;
  for (const std::string& line : lines_of(page)) {
    if (line.starts_with("```")) fenced = !fenced;
    if (fenced) continue;
    for (std::size_t at = line.find("]("); at != std::string::npos; at = line.find("](", at + 2)) {
      const std::size_t end = line.find(')', at + 2);
      if (end != std::string::npos) targets.push_back(line.substr(at + 2, end - at - 2));
    }
  }
  return targets;
}

struct Checked {
  std::size_t links = 0;
  std::vector<std::string> broken;  ///< "page: target (why)"
};

/// Checks every relative link of `page` (web addresses are not followed).
void check_page(const fs::path& page, Checked& checked) {
  for (const std::string& target : link_targets(page)) {
    if (target.find("://") != std::string::npos || target.starts_with("mailto:")) continue;
    ++checked.links;
    const std::size_t hash = target.find('#');
    const std::string path = target.substr(0, hash), anchor = hash == std::string::npos ? "" : target.substr(hash + 1);
    const fs::path file = path.empty() ? page : page.parent_path() / path;
    const std::string where = page.filename().string() + ": " + target;
    if (!fs::exists(file))
      checked.broken.push_back(where + " (no such file)");
    else if (!anchor.empty() && !anchors_of(file).contains(anchor))
      checked.broken.push_back(where + " (no such heading)");
  }
}

/// REPORT.md and every page of claims/ in `folder`.
Checked check_report(const fs::path& folder) {
  Checked checked;
  check_page(folder / "REPORT.md", checked);
  for (const auto& entry : fs::directory_iterator(folder / "claims"))
    if (entry.path().extension() == ".md") check_page(entry.path(), checked);
  return checked;
}

nlohmann::json committed_document() {
  std::ifstream in(committed / "claims.json");
  return nlohmann::json::parse(in);
}

/// A fresh temporary folder of the running test's own.
fs::path scratch() {
  const fs::path folder = fs::temp_directory_path() / ("affinterp_links_" + std::to_string(::getpid()) + "_" +
                                                       ::testing::UnitTest::GetInstance()->current_test_info()->name());
  fs::remove_all(folder);
  fs::create_directories(folder);
  return folder;
}

TEST(ReportLinks, TheCommittedReportsLinksAllResolve) {
  const Checked checked = check_report(committed);
  EXPECT_TRUE(checked.broken.empty()) << ::testing::PrintToString(checked.broken);
  const std::size_t claims = committed_document()["claims"].size();
  EXPECT_GE(checked.links, 2 * claims) << "the table's link to each page, and each page's back to the summary";
  for (const auto& claim : committed_document()["claims"])
    EXPECT_TRUE(fs::exists(committed / "claims" / (claim["id"].get<std::string>() + ".md"))) << claim["id"];
}

TEST(ReportLinks, AReportGeneratedAfreshHasNoBrokenLink) {
  const fs::path folder = scratch();
  for (const char* beside : {"figures", "proofs", "bench", "claims.json"})  // what the pages link besides themselves
    fs::create_symlink(committed / beside, folder / beside);
  write_pages(render(committed_document()), folder);
  const Checked checked = check_report(folder);
  EXPECT_TRUE(checked.broken.empty()) << ::testing::PrintToString(checked.broken);
  EXPECT_GT(checked.links, 0u);
  fs::remove_all(folder);
}

TEST(ReportLinks, AMissingFileAndAMissingHeadingAreBroken) {
  const fs::path folder = scratch();
  fs::create_directories(folder / "claims");
  std::ofstream(folder / "REPORT.md") << "# Report\n\n## Strength\n\n[a](claims/a.md) [b](claims/b.md) "
                                         "[here](#strength) [there](#nowhere)\n";
  std::ofstream(folder / "claims" / "a.md") << "# `a`: confirmed\n\n[back](../REPORT.md#strength) "
                                               "[wrong](../REPORT.md#verdicts)\n```\n[code](not-a-link.md)\n```\n";
  const Checked checked = check_report(folder);
  EXPECT_EQ(checked.links, 6u);
  EXPECT_EQ(checked.broken,
            (std::vector<std::string>{"REPORT.md: claims/b.md (no such file)", "REPORT.md: #nowhere (no such heading)",
                                      "a.md: ../REPORT.md#verdicts (no such heading)"}));
  fs::remove_all(folder);
}

TEST(ReportLinks, ThePageOfAClaimNoLongerInTheDocumentIsRemoved) {
  const fs::path folder = scratch();
  nlohmann::json doc = committed_document();
  write_pages(render(doc), folder);
  const std::string gone = doc["claims"].back()["id"];
  ASSERT_TRUE(fs::exists(folder / "claims" / (gone + ".md")));
  doc["claims"].erase(doc["claims"].size() - 1);
  write_pages(render(doc), folder);
  EXPECT_FALSE(fs::exists(folder / "claims" / (gone + ".md")));
  EXPECT_TRUE(fs::exists(folder / "claims" / (doc["claims"][0]["id"].get<std::string>() + ".md")));
  EXPECT_EQ(lines_of(folder / "REPORT.md").front(), "# affinterp report");
  fs::remove_all(folder);
}

}  // namespace
}  // namespace affinterp::report::links_test
