// The engine's speed targets on the recorded runs of the history (bench/history.hpp): each run decided alone for
// the table, each machine's runs pooled (bench/pooled.hpp) and decided on the pooled intervals, and the machines
// together by speed_verdict.hpp's across_machines, the rule the speed claims follow.
#include "experiments/measurements/engine_speed.hpp"

#include <gtest/gtest.h>

#include <string>

namespace affinterp::measurements::speed_history_test {
namespace {

/// A run `id` on CPU `cpu` of 2 cores: E^F at `frames_per_s` (±5) after a set-up of 100 ms (±5), from ten
/// repetitions of one process.
bench::RecordedRun entry(const std::string& id, const std::string& cpu, double frames_per_s) {
  bench::RecordedRun run;
  run.id = id;
  run.date = id;
  run.machine = {{"cpu", cpu}, {"cores", 2}};
  run.figures["frame/F/mesh"] = {"bench_interp", "frames/s",
                                 bench::Measured{frames_per_s, Interval{frames_per_s - 5, frames_per_s + 5}, 10, 1}};
  run.figures["setup/F/mesh"] = {"bench_interp", "ms", bench::Measured{100, Interval{95, 105}, 10, 1}};
  return run;
}

TEST(SpeedHistory, EngineTargetsAreDecidedPerMachine) {
  const SpeedHistory met = engine_speed_history({entry("a", "A", 300), entry("b", "B", 320)});
  ASSERT_EQ(met.machines.size(), 2u);
  EXPECT_EQ(met.across_machines.at("F"), Verdict::reproduced);
  const SpeedHistory split = engine_speed_history({entry("a", "A", 300), entry("b", "B", 100)});
  ASSERT_EQ(split.rows.size(), 2u);
  EXPECT_EQ(split.rows[1].verdict, Verdict::not_reproduced);
  EXPECT_EQ(split.rows[1].cores, 2);
  ASSERT_EQ(split.machines.size(), 2u);
  EXPECT_EQ(split.machines[1].verdict, Verdict::not_reproduced);
  EXPECT_EQ(split.across_machines.at("F"), Verdict::machine_dependent) << "two machines disagree";
  const nlohmann::json written = EngineSpeed{{}, "mesh", 1000.0, {}, split};
  EXPECT_EQ(written["history"]["rows"][1]["verdict"], "not-reproduced");
  EXPECT_EQ(written["history"]["machines"][1]["verdict"], "not-reproduced");
  EXPECT_EQ(written["history"]["across_machines"]["F"], "machine-dependent");
  EXPECT_EQ(nlohmann::json(written.get<EngineSpeed>()), written) << "read back as written";
}

TEST(SpeedHistory, RunsOfOneMachineArePooledNotSetAgainstEachOther) {
  // Runs without their repetitions give a machine of several runs no pooled interval: undecided, never
  // machine-dependent, as one machine cannot depend on itself.
  const SpeedHistory one = engine_speed_history({entry("a", "A", 300), entry("b", "A", 100)});
  ASSERT_EQ(one.machines.size(), 1u);
  EXPECT_EQ(one.machines[0].runs, 2u);
  EXPECT_NE(one.across_machines.at("F"), Verdict::machine_dependent);
}

}  // namespace
}  // namespace affinterp::measurements::speed_history_test
