// The history of benchmark runs (experiments/bench/history.hpp) and the verdicts across it: the rule across
// machines (experiments/claims/speed_verdict.hpp, across_machines: every machine agreeing gives its verdict, a
// reproduced machine beside a not-reproduced one gives machine-dependent, undecided machines beside agreeing ones
// leave it inconclusive), and the speed claims on history entries of different machines (each a machine of
// one run, decided as across_machines decides machines); on synthetic history entries and benchmark files, merged
// from whole processes and recorded once, with their repetitions.
#include "experiments/bench/history.hpp"
#include "experiments/bench/merge_processes.hpp"
#include "experiments/claims/registry.hpp"
#include "experiments/claims/speed_verdict.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace affinterp::claims::speed_history_test {
namespace {

namespace fs = std::filesystem;
using V = Verdict;

Verdict across(std::vector<Verdict> machines) { return across_machines(machines); }

TEST(AcrossMachines, EveryMachineAgreeingGivesItsVerdict) {
  EXPECT_EQ(across({V::reproduced}), V::reproduced);
  EXPECT_EQ(across({V::reproduced, V::reproduced, V::reproduced}), V::reproduced);
  EXPECT_EQ(across({V::not_reproduced, V::not_reproduced}), V::not_reproduced);
  EXPECT_EQ(across({V::inconclusive, V::inconclusive}), V::inconclusive);
}

TEST(AcrossMachines, ReproducedBesideNotReproducedIsMachineDependent) {
  EXPECT_EQ(across({V::reproduced, V::not_reproduced}), V::machine_dependent);
  EXPECT_EQ(across({V::not_reproduced, V::inconclusive, V::reproduced}), V::machine_dependent);
  EXPECT_EQ(to_string(V::machine_dependent), "machine-dependent");
  EXPECT_EQ(parse_verdict("machine-dependent"), V::machine_dependent);
}

TEST(AcrossMachines, UndecidedMachinesBesideAgreeingOnesLeaveItInconclusive) {
  EXPECT_EQ(across({V::reproduced, V::inconclusive}), V::inconclusive);
  EXPECT_EQ(across({V::inconclusive, V::not_reproduced}), V::inconclusive);
  EXPECT_EQ(across({}), V::inconclusive);
}

/// A fresh folder per test.
fs::path folder() {
  const fs::path dir =
      fs::temp_directory_path() /
      ("affinterp_speed_history_" + std::string(testing::UnitTest::GetInstance()->current_test_info()->name()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

/// A history entry holding one figure, the eigenvalue speed-up, with its interval.
void write_entry(const fs::path& history, const std::string& id, const std::string& date, const std::string& cpu,
                 double ratio, double lo, double hi) {
  fs::create_directories(history);
  std::ofstream(history / (id + ".json")) << nlohmann::json{
      {"date", date},
      {"machine", {{"cpu", cpu}, {"cores", 2}}},
      {"note", "synthetic"},
      {"programs", {{"bench_exp3", {{"processes", 3}, {"dates", {date}}}}}},
      {"figures",
       {{"eig3/eigen-qr ÷ eig3/viete",
         {{"program", "bench_exp3"},
          {"unit", "×"},
          {"value", ratio},
          {"ci95", {lo, hi}},
          {"repetitions", 30},
          {"processes", 3}}}}}}.dump(2);
}

Outcome eig_speedup(const fs::path& bench_dir) {
  RunContext run;
  run.bench_dir = bench_dir;
  return registered_claims().find("thesis.eig.speedup")->check(run.for_claim("thesis.eig.speedup"));
}

TEST(SpeedHistory, RunsThatAgreeDecideTheClaim) {
  const fs::path dir = folder();
  write_entry(dir / "history", "2026-01-01-a", "2026-01-01T00:00:00+00:00", "CPU A", 4.4, 4.3, 4.5);
  write_entry(dir / "history", "2026-01-02-b", "2026-01-02T00:00:00+00:00", "CPU B", 3.0, 2.8, 3.3);
  const Outcome outcome = eig_speedup(dir);  // band [2.13, 4.80]: both inside
  EXPECT_EQ(outcome.verdict, V::reproduced) << outcome.summary;
  EXPECT_EQ(outcome.evidence.measurements["runs"].size(), 2u);
  EXPECT_EQ(outcome.evidence.measurements["latest_run"], "2026-01-02-b");
  EXPECT_NE(outcome.summary.find(
                "CPU A, CPU flags not recorded, compiler not recorded, build flags not recorded, 1 run: reproduced"),
            std::string::npos)
      << outcome.summary;
  EXPECT_EQ(outcome.evidence.measurements["machines"].size(), 2u);
  EXPECT_EQ(outcome.evidence.details["tables"][1]["rows"].size(), 2u);
}

TEST(SpeedHistory, RunsThatDisagreeMakeItMachineDependent) {
  const fs::path dir = folder();
  write_entry(dir / "history", "2026-01-01-a", "2026-01-01T00:00:00+00:00", "CPU A", 4.4, 4.3, 4.5);
  write_entry(dir / "history", "2026-01-02-b", "2026-01-02T00:00:00+00:00", "CPU B", 5.2, 5.0, 5.4);
  const Outcome outcome = eig_speedup(dir);
  EXPECT_EQ(outcome.verdict, V::machine_dependent) << outcome.summary;
  const nlohmann::json& runs = outcome.evidence.measurements["runs"];
  EXPECT_EQ(runs[0]["verdict"], "reproduced");
  EXPECT_EQ(runs[1]["verdict"], "not-reproduced");
  EXPECT_EQ(runs[1]["machine"]["cpu"], "CPU B");
  // A third run across the band's edge does not undo the disagreement.
  write_entry(dir / "history", "2026-01-03-c", "2026-01-03T00:00:00+00:00", "CPU C", 4.8, 4.6, 5.0);
  EXPECT_EQ(eig_speedup(dir).verdict, V::machine_dependent);
}

TEST(SpeedHistory, AnUndecidedRunBesideADecidedOneIsInconclusive) {
  const fs::path dir = folder();
  write_entry(dir / "history", "2026-01-01-a", "2026-01-01T00:00:00+00:00", "CPU A", 5.2, 5.0, 5.4);
  write_entry(dir / "history", "2026-01-02-b", "2026-01-02T00:00:00+00:00", "CPU B", 4.8, 4.6, 5.0);
  EXPECT_EQ(eig_speedup(dir).verdict, V::inconclusive);
}

TEST(SpeedHistory, AMalformedEntryIsInconclusiveNamingItsFile) {
  const fs::path dir = folder();
  fs::create_directories(dir / "history");
  std::ofstream(dir / "history" / "broken.json") << "{\"date\": \"2026\"}";
  const Outcome outcome = eig_speedup(dir);
  EXPECT_EQ(outcome.verdict, V::inconclusive);
  EXPECT_NE(outcome.summary.find("broken.json"), std::string::npos) << outcome.summary;
}

/// One process's Google Benchmark output of bench_exp3 with the two eigenvalue benchmarks, ten repetitions each
/// spread over ±1% around `qr` and `viete` ns, started at `date`.
fs::path write_process(const fs::path& dir, int k, double qr, double viete, const std::string& date) {
  nlohmann::json runs = nlohmann::json::array();
  for (const auto& [name, value] : {std::pair{"eig3/eigen-qr", qr}, std::pair{"eig3/viete", viete}}) {
    const std::string run_name = std::string(name) + "/min_time:0.200/repeats:10";
    for (int i = 0; i < 10; ++i)
      runs.push_back({{"name", run_name},
                      {"run_name", run_name},
                      {"run_type", "iteration"},
                      {"ns_per_matrix", value * (1 + 0.01 * (2.0 * i / 9 - 1))}});
    runs.push_back({{"name", run_name + "_median"},
                    {"run_name", run_name},
                    {"run_type", "aggregate"},
                    {"aggregate_name", "median"},
                    {"ns_per_matrix", value}});
  }
  const fs::path file = dir / ("bench_exp3." + std::to_string(k) + ".json");
  std::ofstream(file) << nlohmann::json{
      {"context",
       {{"date", date}, {"affinterp_cpu", "Test CPU"}, {"affinterp_cpu_flags", "sse2 avx2"}, {"num_cpus", 2}}},
      {"benchmarks", runs}}.dump();
  return file;
}

TEST(SpeedHistory, MergedProcessesAreRecordedOnce) {
  const fs::path dir = folder();
  // Two processes, the second in a slow phase for eigen-qr: ratios 4.0 and 4.6.
  const nlohmann::json merged = bench::merge_processes({write_process(dir, 1, 400, 100, "2026-02-01T10:00:00+00:00"),
                                                        write_process(dir, 2, 460, 100, "2026-02-01T10:05:00+00:00")});
  EXPECT_EQ(merged["context"]["affinterp_processes"], 2);
  EXPECT_EQ(merged["benchmarks"].size(), 40u);  // the aggregates are dropped
  std::ofstream(dir / "bench_exp3.json") << merged.dump();

  const auto run = bench::current_run(dir, "a test");
  ASSERT_TRUE(run.has_value());
  EXPECT_EQ(run->machine["cpu"], "Test CPU");
  EXPECT_EQ(run->machine["cpu_flags"], "sse2 avx2");
  EXPECT_EQ(run->id, "2026-02-01-test-cpu-avx2");
  const bench::Figure& ratio = run->figures.at("eig3/eigen-qr ÷ eig3/viete");
  EXPECT_EQ(ratio.measured.processes, 2u);
  EXPECT_EQ(ratio.measured.repetitions, 20u);
  ASSERT_TRUE(ratio.measured.ci95.has_value());
  EXPECT_LT(ratio.measured.ci95->lo, 4.05);  // the interval spans both processes' ratios
  EXPECT_GT(ratio.measured.ci95->hi, 4.55);

  // Not recorded yet: the files count as a run of their own; recorded: once, and a second record changes nothing.
  EXPECT_FALSE(bench::runs_of(dir).back().recorded);
  const fs::path file = bench::record(*run, dir / "history");
  EXPECT_EQ(file.filename(), "2026-02-01-test-cpu-avx2.json");
  EXPECT_EQ(bench::record(*run, dir / "history"), file);
  const std::vector<bench::RecordedRun> runs = bench::runs_of(dir);
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_TRUE(runs[0].recorded);
  EXPECT_EQ(runs[0].note, "a test");
  EXPECT_EQ(runs[0].figures.at("eig3/eigen-qr ÷ eig3/viete").measured.ci95->lo, ratio.measured.ci95->lo);
  // The entry keeps the repetitions its figures were computed from, by process, for pooling a machine's runs.
  ASSERT_TRUE(runs[0].repetitions.contains("eig3/eigen-qr"));
  EXPECT_EQ(runs[0].repetitions.at("eig3/eigen-qr").size(), 2u);
  EXPECT_EQ(runs[0].repetitions.at("eig3/viete"), run->repetitions.at("eig3/viete"));
}

}  // namespace
}  // namespace affinterp::claims::speed_history_test
