// The 3D engine's record (engine3_speed.hpp) read from a file shaped like bench_3d's output, written to claims.json
// and read back unchanged, and rendered into the report's 3D table with the cost of an as-rigid-as-possible step;
// a file whose benchmarks did not run gives none.
#include "experiments/measurements/engine3_speed.hpp"
#include "reports/generator/report.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace affinterp::measurements::engine3_speed_test {
namespace {

namespace fs = std::filesystem;

/// A repetition of `name` with `ns` per iteration (and the frame parts' counters for 3d/frame-parts).
nlohmann::json repetition(const std::string& name, double ns) {
  nlohmann::json run = {{"name", name},      {"run_name", name},       {"run_type", "iteration"},
                        {"iterations", 10},  {"real_time", ns * 1e-6}, {"cpu_time", ns * 1e-6},
                        {"time_unit", "ms"}, {"ns_per_iteration", ns}, {"triangles", 57640}};
  if (name == "3d/frame-parts") run["local_maps_ms"] = 2.5, run["right_hand_side_ms"] = 1.5, run["solve_ms"] = 5.0;
  return run;
}

fs::path bench_file(bool ran) {
  nlohmann::json doc = {{"context", {{"date", "2026-03-01T10:00:00+00:00"}, {"host_name", "test"}}},
                        {"benchmarks", nlohmann::json::array()}};
  if (ran)
    for (const char* name :
         {"3d/setup", "3d/frame-1-thread", "3d/frame-parts", "3d/blend3", "3d/arap-step", "3d/stand-in"})
      for (double ns : {1e7, 1.2e7, 1.1e7})
        doc["benchmarks"].push_back(repetition(name, std::string(name) == "3d/arap-step" ? 5 * ns : ns));
  const fs::path file = fs::temp_directory_path() / (ran ? "engine3_speed_test.json" : "engine3_speed_empty.json");
  std::ofstream(file) << doc.dump();
  return file;
}

TEST(Engine3Speed, ReadsMediansSpreadAndPartsAndReadsBackAsWritten) {
  const auto speed = engine3_speed(bench_file(true));
  ASSERT_TRUE(speed.has_value());
  // set-up, one thread, blend, an as-rigid-as-possible step, stand-in: the two-thread frame did not run
  ASSERT_EQ(speed->rows.size(), 5u);
  EXPECT_EQ(speed->rows[0].benchmark, "3d/setup");
  EXPECT_DOUBLE_EQ(speed->rows[0].median_ms, 11);
  EXPECT_DOUBLE_EQ(speed->rows[0].range_ms.lo, 10);
  EXPECT_DOUBLE_EQ(speed->rows[0].range_ms.hi, 12);
  ASSERT_TRUE(speed->rows[0].limit_ms && speed->rows[0].verdict);  // set-up ≤ 200 ms: every repetition meets it
  EXPECT_EQ(*speed->rows[0].verdict, Verdict::reproduced);
  EXPECT_FALSE(speed->rows[1].limit_ms.has_value());  // the one-thread frame has no target
  EXPECT_DOUBLE_EQ(speed->triangles, 57640);
  ASSERT_TRUE(speed->parts.has_value());
  EXPECT_DOUBLE_EQ(speed->parts->solve_ms, 5.0);
  const nlohmann::json written = *speed;
  EXPECT_EQ(nlohmann::json(written.get<Engine3Speed>()), written);

  nlohmann::json doc = {{"claims", nlohmann::json::array()}, {"environment", nlohmann::json::object()}};
  doc["engine3_speed"] = written;
  const std::string md = report::render(doc).summary;
  EXPECT_NE(md.find("### 3D engine speed"), std::string::npos) << md;
  EXPECT_NE(md.find("| `3d/setup` |"), std::string::npos) << md;
  EXPECT_NE(md.find("| ≤ 200 ms | yes |"), std::string::npos) << md;
  EXPECT_NE(md.find("solve 5.00 ms"), std::string::npos) << md;
  EXPECT_NE(md.find("E^R and E^S stay in the plane"), std::string::npos) << md;
  EXPECT_NE(md.find("one step costing 55.0 ms against 11.0 ms for a frame (5.0×"), std::string::npos) << md;
}

TEST(Engine3Speed, NoneWithoutTheFileOrItsBenchmarks) {
  EXPECT_FALSE(engine3_speed(fs::temp_directory_path() / "no-such-bench_3d.json").has_value());
  EXPECT_FALSE(engine3_speed(bench_file(false)).has_value());
}

}  // namespace
}  // namespace affinterp::measurements::engine3_speed_test
