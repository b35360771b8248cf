// A frame through the CLI against the engine's at 1M triangles: read from a Google Benchmark JSON like
// bench_cli_scale's, judged against the target of 1.3 times on the ratio's bootstrap interval, and rendered into the
// report.
#include "experiments/measurements/engine_cli.hpp"
#include "checks/claims/bench_json.hpp"
#include "reports/generator/report.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace affinterp::measurements::engine_cli_test {
namespace {

namespace fs = std::filesystem;
using namespace claims;  // the benchmark files of bench_json.hpp

/// The record of `file` as claims.json holds it (null: no file), read back through from_json to the same JSON.
nlohmann::json engine_cli_json(const fs::path& file) {
  const std::optional<EngineCli> record = engine_cli(file);
  if (!record) return nullptr;
  const nlohmann::json written = *record;
  EXPECT_EQ(nlohmann::json(written.get<EngineCli>()), written) << "read back as written";
  return written;
}

/// REPORT.md of a claims.json document.
std::string summary(const nlohmann::json& doc) { return report::render(doc).summary; }

nlohmann::json judged(const nlohmann::json& benchmarks) {
  const fs::path file = fs::temp_directory_path() / "affinterp_engine_cli_test.json";
  std::ofstream(file)
      << nlohmann::json{{"context", {{"affinterp_cpu", "test cpu"}}}, {"benchmarks", benchmarks}}.dump();
  const nlohmann::json table = engine_cli_json(file);
  fs::remove(file);
  return table;
}

TEST(EngineCli, JudgesEachEnergysCliFrameAgainstTheEnginesOnTheRatiosInterval) {
  // E^F 1.2 times the engine (1.05 into memory), E^R 1.33 times (both within 1%); E^S 1.3 times with a 20% spread:
  // undecided.
  const nlohmann::json table = judged(concatenated(
      {with_counter(repeated("cli_frame/F/1000000", 120, 1e6), "extra_frames", 32),
       repeated("cli_frame_memory/F/1000000", 105, 1e6), repeated("engine_frame/F/1000000", 100, 1e6),
       repeated("cli_frame/R/1000000", 800, 1e6), repeated("engine_frame/R/1000000", 600, 1e6),
       repeated("cli_frame/S/1000000", 130, 1e6, 0.2), repeated("engine_frame/S/1000000", 100, 1e6, 0.2)}));
  ASSERT_EQ(table["rows"].size(), 3u);
  EXPECT_EQ(table["triangles"], 1e6);
  EXPECT_EQ(table["machine"], "test cpu");
  const auto& F = table["rows"][0];
  EXPECT_EQ(F["energy"], "F");
  EXPECT_DOUBLE_EQ(F["ratio"].get<double>(), 1.2);
  EXPECT_EQ(F["repetitions"], 10);
  ASSERT_TRUE(F["ratio_ci95"].is_array());
  EXPECT_LT(F["ratio_ci95"][1].get<double>(), 1.3);
  EXPECT_EQ(F["verdict"], "reproduced");
  EXPECT_EQ(F["extra_frames"], 32);
  EXPECT_FALSE(table["rows"][1].contains("extra_frames")) << "not recorded for E^R";
  EXPECT_DOUBLE_EQ(F["memory_ratio"].get<double>(), 1.05) << "the same CLI runs writing into memory";
  EXPECT_FALSE(table["rows"][1].contains("memory_ratio")) << "E^R was not run into memory";
  EXPECT_EQ(table["rows"][1]["verdict"], "not-reproduced") << "800 / 600 > 1.3";
  EXPECT_EQ(table["rows"][2]["verdict"], "inconclusive") << "1.3 with a 20% spread straddles the target";
  EXPECT_EQ(table["verdict"], "not-reproduced");

  const std::string md =
      summary({{"claims", nlohmann::json::array()}, {"environment", nlohmann::json::object()}, {"engine_cli", table}});
  EXPECT_NE(md.find("| E^F | 32 | 120.0 | 100.0 | 1.20 ("), std::string::npos) << md;
  EXPECT_NE(md.find("| E^R | — | 800.0 | 600.0 | 1.33 ("), std::string::npos) << md;
  EXPECT_NE(md.find("| 10 | **no** | — | — |"), std::string::npos) << md;
  EXPECT_NE(md.find("| 10 | yes | 105.0 | 1.05 ("), std::string::npos) << md;
  EXPECT_NE(md.find("| 10 | undecided |"), std::string::npos) << md;
}

TEST(EngineCli, IsNotMeasuredWithoutItsFile) {
  EXPECT_TRUE(engine_cli_json(fs::temp_directory_path() / "affinterp_engine_cli_test_absent.json").is_null());
}

}  // namespace
}  // namespace affinterp::measurements::engine_cli_test
