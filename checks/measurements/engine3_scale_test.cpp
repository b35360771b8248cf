// The 3D engine's million-triangle record (engine3_scale.hpp) read from a file shaped like bench_3d_scale's output:
// each target decided on the spread of its repetitions (met, missed, undecided), written to claims.json and read
// back unchanged, rendered into the report; a file whose benchmarks did not run gives none.
#include "experiments/measurements/engine3_scale.hpp"
#include "reports/generator/report.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace affinterp::measurements::engine3_scale_test {
namespace {

namespace fs = std::filesystem;

/// A repetition as bench_3d_scale writes it: the run name carries the options set in code and UseRealTime's suffix.
nlohmann::json repetition(const std::string& base, double ns, double peak_mb) {
  const std::string name = base + "/iterations:1/repeats:3/real_time";
  return {{"name", name},         {"run_name", name},      {"run_type", "iteration"}, {"iterations", 1},
          {"real_time", ns},      {"cpu_time", ns},        {"time_unit", "ns"},       {"ns_per_iteration", ns},
          {"triangles", 1422848}, {"peak_rss_mb", peak_mb}};
}

fs::path bench_file(bool ran) {
  nlohmann::json doc = {{"context", {{"date", "2026-03-01T10:00:00+00:00"}, {"host_name", "test"}}},
                        {"benchmarks", nlohmann::json::array()}};
  if (ran) {
    for (double s : {4.0, 4.5, 4.8}) doc["benchmarks"].push_back(repetition("3d-scale/setup", s * 1e9, 2000));
    // frames straddle 250 ms; the peak misses 3 GB on every repetition
    for (double ms : {240.0, 245.0, 260.0}) doc["benchmarks"].push_back(repetition("3d-scale/frame", ms * 1e6, 3500));
  }
  const fs::path file = fs::temp_directory_path() / (ran ? "engine3_scale_test.json" : "engine3_scale_empty.json");
  std::ofstream(file) << doc.dump();
  return file;
}

TEST(Engine3Scale, DecidesEachTargetOnTheSpreadAndReadsBackAsWritten) {
  const auto scale = engine3_scale(bench_file(true));
  ASSERT_TRUE(scale.has_value());
  EXPECT_DOUBLE_EQ(scale->triangles, 1422848);
  EXPECT_DOUBLE_EQ(scale->setup_s.median, 4.5);
  EXPECT_DOUBLE_EQ(scale->setup_s.range.hi, 4.8);
  EXPECT_EQ(scale->setup_s.verdict, Verdict::reproduced);
  EXPECT_DOUBLE_EQ(scale->frame_ms.median, 245);
  EXPECT_EQ(scale->frame_ms.verdict, Verdict::inconclusive);
  EXPECT_EQ(scale->peak_MB.verdict, Verdict::not_reproduced);
  const nlohmann::json written = *scale;
  EXPECT_EQ(nlohmann::json(written.get<Engine3Scale>()), written);

  nlohmann::json doc = {{"claims", nlohmann::json::array()}, {"environment", nlohmann::json::object()}};
  doc["engine3_scale"] = written;
  const std::string md = report::render(doc).summary;
  EXPECT_NE(md.find("At a million triangles"), std::string::npos) << md;
  EXPECT_NE(md.find("| set-up (s) | 4.50 | 4.00 – 4.80 | ≤ 5.00 s |"), std::string::npos) << md;
}

TEST(Engine3Scale, NoneWithoutTheFileOrItsBenchmarks) {
  EXPECT_FALSE(engine3_scale(fs::temp_directory_path() / "no-such-bench_3d_scale.json").has_value());
  EXPECT_FALSE(engine3_scale(bench_file(false)).has_value());
}

}  // namespace
}  // namespace affinterp::measurements::engine3_scale_test
