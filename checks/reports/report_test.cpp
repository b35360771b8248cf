// The report generator renders every claim of a claims.json document: the summary page's table links each claim's
// page, which holds its evidence, tables, counterexample, proof and figures.
#include "reports/generator/report.hpp"

#include "experiments/measurements/engine_scale.hpp"

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
  const affinterp::report::Pages pages = affinterp::report::render(doc);
  const std::string& md = pages.summary;
  const auto table = md.find("| [`kaji.polar.det`](claims/kaji.polar.det.md) |");
  const auto environment = md.find("## Environment");
  ASSERT_NE(table, std::string::npos) << md;
  ASSERT_NE(environment, std::string::npos);
  EXPECT_LT(table, environment);
  EXPECT_NE(md.find("a \\| b"), std::string::npos);  // table cells escape '|'
  EXPECT_NE(md.find("- [`kaji.polar.det`](claims/kaji.polar.det.md) **refuted**: found one"), std::string::npos)
      << "the area's paragraph lists what is not confirmed";
  EXPECT_NE(md.find("test cpu"), std::string::npos);
  ASSERT_EQ(pages.claims.size(), 1u);
  const std::string& page = pages.claims.at("kaji.polar.det");
  EXPECT_EQ(page.find("# `kaji.polar.det`: refuted"), 0u) << page;
  EXPECT_NE(page.find("[Report](../REPORT.md)"), std::string::npos);
  EXPECT_NE(page.find("\"x\": \"1/2\""), std::string::npos);
  EXPECT_NE(page.find("![kaji.polar.det](../figures/p.png)"), std::string::npos) << "paths from the page's folder";
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
  const affinterp::report::Pages pages = affinterp::report::render({{"seed", 1},
                                                                    {"size", "quick"},
                                                                    {"generated_at", "now"},
                                                                    {"environment", nlohmann::json::object()},
                                                                    {"claims", {claim}}});
  EXPECT_NE(pages.summary.find("[figure](figures/f-1.png) · [viewer](figures/f-viewer.html)"), std::string::npos);
  const std::string& md = pages.claims.at("kaji.global.flips");
  EXPECT_NE(md.find("[Interactive viewer](../figures/f-viewer.html)"), std::string::npos);
  EXPECT_EQ(md.find("](../figures/f-viewer.html)\n\n!["), std::string::npos);
  EXPECT_EQ(md.find("![kaji.global.flips](../figures/f-viewer.html)"), std::string::npos);
}

TEST(Report, ScaleTableAndCurveAgainstTheTargets) {
  using namespace affinterp::measurements;
  EngineScale scale;
  scale.run = {"bench_scale.json", "2026-02-01T10:00:00+00:00", "test cpu", "g++", "-O3"};
  scale.blas = "/usr/lib/openblas/libblas.so.3";
  scale.cholmod_from_unknowns = CholmodSwitch{10000, 100000};
  ScaleRow row;
  row.triangles = 1045216.0;
  row.setup_F.value = 2500.0, row.setup_R.value = 3100.0, row.frame_F.value = 80.0, row.frame_R.value = 900.0;
  row.batch_R.value = 550.0, row.peak_MB.value = 1500.0;
  scale.rows = {row};
  scale.exponents.batch_R = 1.25;
  BackEndRow factor;
  factor.triangles = 1045216.0;
  factor.factor_R.cpu_ms = 1234.5;
  BackEndExponents factor_exponents;
  factor_exponents.factor_R = 1.5;
  scale.back_ends = {{"cholmod", {factor}, factor_exponents}};
  scale.targets = {1e6, 3000.0, 100.0, 600.0, 2048.0, 5.0};
  scale.verdict = Verdict::not_reproduced;
  scale.target_verdicts = {
      {"E^F frame", 100.0, 99.0, Interval{95.0, 104.0}, Verdict::inconclusive, "the solve"},
      {"set-up E^R", 3000.0, 3100.0, Interval{3050.0, 3150.0}, Verdict::not_reproduced, "the factorisation"}};
  scale.figures = {"figures/engine-scale.png", "figures/engine-scale.svg"};
  nlohmann::json doc = {{"seed", 1},
                        {"size", "full"},
                        {"generated_at", "now"},
                        {"environment", nlohmann::json::object()},
                        {"claims", nlohmann::json::array()},
                        {"engine_scale", scale}};
  std::string md = affinterp::report::render(doc).summary;
  EXPECT_NE(md.find("## Global engine at scale"), std::string::npos);
  EXPECT_NE(md.find("| 1045216 | 2500 (—) | 3100 (—) | 80.0 (—) | 900.0 (—) | 550.0 | 1500 |"), std::string::npos)
      << md;
  EXPECT_NE(md.find("| — | — | — | — | 1.25 | — |"), std::string::npos) << "the exponents' row";
  EXPECT_NE(md.find("| cholmod | 1045216 | — | 1234.5 |"), std::string::npos) << "the back-ends' table";
  EXPECT_NE(md.find("below 10000 unknowns (vertices) for E^F's real system"), std::string::npos);
  EXPECT_NE(md.find("below 100000 for the complex systems"), std::string::npos);
  EXPECT_NE(md.find("/usr/lib/openblas/libblas.so.3"), std::string::npos);
  EXPECT_NE(md.find("measured on test cpu, 2026-02-01 10:00:00+00:00"), std::string::npos);
  EXPECT_NE(md.find("targets met: **no**"), std::string::npos);
  EXPECT_NE(md.find("| E^F frame | 100.0 | 99.0 | 95.0–104.0 | undecided | the solve |"), std::string::npos) << md;
  EXPECT_NE(md.find("| set-up E^R | 3000.0 | 3100.0 | 3050.0–3150.0 | **no** | the factorisation |"),
            std::string::npos);
  EXPECT_NE(md.find("![cost against mesh size](figures/engine-scale.png)"), std::string::npos);
  doc["engine_scale"] = nullptr;
  md = affinterp::report::render(doc).summary;
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
  const std::string md =
      affinterp::report::render(
          {{"seed", 1}, {"size", "quick"}, {"environment", nlohmann::json::object()}, {"claims", {claim}}})
          .claims.at("thesis.exp.accuracy");
  EXPECT_NE(md.find("**Peer table**\n\n| family | ours | theirs |\n|---|---|---|\n| spread | 1.0e-16 | 2.0e-14; **3 "
                    "NaN/∞** |\n"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("\"worst\": 1e-15"), std::string::npos) << md;
  EXPECT_EQ(md.find("\"tables\""), std::string::npos) << md;
  EXPECT_EQ(md.find("\"peers\""), std::string::npos) << md;  // the table stands for it
}
