// The engine's speed targets on every recorded run of the history (bench/history.hpp): each run decided alone,
// the runs together by speed_verdict.hpp's across_runs (every run agreeing gives its verdict, a run meeting a
// target beside one missing it gives machine-dependent).
#include "experiments/measurements/engine_speed.hpp"

#include <gtest/gtest.h>

#include <string>

namespace affinterp::measurements::speed_history_test {
namespace {

/// A run on CPU `id` of 2 cores: E^F at `frames_per_s` (±5) after a set-up of 100 ms (±5).
bench::RecordedRun entry(const std::string& id, double frames_per_s) {
  bench::RecordedRun run;
  run.id = id;
  run.date = id;
  run.machine = {{"cpu", id}, {"cores", 2}};
  run.figures["frame/F/mesh"] = {"bench_interp", "frames/s",
                                 bench::Measured{frames_per_s, Interval{frames_per_s - 5, frames_per_s + 5}, 10, 1}};
  run.figures["setup/F/mesh"] = {"bench_interp", "ms", bench::Measured{100, Interval{95, 105}, 10, 1}};
  return run;
}

TEST(SpeedHistory, EngineTargetsAreDecidedRunByRun) {
  const SpeedHistory met = engine_speed_by_run({entry("a", 300), entry("b", 320)});
  EXPECT_EQ(met.across_runs.at("F"), Verdict::reproduced);
  const SpeedHistory split = engine_speed_by_run({entry("a", 300), entry("b", 100)});
  ASSERT_EQ(split.rows.size(), 2u);
  EXPECT_EQ(split.rows[1].verdict, Verdict::not_reproduced);
  EXPECT_EQ(split.rows[1].cores, 2);
  EXPECT_EQ(split.across_runs.at("F"), Verdict::machine_dependent);
  const nlohmann::json written = EngineSpeed{{}, "mesh", 1000.0, {}, split};
  EXPECT_EQ(written["history"]["rows"][1]["verdict"], "not-reproduced");
  EXPECT_EQ(written["history"]["across_runs"]["F"], "machine-dependent");
  EXPECT_EQ(nlohmann::json(written.get<EngineSpeed>()), written) << "read back as written";
}

}  // namespace
}  // namespace affinterp::measurements::speed_history_test
