// A frame through the CLI against the engine's at 1M triangles: read from a Google Benchmark JSON like
// bench_cli_scale's, judged against issue 19's 1.3 times, and rendered into the report.
#include "experiments/claims/engine_cli.hpp"
#include "reports/generator/report.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace affinterp::claims {
namespace {

namespace fs = std::filesystem;

nlohmann::json median(const std::string& name, double ms) {
  const std::string run_name = name + "/1000000/iterations:1/repeats:3/manual_time";
  return {{"name", run_name + "_median"},
          {"run_name", run_name},
          {"run_type", "aggregate"},
          {"aggregate_name", "median"},
          {"real_time", ms},
          {"time_unit", "ms"},
          {"triangles", 1e6}};
}

TEST(EngineCli, JudgesEachEnergysCliFrameAgainstTheEngines) {
  const fs::path file = fs::temp_directory_path() / "affinterp_engine_cli_test.json";
  std::ofstream(file) << nlohmann::json{
      {"context", {{"affinterp_cpu", "test cpu"}}},
      {"benchmarks",
       {median("cli_frame/F", 120), median("engine_frame/F", 100), median("cli_frame/R", 800),
        median("engine_frame/R",
               600)}}}.dump();
  const nlohmann::json table = engine_cli(file);
  fs::remove(file);
  ASSERT_EQ(table["rows"].size(), 2u);
  EXPECT_EQ(table["triangles"], 1e6);
  EXPECT_EQ(table["machine"], "test cpu");
  EXPECT_EQ(table["rows"][0]["energy"], "F");
  EXPECT_DOUBLE_EQ(table["rows"][0]["ratio"].get<double>(), 1.2);
  EXPECT_EQ(table["rows"][0]["met"], true);
  EXPECT_EQ(table["rows"][1]["met"], false) << "800 / 600 > 1.3";
  EXPECT_EQ(table["met"], false);
  EXPECT_TRUE(engine_cli(file).is_null()) << "not measured";

  const std::string md = report::render_markdown(
      {{"claims", nlohmann::json::array()}, {"environment", nlohmann::json::object()}, {"engine_cli", table}});
  EXPECT_NE(md.find("| E^R | 800.0 | 600.0 | 1.33 | **no** |"), std::string::npos) << md;
}

}  // namespace
}  // namespace affinterp::claims
