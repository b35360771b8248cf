// The global engine's speed table: read from a Google Benchmark JSON like bench_interp's, judged against
// the targets, and rendered into the report.
#include "experiments/measurements/engine_speed.hpp"
#include "checks/claims/bench_json.hpp"
#include "reports/generator/report.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace affinterp::measurements::engine_speed_test {
namespace {

namespace fs = std::filesystem;
using namespace claims;  // the benchmark files of bench_json.hpp

/// The record of `file` as claims.json holds it (null: no file), read back through from_json to the same JSON.
nlohmann::json engine_speed_json(const fs::path& file) {
  const std::optional<EngineSpeed> record = engine_speed(file);
  if (!record) return nullptr;
  const nlohmann::json written = *record;
  EXPECT_EQ(nlohmann::json(written.get<EngineSpeed>()), written) << "read back as written";
  return written;
}

/// REPORT.md of a claims.json document.
std::string summary(const nlohmann::json& doc) { return report::render(doc).summary; }

/// A file of the running test's own: CTest runs these tests as processes side by side.
fs::path write_bench(const nlohmann::json& benchmarks) {
  const fs::path file = fs::temp_directory_path() /
                        ("affinterp_engine_speed_" +
                         std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + ".json");
  std::ofstream(file)
      << nlohmann::json{{"context", {{"affinterp_cpu", "test cpu"}}}, {"benchmarks", benchmarks}}.dump();
  return file;
}

TEST(EngineSpeed, JudgesTheRaisedTargetsOneFrameAtATimeAndBatched) {
  // E^F: 200 frames/s alone, a batch of 8 in 20 ms (400 frames/s); E^R: 50 alone, 8 in 160 ms (50), its frame's
  // 20 ms made of 4 (assembly), 12 (factorisation) and 2.5 (solve) on 2 threads, E^F's 5 ms of 1.5 (right-hand
  // side) and 3 (solve).
  const fs::path file = write_bench(concatenated(
      {repeated("setup/F/mesh", 120, 1000), repeated("frame/F/mesh", 5.0), repeated("batch_frames/F/mesh", 20.0),
       repeated("setup/R/mesh", 150, 1000), repeated("frame/R/mesh", 20.0), repeated("batch_frames/R/mesh", 160.0),
       repeated("frame_assembly/R/mesh", 4.0), repeated("frame_factor/R/mesh", 12.0),
       with_counter(repeated("frame_solve/R/mesh", 2.5), "threads", 2), repeated("frame_rhs/F/mesh", 1.5),
       with_counter(repeated("frame_solve/F/mesh", 3.0), "threads", 2)}));
  const nlohmann::json table = engine_speed_json(file);
  fs::remove(file);
  ASSERT_EQ(table["rows"].size(), 2u);
  const auto& F = table["rows"][0];
  EXPECT_EQ(F["raised_target_frames_per_s"], 300.0);
  EXPECT_DOUBLE_EQ(F["batched_frames_per_s"].get<double>(), 400.0);
  EXPECT_EQ(F["raised_verdict"], "not-reproduced");
  EXPECT_EQ(F["raised_verdict_batched"], "reproduced");
  const auto& R = table["rows"][1];
  EXPECT_EQ(R["raised_target_frames_per_s"], 60.0);
  EXPECT_EQ(R["raised_verdict"], "not-reproduced");
  EXPECT_EQ(R["raised_verdict_batched"], "not-reproduced");
  EXPECT_TRUE(F["frame_parts"]["factor_ms"].is_null());
  EXPECT_DOUBLE_EQ(F["frame_parts"]["rest_ms"].get<double>(), 0.5);
  EXPECT_DOUBLE_EQ(R["frame_parts"]["factor_ms"].get<double>(), 12.0);
  EXPECT_DOUBLE_EQ(R["frame_parts"]["rest_ms"].get<double>(), 1.5);

  const std::string md = summary(
      {{"claims", nlohmann::json::array()}, {"environment", nlohmann::json::object()}, {"engine_speed", table}});
  EXPECT_NE(md.find("| F | 300 | 200.0 ("), std::string::npos) << md;
  EXPECT_NE(md.find(") | **no** | 400.0 ("), std::string::npos) << md;
  EXPECT_NE(md.find("| numeric factorisation 12.0 ms, assembly of H(t) 4.0 ms, solve 2.5 ms on 2 "
                    "threads; the rest 1.5 ms |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| right-hand side 1.5 ms, solve 3.0 ms on 2 threads; the rest 0.5 ms |"), std::string::npos) << md;
}

TEST(EngineSpeed, PartsThatSumPastTheFrameSaySoInsteadOfANegativeRest) {
  // The parts are timed in benchmarks of their own: E^R's 20 ms frame against 4 + 15 + 2.5 ms of parts.
  const fs::path file = write_bench(concatenated(
      {repeated("setup/R/mesh", 150, 1000), repeated("frame/R/mesh", 20.0), repeated("frame_assembly/R/mesh", 4.0),
       repeated("frame_factor/R/mesh", 15.0), with_counter(repeated("frame_solve/R/mesh", 2.5), "threads", 2)}));
  const nlohmann::json table = engine_speed_json(file);
  fs::remove(file);
  EXPECT_DOUBLE_EQ(table["rows"][0]["frame_parts"]["rest_ms"].get<double>(), -1.5);
  const std::string md = summary(
      {{"claims", nlohmann::json::array()}, {"environment", nlohmann::json::object()}, {"engine_speed", table}});
  EXPECT_NE(md.find("solve 2.5 ms on 2 threads; timed apart, the parts sum 1.5 ms past the frame's median |"),
            std::string::npos)
      << md;
}

TEST(EngineSpeed, JudgesEachEnergyAgainstItsTargets) {
  const fs::path file = write_bench(concatenated({repeated("setup/F/mesh", 120, 1000), repeated("frame/F/mesh", 5.0),
                                                  repeated("frame_refactor/F/mesh", 100),
                                                  repeated("setup/R/mesh", 250, 1000), repeated("frame/R/mesh", 50.0),
                                                  repeated("setup/S/mesh", 90, 1000), repeated("frame/S/mesh", 60.0)}));
  const nlohmann::json table = engine_speed_json(file);
  fs::remove(file);
  ASSERT_EQ(table["rows"].size(), 3u);
  EXPECT_EQ(table["mesh"], "mesh");
  EXPECT_EQ(table["machine"], "test cpu");
  const auto& F = table["rows"][0];
  EXPECT_EQ(F["energy"], "F");
  EXPECT_DOUBLE_EQ(F["frames_per_s"].get<double>(), 200.0);
  EXPECT_DOUBLE_EQ(F["speedup_vs_baseline"].get<double>(), 20.0);
  EXPECT_EQ(F["verdict"], "reproduced");
  EXPECT_LT(F["frames_per_s_ci95"][0].get<double>(), 200.0);
  EXPECT_GT(F["frames_per_s_ci95"][1].get<double>(), 200.0);
  EXPECT_EQ(F["repetitions"], 10);
  const auto& R = table["rows"][1];  // 20 frames/s < 25 and set-up 250 ms > 200 ms
  EXPECT_EQ(R["verdict"], "not-reproduced");
  EXPECT_TRUE(R["baseline_ms"].is_null());
  const auto& S = table["rows"][2];  // no frame-rate target; set-up within 0.2 s
  EXPECT_TRUE(S["target_frames_per_s"].is_null());
  EXPECT_EQ(S["verdict"], "reproduced");

  const std::string md = summary(
      {{"claims", nlohmann::json::array()}, {"environment", nlohmann::json::object()}, {"engine_speed", table}});
  EXPECT_NE(md.find("| F | 120.0 | 5.00 | 200.0 ("), std::string::npos) << md;
  EXPECT_NE(md.find(") | 150 | 100.0 | 20.0 | yes |"), std::string::npos) << md;
  EXPECT_NE(md.find(") | 25 | — | — | **no** |"), std::string::npos) << md;
}

TEST(EngineSpeed, AnIntervalAcrossATargetIsUndecided) {
  // 150 frames/s, E^F's target, measured with ±10% spread; and a file with aggregates only.
  const fs::path file =
      write_bench(concatenated({repeated("setup/F/mesh", 120, 1000), repeated("frame/F/mesh", 1000.0 / 150, 0, 0.1)}));
  const nlohmann::json table = engine_speed_json(file);
  fs::remove(file);
  EXPECT_EQ(table["rows"][0]["verdict"], "inconclusive");
  const std::string md = summary(
      {{"claims", nlohmann::json::array()}, {"environment", nlohmann::json::object()}, {"engine_speed", table}});
  EXPECT_NE(md.find("| undecided |"), std::string::npos) << md;

  nlohmann::json aggregates_only = nlohmann::json::array();
  for (const auto& run : concatenated({repeated("setup/F/mesh", 120, 1000), repeated("frame/F/mesh", 5.0)}))
    if (run["run_type"] == "aggregate") aggregates_only.push_back(run);
  const fs::path old_file = write_bench(aggregates_only);
  const nlohmann::json old_table = engine_speed_json(old_file);
  fs::remove(old_file);
  EXPECT_EQ(old_table["rows"][0]["verdict"], "inconclusive");
  EXPECT_TRUE(old_table["rows"][0]["frames_per_s_ci95"].is_null());
}

TEST(EngineSpeed, AbsentBenchmarkIsSaidInTheReport) {
  EXPECT_TRUE(engine_speed_json(fs::temp_directory_path() / "affinterp_no_such_bench.json").is_null());
  const std::string md = summary(
      {{"claims", nlohmann::json::array()}, {"environment", nlohmann::json::object()}, {"engine_speed", nullptr}});
  EXPECT_NE(md.find("Not measured"), std::string::npos);
}

}  // namespace
}  // namespace affinterp::measurements::engine_speed_test
