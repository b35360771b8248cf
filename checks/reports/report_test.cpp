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

TEST(Report, LinksAViewerPageInsteadOfShowingItAsAnImage) {
  nlohmann::json claim = {{"id", "kaji.global.flips"},
                          {"group", "Global"},
                          {"where", "Kaji §4"},
                          {"statement", "s"},
                          {"verdict", "confirmed"},
                          {"summary", ""},
                          {"evidence",
                           {{"method", "m"},
                            {"sample_size", 1},
                            {"seed", nullptr},
                            {"tolerance", nullptr},
                            {"worst_deviation", nullptr},
                            {"details", nlohmann::json::object()},
                            {"measurements", nlohmann::json::object()}}},
                          {"counterexample", nullptr},
                          {"correction", nullptr},
                          {"figures", {"figures/f-1.png", "figures/f-viewer.html"}}};
  const std::string md = affinterp::report::render_markdown({{"seed", 1},
                                                             {"size", "quick"},
                                                             {"generated_at", "now"},
                                                             {"environment", nlohmann::json::object()},
                                                             {"claims", {claim}}});
  EXPECT_NE(md.find("[figure](figures/f-1.png) · [viewer](figures/f-viewer.html)"), std::string::npos);
  EXPECT_NE(md.find("[Interactive viewer](figures/f-viewer.html)"), std::string::npos);
  EXPECT_EQ(md.find("](figures/f-viewer.html)\n\n!["), std::string::npos);
  EXPECT_EQ(md.find("![kaji.global.flips](figures/f-viewer.html)"), std::string::npos);
}

TEST(Report, ScaleTableAndCurveAgainstTheTargets) {
  const nlohmann::json row = {{"triangles", 1045216.0}, {"setup_F_ms", 2500.0}, {"setup_R_ms", 3100.0},
                              {"frame_F_ms", 80.0},     {"frame_R_ms", 900.0},  {"batch_R_ms", 550.0},
                              {"peak_MB", 1500.0}};
  const nlohmann::json factor = {{"triangles", 1045216.0}, {"factor_R_cpu_ms", 1234.5}};
  const nlohmann::json scale = {
      {"machine", "test cpu"},
      {"compiler", "g++"},
      {"blas", "/usr/lib/openblas/libblas.so.3"},
      {"cholmod_from_unknowns", {{"real", 10000}, {"complex", 100000}}},
      {"rows", {row}},
      {"exponents", {{"batch_R_ms", 1.25}}},
      {"back_ends", {{{"name", "cholmod"}, {"rows", {factor}}, {"exponents", {{"factor_R_ms", 1.5}}}}}},
      {"targets",
       {{"triangles", 1e6},
        {"setup_ms", 3000.0},
        {"frame_F_ms", 100.0},
        {"batch_R_ms", 600.0},
        {"growth_R", 5.0},
        {"peak_MB", 2048.0}}},
      {"verdict", "not-reproduced"},
      {"target_verdicts",
       {{{"target", "E^F frame"},
         {"limit", 100.0},
         {"measured", 99.0},
         {"range", {95.0, 104.0}},
         {"verdict", "inconclusive"},
         {"cause", "the solve"}},
        {{"target", "set-up E^R"},
         {"limit", 3000.0},
         {"measured", 3100.0},
         {"range", {3050.0, 3150.0}},
         {"verdict", "not-reproduced"},
         {"cause", "the factorisation"}}}},
      {"figures", {"figures/engine-scale.png", "figures/engine-scale.svg"}}};
  nlohmann::json doc = {{"seed", 1},
                        {"size", "full"},
                        {"generated_at", "now"},
                        {"environment", nlohmann::json::object()},
                        {"claims", nlohmann::json::array()},
                        {"engine_scale", scale}};
  std::string md = affinterp::report::render_markdown(doc);
  EXPECT_NE(md.find("## Global engine at scale"), std::string::npos);
  EXPECT_NE(md.find("| 1045216 | 2500 (—) | 3100 (—) | 80.0 (—) | 900.0 (—) | 550.0 | 1500 |"), std::string::npos)
      << md;
  EXPECT_NE(md.find("| — | — | — | — | 1.25 | — |"), std::string::npos) << "the exponents' row";
  EXPECT_NE(md.find("| cholmod | 1045216 | — | 1234.5 |"), std::string::npos) << "the back-ends' table";
  EXPECT_NE(md.find("below 10000 unknowns (vertices) for E^F's real system"), std::string::npos);
  EXPECT_NE(md.find("below 100000 for the complex systems"), std::string::npos);
  EXPECT_NE(md.find("/usr/lib/openblas/libblas.so.3"), std::string::npos);
  EXPECT_NE(md.find("targets met: **no**"), std::string::npos);
  EXPECT_NE(md.find("| E^F frame | 100.0 | 99.0 | 95.0–104.0 | undecided | the solve |"), std::string::npos) << md;
  EXPECT_NE(md.find("| set-up E^R | 3000.0 | 3100.0 | 3050.0–3150.0 | **no** | the factorisation |"),
            std::string::npos);
  EXPECT_NE(md.find("![cost against mesh size](figures/engine-scale.png)"), std::string::npos);
  doc["engine_scale"] = nullptr;
  md = affinterp::report::render_markdown(doc);
  EXPECT_NE(md.find("`reports/bench/bench_scale.json` is absent"), std::string::npos);
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
