// The global engine's scale table: read from a Google Benchmark JSON like bench_scale's, judged against the
// 1M-triangle targets (the largest size at or beyond 1M decides), and drawn as a cost curve.
#include "experiments/claims/engine_scale.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

namespace affinterp::claims {
namespace {

namespace fs = std::filesystem;

nlohmann::json median(const std::string& name, double ms, double peak_MB) {
  return {{"name", name + "/min_time:0.500/repeats:3_median"},
          {"run_name", name + "/min_time:0.500/repeats:3"},
          {"run_type", "aggregate"},
          {"aggregate_name", "median"},
          {"real_time", ms},
          {"cpu_time", ms / 2},
          {"time_unit", "ms"},
          {"peak_MB", peak_MB}};
}

/// A bench file of this test's own (CTest runs the tests of this file in parallel processes).
fs::path write_bench(const nlohmann::json& benchmarks) {
  std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  name.insert(0, "affinterp_engine_scale_").append(".json");
  const fs::path file = fs::temp_directory_path() / name;
  std::ofstream(file)
      << nlohmann::json{{"context", {{"affinterp_cpu", "test cpu"}}}, {"benchmarks", benchmarks}}.dump();
  return file;
}

/// The four benchmarks of one size.
std::vector<nlohmann::json> size(int triangles, double setup_ms, double frame_F_ms, double frame_R_ms, double peak) {
  const auto name = [triangles](const char* benchmark) {
    return std::string(benchmark).append("/").append(std::to_string(triangles));
  };
  return {median(name("scale_setup/F"), setup_ms, peak / 2), median(name("scale_setup/R"), setup_ms * 1.2, peak),
          median(name("scale_frame/F"), frame_F_ms, peak / 2), median(name("scale_frame/R"), frame_R_ms, peak)};
}

TEST(EngineScale, TheLargestSizeBeyondAMillionDecidesTheTargets) {
  nlohmann::json benchmarks = nlohmann::json::array();
  for (const auto& runs : {size(65326, 100, 4, 26, 64), size(1045216, 4000, 90, 550, 1900)})
    for (const auto& run : runs) benchmarks.push_back(run);
  fs::path file = write_bench(benchmarks);
  nlohmann::json table = engine_scale(file, RunSettings{});
  ASSERT_EQ(table["rows"].size(), 2u);
  EXPECT_EQ(table["rows"][0]["triangles"], 65326.0);  // ascending
  EXPECT_EQ(table["rows"][1]["setup_R_ms"], 4800.0);
  EXPECT_EQ(table["rows"][1]["setup_R_cpu_ms"], 2400.0);
  EXPECT_EQ(table["rows"][1]["peak_MB"], 1900.0);  // the largest of the size's benchmarks
  EXPECT_EQ(table["met"], true);
  EXPECT_EQ(table["machine"], "test cpu");
  EXPECT_TRUE(table["figures"].empty()) << "no figure without a figure folder";

  file = write_bench(size(1045216, 4000, 90, 700, 1900));
  EXPECT_EQ(engine_scale(file, RunSettings{})["met"], false) << "E^R above 600 ms a frame";
  file = write_bench(size(1045216, 4000, 90, 550, 2100));
  EXPECT_EQ(engine_scale(file, RunSettings{})["met"], false) << "peak above 2 GB";

  file = write_bench(size(261304, 700, 20, 150, 300));
  EXPECT_TRUE(engine_scale(file, RunSettings{})["met"].is_null()) << "not measured at 1M";
  fs::remove(file);
  EXPECT_TRUE(engine_scale(file, RunSettings{}).is_null());
}

TEST(EngineScale, DrawsTheCostCurve) {
  nlohmann::json benchmarks = nlohmann::json::array();
  for (const auto& runs : {size(65326, 100, 4, 26, 64), size(261304, 700, 20, 150, 300)})
    for (const auto& run : runs) benchmarks.push_back(run);
  const fs::path file = write_bench(benchmarks);
  RunSettings settings;
  settings.figure_dir =
      fs::temp_directory_path() / "affinterp_engine_scale_figures" / fs::path(std::to_string(::getpid()));
  fs::create_directories(settings.figure_dir);
  const nlohmann::json table = engine_scale(file, settings);
  fs::remove(file);
  ASSERT_FALSE(table["figures"].empty());
  EXPECT_EQ(table["figures"][0], "figures/engine-scale.png");
  EXPECT_GT(fs::file_size(settings.figure_dir / "engine-scale.png"), 1000u);
  fs::remove_all(settings.figure_dir);
}

}  // namespace
}  // namespace affinterp::claims
