// The report generator renders every claim of a claims.json document.
#include "reports/generator/report.hpp"

#include <gtest/gtest.h>

TEST(Report, TableFirstThenSectionsThenEnvironment) {
  const nlohmann::json claim = {{"id", "kaji.polar.det"},
                                {"group", "Local"},
                                {"where", "Kaji §3"},
                                {"statement", "a | b"},
                                {"verdict", "refuted"},
                                {"summary", "found one"},
                                {"evidence",
                                 {{"method", "exact"},
                                  {"sample_size", 3},
                                  {"seed", 1},
                                  {"tolerance", nullptr},
                                  {"worst_deviation", nullptr},
                                  {"details", nlohmann::json::object()},
                                  {"measurements", nlohmann::json::object()}}},
                                {"counterexample", {{"x", "1/2"}}},
                                {"correction", nullptr},
                                {"figures", {"figures/p.png"}}};
  const nlohmann::json doc = {{"seed", 1},
                              {"size", "quick"},
                              {"generated_at", "now"},
                              {"environment", {{"cpu", "test cpu"}}},
                              {"claims", {claim}}};
  const std::string md = affinterp::report::render_markdown(doc);
  const auto table = md.find("| [`kaji.polar.det`]");
  const auto section = md.find("### `kaji.polar.det`: refuted");
  const auto environment = md.find("## Environment");
  ASSERT_NE(table, std::string::npos);
  ASSERT_NE(section, std::string::npos);
  ASSERT_NE(environment, std::string::npos);
  EXPECT_LT(table, section);
  EXPECT_LT(section, environment);
  EXPECT_NE(md.find("a \\| b"), std::string::npos);  // table cells escape '|'
  EXPECT_NE(md.find("\"x\": \"1/2\""), std::string::npos);
  EXPECT_NE(md.find("![kaji.polar.det](figures/p.png)"), std::string::npos);
  EXPECT_NE(md.find("test cpu"), std::string::npos);
}

TEST(Report, ClaimTablesAreRenderedAsMarkdownNotAsJson) {
  nlohmann::json details = {{"worst", 1e-15},
                            {"peers", {{"spread", {{"ours", 1e-16}, {"theirs", 2e-14}}}}},
                            {"tables",
                             {{{"title", "Peer table"},
                               {"columns", {"family", "ours", "theirs"}},
                               {"rows", {{"spread", "1.0e-16", "2.0e-14; **3 NaN/∞**"}}},
                               {"replaces", {"peers"}}}}}};
  const nlohmann::json claim = {{"id", "thesis.exp.accuracy"},
                                {"group", "Thesis ch. 3"},
                                {"where", "thesis §3.4"},
                                {"statement", "accurate"},
                                {"verdict", "corrected"},
                                {"summary", ""},
                                {"evidence",
                                 {{"method", "sweep"},
                                  {"sample_size", 3},
                                  {"seed", 1},
                                  {"tolerance", nullptr},
                                  {"worst_deviation", nullptr},
                                  {"details", details},
                                  {"measurements", nlohmann::json::object()}}},
                                {"counterexample", nullptr},
                                {"correction", nullptr},
                                {"figures", nlohmann::json::array()}};
  const std::string md = affinterp::report::render_markdown(
      {{"seed", 1}, {"size", "quick"}, {"environment", nlohmann::json::object()}, {"claims", {claim}}});
  EXPECT_NE(md.find("**Peer table**\n\n| family | ours | theirs |\n|---|---|---|\n| spread | 1.0e-16 | 2.0e-14; **3 "
                    "NaN/∞** |\n"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("\"worst\": 1e-15"), std::string::npos) << md;
  EXPECT_EQ(md.find("\"tables\""), std::string::npos) << md;
  EXPECT_EQ(md.find("\"peers\""), std::string::npos) << md;  // the table stands for it
}
