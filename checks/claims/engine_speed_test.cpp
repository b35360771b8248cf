// The global engine's speed table: read from a Google Benchmark JSON like bench_interp's, judged against
// the targets, and rendered into the report.
#include "experiments/claims/engine_speed.hpp"
#include "reports/generator/report.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace affinterp::claims {
namespace {

namespace fs = std::filesystem;

nlohmann::json median(const std::string& name, double ms, double triangles = 0) {
  nlohmann::json run = {{"name", name + "/min_time:1.000/repeats:3_median"},
                        {"run_name", name + "/min_time:1.000/repeats:3"},
                        {"run_type", "aggregate"},
                        {"aggregate_name", "median"},
                        {"real_time", ms},
                        {"time_unit", "ms"}};
  if (triangles > 0) run["triangles"] = triangles;
  return run;
}

fs::path write_bench(const nlohmann::json& benchmarks) {
  const fs::path file = fs::temp_directory_path() / "affinterp_engine_speed_test.json";
  std::ofstream(file)
      << nlohmann::json{{"context", {{"affinterp_cpu", "test cpu"}}}, {"benchmarks", benchmarks}}.dump();
  return file;
}

TEST(EngineSpeed, JudgesEachEnergyAgainstItsTargets) {
  const fs::path file =
      write_bench({median("setup/F/mesh", 120, 1000), median("frame/F/mesh", 5.0), median("frame_refactor/F/mesh", 100),
                   median("setup/R/mesh", 250, 1000), median("frame/R/mesh", 50.0), median("setup/S/mesh", 90, 1000),
                   median("frame/S/mesh", 60.0)});
  const nlohmann::json table = engine_speed(file);
  fs::remove(file);
  ASSERT_EQ(table["rows"].size(), 3u);
  EXPECT_EQ(table["mesh"], "mesh");
  EXPECT_EQ(table["machine"], "test cpu");
  const auto& F = table["rows"][0];
  EXPECT_EQ(F["energy"], "F");
  EXPECT_DOUBLE_EQ(F["frames_per_s"].get<double>(), 200.0);
  EXPECT_DOUBLE_EQ(F["speedup_vs_baseline"].get<double>(), 20.0);
  EXPECT_TRUE(F["met"].get<bool>());
  const auto& R = table["rows"][1];  // 20 frames/s < 25 and set-up 250 ms > 200 ms
  EXPECT_FALSE(R["met"].get<bool>());
  EXPECT_TRUE(R["baseline_ms"].is_null());
  const auto& S = table["rows"][2];  // no frame-rate target; set-up within 0.2 s
  EXPECT_TRUE(S["target_frames_per_s"].is_null());
  EXPECT_TRUE(S["met"].get<bool>());

  const std::string md = report::render_markdown(
      {{"claims", nlohmann::json::array()}, {"environment", nlohmann::json::object()}, {"engine_speed", table}});
  EXPECT_NE(md.find("| F | 120.0 | 5.00 | 200.0 | 150 | 100.0 | 20.0 | yes |"), std::string::npos) << md;
  EXPECT_NE(md.find("| R | 250.0 | 50.00 | 20.0 | 25 | — | — | **no** |"), std::string::npos) << md;
}

TEST(EngineSpeed, AbsentBenchmarkIsSaidInTheReport) {
  EXPECT_TRUE(engine_speed(fs::temp_directory_path() / "affinterp_no_such_bench.json").is_null());
  const std::string md = report::render_markdown(
      {{"claims", nlohmann::json::array()}, {"environment", nlohmann::json::object()}, {"engine_speed", nullptr}});
  EXPECT_NE(md.find("Not measured"), std::string::npos);
}

}  // namespace
}  // namespace affinterp::claims
